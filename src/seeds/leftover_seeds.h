// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "floodplane/point_grid.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"
#include "seeds/seed_selector.h"
#include "util/distance_buffer.h"

namespace floodplane {

/// Beyond the paper: seeds for what the seed lattice leaves. A face narrower than the seed
/// cross (a board's 2 cm edge is 3-13 pixels wide) gets no seed from Eqs. 5-7, even from the
/// finer second pass: the cross's arms reach across its edges. After both passes, every
/// connected region of unclaimed points (4-neighbours whose points are 3-D neighbours) of at
/// least `min_pixels` pixels is fitted with a plane; where most of its points lie within that
/// plane's noise band, the point nearest the region's centroid seeds a flood with that plane.
class LeftoverSeeds {
 public:
  const std::vector<Seed>& find(const PointGrid& grid, const DistanceBuffer& buffer, const Tolerances& tolerances,
                                std::size_t min_pixels);

 private:
  /// A region of unclaimed points (its pixels in members_).
  struct Region {
    PlaneSums sums;
    double spacing = 0.0;  ///< summed distances of the neighbour links
    std::size_t links = 0;
  };
  Region gather(const PointGrid& grid, const DistanceBuffer& buffer, const Tolerances& tolerances, std::size_t start);
  bool seedOf(const PointGrid& grid, const Tolerances& tolerances, const Region& region, Seed& seed) const;

  std::vector<std::uint8_t> visited_;
  std::vector<std::size_t> stack_, members_;
  std::vector<Seed> seeds_;
};

}  // namespace floodplane
