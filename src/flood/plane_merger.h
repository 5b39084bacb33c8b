// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <queue>
#include <utility>
#include <vector>

#include "flood/segment_borders.h"
#include "floodplane/params.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"

namespace floodplane {

/// The merge test of Eq. 9 between two segments, on their least-squares planes.
///
/// Eq. 9 asks for similar seed normals and for either centroid to lie within
/// sigma_plane-merge of the other's plane. We test the segments' least-squares normals and
/// centroids instead of the seeds' (the running sums make them exact and free), require both
/// centroid distances (the paper's "or" lets a small segment's plane wave a big one through),
/// and add one test the paper lacks: each part must fit the merged plane, its RMS distance to
/// it at most Tolerances::mergeFit. Without it, a 2 cm board on a wall, whose
/// centroid is within 3 cm of the wall's plane, would merge into the wall.
class MergeCriterion {
 public:
  MergeCriterion(const Params& params, const Tolerances& tolerances);

  /// Whether segments a and b (sums and fits) may merge; when they may, `cost` is how
  /// tightly they fit one plane (lower merges first).
  bool mergeable(const PlaneSums& a, const PlaneFit& fit_a, const PlaneSums& b, const PlaneFit& fit_b,
                 double& cost) const;

  /// Whether segments a and b, which fail Eq. 9, are one real surface that bends: they meet
  /// at `border` without a step, and their normals agree within half the angular threshold.
  /// The step is the mean difference across the border's pixel pairs along the normal; a
  /// bend puts none there, a board on a wall or a door in its frame its thickness. It must
  /// lie within what the depth noise explains of a mean over the border's pairs (3 standard
  /// errors of a difference, kDifferenceDeviations sigma / sqrt(pairs)) plus sigma_plane's
  /// fixed part. Eq. 9's centroid test and the fit of the union refuse a bend, whose halves'
  /// centroids leave each other's planes and whose union fits one plane loosely; a crease
  /// shows in the normals. `cost` is above every Eq. 9 cost, so tight merges come first.
  bool continuous(const PlaneFit& fit_a, const PlaneFit& fit_b, const SegmentBorder& border, double& cost) const;
  /// continuous()'s test of the step: whether the mean difference across `border` along
  /// `normal` lies within what the noise explains; `step` is it over that tolerance.
  bool withoutStep(const Eigen::Vector3d& normal, const SegmentBorder& border, double& step) const;

 private:
  double angle_;
  Tolerances tolerances_;
};

/// Agglomerative hierarchical clustering of the segment graph (Sec. III-D).
///
/// The paper walks the segments in label order and merges each with the neighbours that pass
/// Eq. 9, so the result depends on the labels' order. We merge best-first instead (as PEAC's
/// AHC): the pair of neighbouring segments that fits one plane most tightly merges first, the
/// merged segment's plane is refit from the summed sums, and its neighbours are re-tested.
class PlaneMerger {
 public:
  /// Starts a graph over segments 1..segment_count-1 (0 is "no segment").
  void reset(std::size_t segment_count);
  /// Records that segments a and b (below the count given to reset()) touch: pixel neighbours
  /// and 3-D neighbours.
  void addEdge(std::int32_t a, std::int32_t b);
  /// Merges; afterwards root(s) gives the surviving segment of each segment.
  /// `sums` holds each segment's sums (index = segment label), and is updated: a root's
  /// sums become those of its whole cluster.
  /// `borders` holds where segments touch (SegmentBorders); merging adds a gone segment's
  /// borders to its survivor's.
  void merge(std::vector<PlaneSums>& sums, const MergeCriterion& criterion, SegmentBorderMap& borders);
  std::int32_t root(std::int32_t segment) const { return parent_[segment]; }
  std::size_t mergeCount() const { return merges_; }
  /// root() of every segment, indexed by segment.
  const std::int32_t* rootData() const { return parent_.data(); }

 private:
  // The survivor `keep` of a merge inherits `gone`'s neighbours and its borders with them,
  // which now point at the survivor.
  void inheritNeighbours(std::int32_t keep, std::int32_t gone, SegmentBorderMap& borders);
  struct Candidate {
    double cost;
    std::int32_t a, b;
    std::uint32_t version_a, version_b;
    bool operator>(const Candidate& o) const {
      if (cost != o.cost) return cost > o.cost;
      return a != o.a ? a > o.a : b > o.b;  // deterministic ties
    }
  };
  void consider(std::int32_t a, std::int32_t b, const std::vector<PlaneSums>& sums, const MergeCriterion& criterion,
                const SegmentBorderMap& borders);
  // Sorts edges_ by (a, b), as std::sort does, and drops repeats.
  void sortEdges();

  std::vector<std::pair<std::int32_t, std::int32_t>> edges_;
  std::vector<std::pair<std::int32_t, std::int32_t>> sorted_edges_;  // sortEdges' scratch
  std::vector<std::size_t> edge_counts_;                             // sortEdges' scratch
  std::vector<std::vector<std::int32_t>> neighbours_;
  std::vector<PlaneFit> fits_;
  std::vector<std::uint32_t> versions_;
  std::vector<std::int32_t> parent_;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
  std::size_t merges_ = 0;
};

}  // namespace floodplane
