// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "seeds/leftover_seeds.h"

#include <cmath>
#include <limits>

#include "models/depth_noise.h"
#include "models/plane_sums.h"

namespace floodplane {

namespace {

// Share of a region's points that must lie within its plane's noise band.
constexpr double kInlierShare = 0.9;
// Neighbouring points of one surface are at most this many pixel footprints apart (a face
// seen at 75 degrees from its normal spreads its points four footprints apart), plus the noise.
constexpr double kNeighbourFootprints = 4.0;
// A region's plane seen at most this far from its normal (cos 75 degrees, as the noise
// estimator's patches).
constexpr double kSmallestIncidenceCosine = 0.25;

}  // namespace

const std::vector<Seed>& LeftoverSeeds::find(const PointGrid& grid, const DistanceBuffer& buffer,
                                             const Tolerances& tolerances, std::size_t min_pixels) {
  seeds_.clear();
  visited_.assign(grid.size(), 0);
  for (std::size_t start = 0; start < grid.size(); ++start) {
    if (visited_[start] || buffer.label(start) != 0 || !grid.isFinite(start)) continue;
    const Region region = gather(grid, buffer, tolerances, start);
    if (members_.size() < min_pixels || region.links == 0) continue;
    Seed seed;
    if (seedOf(grid, tolerances, region, seed)) seeds_.push_back(seed);
  }
  return seeds_;
}

LeftoverSeeds::Region LeftoverSeeds::gather(const PointGrid& grid, const DistanceBuffer& buffer,
                                            const Tolerances& tolerances, std::size_t start) {
  // The region of `start`, depth first, into members_.
  const std::size_t size = grid.size();
  const std::size_t width = static_cast<std::size_t>(grid.width);
  const auto free = [&](std::size_t i) { return buffer.label(i) == 0 && grid.isFinite(i); };
  Region region;
  members_.clear();
  stack_.assign(1, start);
  visited_[start] = 1;
  while (!stack_.empty()) {
    const std::size_t i = stack_.back();
    stack_.pop_back();
    members_.push_back(i);
    const Vec3 p = Vec3::load(grid.point(i));
    region.sums.add(p);
    const double range_sq = p.squaredNorm();
    const double reach = kNeighbourFootprints * tolerances.footprint(std::sqrt(range_sq)) +
                         noiseDeviations(tolerances.noise(), kPointDeviations, range_sq);
    const float reach_sq = static_cast<float>(reach * reach);
    const std::size_t x = i % width;
    const std::size_t neighbours[4] = {x > 0 ? i - 1 : i, x + 1 < width ? i + 1 : i, i >= width ? i - width : i,
                                       i + width < size ? i + width : i};
    for (const std::size_t j : neighbours) {
      if (j == i || visited_[j] || !free(j)) continue;
      const float d_sq = (Vec3::load(grid.point(j)) - p).squaredNorm();
      if (!(d_sq < reach_sq)) continue;
      visited_[j] = 1;
      stack_.push_back(j);
      region.spacing += std::sqrt(static_cast<double>(d_sq));
      ++region.links;
    }
  }
  return region;
}

bool LeftoverSeeds::seedOf(const PointGrid& grid, const Tolerances& tolerances, const Region& region,
                           Seed& seed) const {
  const PlaneFit fit = region.sums.fit();
  if (!fit.valid) return false;
  // Most points within the plane's band: a flat region, not a curved one or clutter.
  const double range = fit.centroid.norm();
  const double incidence = viewIncidence(fit);
  // Not a surface seen edge-on: the band along the outline of every curved surface (a
  // column's, a ball's) fits the plane tangent there as well as a flat face does.
  if (!(incidence >= kSmallestIncidenceCosine)) return false;
  const double band =
      noiseDeviations(tolerances.noise(), kPointDeviations, range * range) * incidence + tolerances.planeFloor(range);
  std::size_t inliers = 0, nearest = members_.front();
  double nearest_sq = std::numeric_limits<double>::infinity();
  for (const std::size_t i : members_) {
    const Vec3 p = Vec3::load(grid.point(i));
    const Eigen::Vector3d q(p.x, p.y, p.z);
    if (std::abs(fit.normal.dot(q) + fit.offset) < band) ++inliers;
    const double d_sq = (q - fit.centroid).squaredNorm();
    if (d_sq < nearest_sq) {
      nearest_sq = d_sq;
      nearest = i;
    }
  }
  if (static_cast<double>(inliers) < kInlierShare * static_cast<double>(members_.size())) return false;
  seed.index = nearest;
  seed.point = Vec3::load(grid.point(nearest));
  seed.normal =
      Vec3{static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()), static_cast<float>(fit.normal.z())};
  seed.normal_uncertainty = static_cast<float>(normalUncertainty(fit, region.sums.count));
  seed.spacing = static_cast<float>(region.spacing / static_cast<double>(region.links));
  seed.rho = 2;
  return true;
}

}  // namespace floodplane
