// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "floodplane/plane_fit.h"
#include "floodplane/point_grid.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"

namespace floodplane {

/// Beyond the paper, for the coarse pass: the facets of one body judged together. A person, a
/// sofa's cushion or a bag is cut by the flood into facets of a few blocks, each flat within
/// the noise of a block mean, and each passes the planarity test alone (a bend under the noise
/// of a patch that small); two touching ones often pass as a pair too. What gives a body away
/// is how its facets meet: at shallow angles, along borders without a step, chained over the
/// whole body, which as a whole is far from any plane. The faces of rooms and furniture meet at
/// creases instead (a floor and a wall, a box's sides, a stair's tread and riser, at about 90
/// degrees), or are large themselves.
///
/// A chain is a set of small facets (candidates of the coarse pass no longer than
/// kLargestFacet) linked by junctions: at least kShortestJunction pairs of 4-neighbouring
/// blocks whose means are 3-D neighbours, between facets whose normals are at most
/// kLargestAngle apart. A chain of at least kFewestFacets facets that spans at least
/// kShortestChain and whose block means lie about their joint plane by more than
/// kDeviations noise deviations of a block mean is one curved surface: each of its facets is
/// curved. (The faces of small objects, a scanner's blocks of a few centimetres, span less
/// than a body and are left to the facet pairs; see bench/HISTORY.md, "Facet chains".)
class FacetChains {
 public:
  static constexpr double kLargestAngle = 0.7;   // rad, 40 degrees
  static constexpr double kLargestFacet = 0.6;   // m, the longer side of a facet
  static constexpr double kShortestChain = 0.5;  // m, the longer side of the chain
  static constexpr std::uint32_t kShortestJunction = 3;
  static constexpr std::uint32_t kFewestFacets = 3;
  static constexpr double kDeviations = 3.0;

  /// Marks curved[k] for every facet k of a curved chain. Facets are the candidates 1..n
  /// (fits[k - 1], sums[k - 1]: the sums of their block means, one each); `candidate_of_block`
  /// gives each block of `means` its candidate (0: none); `tolerances` are those of a block mean.
  void judge(const PointGrid& means, const std::vector<std::uint32_t>& candidate_of_block,
             const std::vector<PlaneFit>& fits, const std::vector<const PlaneSums*>& sums, const Tolerances& tolerances,
             std::vector<bool>& curved);

 private:
  std::uint32_t root(std::uint32_t k);

  std::vector<std::uint64_t> junctions_;  // per neighbouring block pair of two facets: low << 32 | high
  std::vector<std::uint32_t> parent_;     // union-find over the facets
  std::vector<PlaneSums> chain_sums_;     // per chain root
  std::vector<std::uint32_t> facets_;     // per chain root: its facets
};

}  // namespace floodplane
