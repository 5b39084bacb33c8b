// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "coarse/facet_chains.h"
#include "flood/flood_pass.h"
#include "floodplane/params.h"
#include "frame/block_grid.h"
#include "frame/hole_filling.h"
#include "models/facet_pairs.h"
#include "models/planarity_test.h"
#include "models/plane_candidates.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"

namespace floodplane {

/// Coarse to fine, what the coarse pass is sure of: the big planes found on the block grid
/// (sub-sampling s > 1) and the blocks inside them, whose pixels the fine pass then takes as
/// they are, without a test of their own; every other pixel the fine pass segments at full
/// resolution with the same tests as s = 1.
///
/// A cluster of blocks (the coarse pass's merged segments) is a coarse plane when
/// - it is a plane as the output would have it (acceptablePlane), and
/// - it is flat as a whole: the planarity test (planarity_test.h) on its block means, at the
///   noise a block mean has. The facets of a curved body (a person, a ball, a pipe) bend
///   together across the blocks of each facet, which one block alone cannot show; and two
///   touching clusters are judged as one surface too (as FacetPairs does for the planes at the
///   end), so that the facets of one curved surface fail together; and so are chains of small
///   facets meeting at shallow angles (FacetChains: a body's facets, each too small to show
///   its bend).
/// A block of a coarse plane is inside it when its eight neighbours are of the same cluster
/// (or have no measured pixel), it straddles no depth step (BlockGrid::split), and its pixels
/// lie within the noise band of its segment's plane on average (their mean squared distance,
/// from the block's scatter): a thin object in front of the plane, a crease or a bend within
/// the block fails that and leaves the block to the fine pass.
class CoarsePlanes {
 public:
  /// Finds the coarse planes among the clusters `merged` of the coarse pass `coarse` over
  /// `block_grid`, the means of `blocks` (its tolerances: the means' noise).
  /// `measured_tolerances` describe the noise of the measured pixels.
  void find(const BlockGrid& blocks, const FloodGrid& block_grid, const FloodPass& coarse, const MergedSegments& merged,
            const Params& params, const Tolerances& measured_tolerances);
  /// Gives the pixels of every inner block to the fine pass `fine` over `pixels` (the frame at
  /// full resolution): a segment per coarse plane, whose sums are those of its inner blocks'
  /// means (as if each of its measured pixels were there: their scatter is then about that of
  /// the fine grid's points) and whose plane is theirs, tested under `fine_tolerances`. The
  /// points `holes` filled in are given too, and added to the sums (the fine pass's segments
  /// hold them until the labels are written, which takes them out again).
  /// Then each coarse plane floods on from the edges of its inner blocks into the pixels
  /// around them (FloodPass::extend): its border pixels are decided by the fine pass's tests
  /// before any seed of the fine pass, as a plane grown from one seed at s = 1 would have taken
  /// them first. Returns the number of pixels given.
  std::size_t claim(const BlockGrid& blocks, const PointGrid& pixels, const HoleFilling& holes,
                    const Tolerances& fine_tolerances, float pixel_pitch, FloodPass& fine, SegmentationStats& stats);

  /// The number of coarse planes.
  std::size_t size() const { return planes_.size(); }

 private:
  struct Plane {
    PlaneSums sums;                  // of its inner blocks' means, each counted once per pixel
    std::vector<std::size_t> inner;  // its inner blocks
    std::int32_t label = 0;          // its segment in the fine pass (claim()), 0: none
  };
  // find()'s view of the coarse pass's clusters, per coarse segment that is a cluster's root.
  struct Clusters {
    std::vector<PlaneSums> sums;          // of its blocks' means, one each
    std::vector<std::uint32_t> blocks;    // its blocks with a measured pixel
    std::vector<std::int32_t> candidate;  // its candidate (numbered from 1), 0: none
    std::vector<std::int32_t> plane;      // its plane + 1, 0: none
  };
  // fillPockets' scratch.
  struct Pockets {
    std::vector<std::size_t> blocks;  // the blocks of one pocket
    std::vector<std::uint8_t> mark;   // per block: 1 in a pocket, 2 inside the plane around this one
  };

