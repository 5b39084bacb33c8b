// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "coarse/facet_chains.h"

#include <algorithm>
#include <cmath>

#include "models/depth_noise.h"
#include "models/flood_criterion.h"

namespace floodplane {

namespace {

// Neighbouring block means of one surface are at most this many block footprints apart (a
// surface seen at 75 degrees from its normal), plus the noise (as LeftoverSeeds links points).
constexpr double kNeighbourFootprints = 4.0;

// The longer side of the rectangle that a uniform spread with these moments covers [m].
double longerSide(const PlaneFit& fit) { return std::sqrt(12.0 * std::max(0.0, fit.eigenvalues[2])); }

}  // namespace

std::uint32_t FacetChains::root(std::uint32_t k) {
  while (parent_[k] != k) k = parent_[k] = parent_[parent_[k]];
  return k;
}

void FacetChains::judge(const PointGrid& means, const std::vector<std::uint32_t>& candidate_of_block,
                        const std::vector<PlaneFit>& fits, const std::vector<const PlaneSums*>& sums,
                        const Tolerances& tolerances, std::vector<bool>& curved) {
  const std::uint32_t count = static_cast<std::uint32_t>(fits.size());
  const auto small = [&](std::uint32_t k) { return longerSide(fits[k - 1]) <= kLargestFacet; };
  // The junctions: 4-neighbouring blocks of two small facets whose means are 3-D neighbours.
  junctions_.clear();
  const std::size_t width = static_cast<std::size_t>(means.width);
  const std::size_t height = static_cast<std::size_t>(means.height);
  const auto link = [&](std::size_t i, std::size_t j) {
    const std::uint32_t k = candidate_of_block[i], l = candidate_of_block[j];
    if (k == 0 || l == 0 || k == l || !small(k) || !small(l)) return;
    const Vec3 p = Vec3::load(means.point(i));
    const double range_sq = p.squaredNorm();
    const double reach = kNeighbourFootprints * tolerances.footprint(std::sqrt(range_sq)) +
                         noiseDeviations(tolerances.noise(), kPointDeviations, range_sq);
    if (!(squaredEuclideanDistance(p, Vec3::load(means.point(j))) < reach * reach)) return;
    junctions_.push_back(static_cast<std::uint64_t>(std::min(k, l)) << 32 | std::max(k, l));
  };
  for (std::size_t y = 0; y < height; ++y)
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      if (x + 1 < width) link(i, i + 1);
      if (y + 1 < height) link(i, i + width);
    }
  std::sort(junctions_.begin(), junctions_.end());
  // Facets whose junction is long enough and shallow (not a crease) join one chain.
  parent_.resize(count + 1);
  for (std::uint32_t k = 0; k <= count; ++k) parent_[k] = k;
  const double shallow = std::cos(kLargestAngle);
  for (std::size_t a = 0; a < junctions_.size();) {
    std::size_t b = a;
    while (b < junctions_.size() && junctions_[b] == junctions_[a]) ++b;
    const std::uint32_t k = static_cast<std::uint32_t>(junctions_[a] >> 32);
    const std::uint32_t l = static_cast<std::uint32_t>(junctions_[a] & 0xffffffffu);
    if (b - a >= kShortestJunction && std::abs(fits[k - 1].normal.dot(fits[l - 1].normal)) >= shallow)
      parent_[root(k)] = root(l);
    a = b;
  }
  // Each chain as one surface: far from its plane, and long enough to be a body, it is curved.
  chain_sums_.assign(count + 1, PlaneSums());
  facets_.assign(count + 1, 0);
  for (std::uint32_t k = 1; k <= count; ++k) {
    chain_sums_[root(k)].merge(*sums[k - 1]);
    ++facets_[root(k)];
  }
  for (std::uint32_t k = 1; k <= count; ++k) {
    const std::uint32_t chain = root(k);
    if (facets_[chain] < kFewestFacets) continue;
    const PlaneFit fit = chain_sums_[chain].fit();
    if (!fit.valid || longerSide(fit) < kShortestChain) continue;
    const double range = fit.centroid.norm();
    const double deviation = depthSigma(tolerances.noise(), range * range) * viewIncidence(fit);
    if (std::sqrt(fit.mean_squared_error) > kDeviations * deviation) curved[k] = true;
  }
}

}  // namespace floodplane
