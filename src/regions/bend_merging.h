// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "flood/plane_merger.h"
#include "floodplane/point_grid.h"
#include "models/facet_pairs.h"
#include "models/planarity_test.h"
#include "models/plane_candidates.h"
#include "util/union_find.h"

namespace floodplane {

/// Beyond the paper: a real plane that the sensor bends is one plane. A depth camera warps a
/// true table towards the image's corners by more than its noise (a real Kinect tilts the
/// table's near corner by 5-12 degrees over a few centimetres): the flood stops where the
/// surface leaves the band of the table's plane, and the corner, flat within its own band,
/// is a plane of its own. Eq. 9 (MergeCriterion) refuses the pair: it compares the two
/// planes' fits over their whole extent, where the corner's tilt is a crease.
///
/// A plane ends at a crease, a step or a gap. Two touching planes (FacetPairs) are held to
/// Eq. 9 where they meet instead: on the bands of each along their shared border, kBandPixels
/// wide (a seed patch's side, the smallest patch the method fits a plane to). A warped
/// surface is flat where its two pieces meet: the bands pass Eq. 9 together and the border
/// between them (every pixel pair across it) shows no step along their normal
/// (MergeCriterion::withoutStep, as for a bend in the flood's merge); at a crease the bands
/// meet at the crease's angle, at a step (a board on a wall) the points across the border
/// lie apart along the normal. Such a pair merges when their union is no curved surface as
/// the planarity test judges it (the facets of a curved thing also meet without a crease:
/// they are curved together instead, PlanarityTest::curvedPair). A long border's bands are
/// walked from about 64 of its pixel pairs, evenly spread.
///
/// The warp can bend a corner tighter than the curved things of a room (a radius under half
/// a metre over a few centimetres): the planarity test then judges the corner curved alone.
/// Such a piece joins a flat plane when the flat one spans more than that radius both ways (a
/// body's, a bin's or a pipe's flat facet is narrower than the thing across its axis) and their
/// union is flat by its curvature (PlanarityTest::unionCurvature): it is the bend of a larger
/// flat surface. Two planes judged curved never join.
class BendMerging {
 public:
  static constexpr int kBandPixels = 12;

  /// Merge groups of the planes 1..planes.size() of the label image `labels` over the points
  /// `grid`: group[k] is a plane number shared by k's group (k itself when k merges with
  /// none). `pairs` are the touching pairs and their borders, `union_bends` per pair whether
  /// their union bends (PlanarityTest::curvedPair), `curved` the planes judged curved
  /// alone (see above), `test` the planarity test's sums of every plane, `criterion` Eq. 9.
  /// Returns whether any merged.
  bool judge(const PointGrid& grid, const CurrentLabels& labels, const FacetPairs& pairs,
             const std::vector<bool>& union_bends, const std::vector<PlaneCandidate>& planes,
             const std::vector<bool>& curved, const PlanarityTest& test, const MergeCriterion& criterion,
             std::vector<std::uint32_t>& group);

 private:
  UnionFind sets_;
};

}  // namespace floodplane