  // find()'s steps, in order: the clusters' sums; the candidates among them; the candidates'
  // flatness, alone, in touching pairs and in chains (a curved candidate is no plane); the
  // planes; their inner blocks.
  void sumClusters(const BlockGrid& blocks, const MergedSegments& merged);
  void pickCandidates(const MergedSegments& merged, const Params& params);
  void testFlatness(const BlockGrid& blocks, const MergedSegments& merged, const Tolerances& block_tolerances);
  void testFacetPairs(const FloodGrid& block_grid);
  void testFacetChains(const PointGrid& means, const Tolerances& block_tolerances);
  void numberPlanes();
  void findInnerBlocks(const BlockGrid& blocks, const FloodPass& coarse, const MergedSegments& merged,
                       const Tolerances& measured_tolerances);
  // Whether the surface of `own` (block bx, by's segment) goes on around the block: none of its
  // eight neighbours straddles a depth step, and their means lie within own's band.
  static bool surroundedBySurface(const BlockGrid& blocks, int bx, int by, const FloodCriterion& own);
  // Whether block i's pixels lie within the noise band of the plane (normal, offset) on average.
  static bool insideBand(const BlockGrid& blocks, std::size_t i, const Vec3& normal, float offset,
                         const Tolerances& measured_tolerances);

  // claim()'s steps, in order: the inner blocks' pixels given to the fine pass; the planes that
  // touch noted; the pockets filled; the floods from the inner blocks' edges.
  std::size_t claimInnerBlocks(const BlockGrid& blocks, const PointGrid& pixels, const HoleFilling& holes,
                               const Tolerances& fine_tolerances, float pixel_pitch, FloodPass& fine);
  static std::size_t claimBlock(const BlockGrid& blocks, std::size_t i, const PointGrid& pixels,
                                const HoleFilling& holes, std::int32_t label, FloodPass& fine, PlaneSums& filled);
  void noteTouchingPlanes(const BlockGrid& blocks, FloodPass& fine) const;
  // The pockets: a few blocks that are not inside a plane (a bump, a patch where the sensor's
  // noise is larger, or where a big plane bends away from its fit) with one plane's inside all
  // around them. The plane floods into each with the plane of its inner blocks around it, which
  // follows a bend the whole plane's fit does not; the pocket's closed, so it cannot run off.
  void fillPockets(const BlockGrid& blocks, const PointGrid& pixels, const Tolerances& fine_tolerances,
                   float pixel_pitch, FloodPass& fine, SegmentationStats& stats);
  // Its steps per pocket: the pocket's blocks from `first` on (returns the plane around it + 1;
  // 0 none, -1 more than one or the frame's edge); the means of that plane's inner blocks around
  // the pocket; the plane's pixels next to the pocket, where the flood starts.
  std::int32_t collectPocket(const BlockGrid& blocks, std::size_t first);
  PlaneSums sumAroundPocket(const BlockGrid& blocks, std::int32_t around);
  void addPocketStarts(const BlockGrid& blocks, const PointGrid& pixels, std::int32_t label,
                       const std::vector<std::int32_t>& claimed_by);
  // Each plane floods on from the pixels along its inner blocks' edge (addEdgeStarts: plane k's).
  void floodFromInnerEdges(const BlockGrid& blocks, const PointGrid& pixels, FloodPass& fine, SegmentationStats& stats);
  void addEdgeStarts(const BlockGrid& blocks, const PointGrid& pixels, std::size_t k,
                     const std::vector<std::int32_t>& claimed_by);

  std::vector<Plane> planes_;
  std::vector<std::int32_t> inner_plane_;  // per block: the plane it is inside of + 1, 0 none
  Clusters clusters_;
  // The candidates (clusters large enough, planes as the output has them), numbered from 1:
  // candidate k's fit, root and views for FacetPairs and FacetChains at [k - 1], its verdicts at [k].
  std::vector<PlaneFit> fits_;
  std::vector<std::int32_t> candidate_root_;  // its cluster's root segment
  PlanarityTest planarity_;
  std::vector<bool> curved_, judgeable_;
  // candidate_of_block_: per block, its candidate (0: none), the grid FacetPairs and FacetChains read.
  std::vector<std::uint32_t> candidate_of_block_;
  std::vector<PlaneCandidate> facets_;  // FacetPairs' view of the candidates
  FacetPairs facet_pairs_;
  std::vector<const PlaneSums*> chain_sums_;  // FacetChains' view of the candidates' sums
  FacetChains facet_chains_;
  Pockets pockets_;
  std::vector<std::size_t> starts_;  // the pixels a flood of claim() or fillPockets() starts from
};

}  // namespace floodplane
