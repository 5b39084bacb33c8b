// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/plane_merger.h"

#include <algorithm>
#include <cmath>

namespace floodplane {

namespace {

// A border of fewer pixel pairs is a corner where two segments touch, not a shared edge.
constexpr double kMinBorderPairs = 8.0;

double normalVariance(const PlaneSums& sums, const PlaneFit& fit) {
  const double sigma = normalUncertainty(fit, sums.count);
  return sigma * sigma;
}

}  // namespace

MergeCriterion::MergeCriterion(const Params& params, const Tolerances& tolerances)
    : angle_(params.angular_threshold), tolerances_(tolerances) {}

bool MergeCriterion::mergeable(const PlaneSums& a, const PlaneFit& fit_a, const PlaneSums& b, const PlaneFit& fit_b,
                               double& cost) const {
  // The cheap tests on the parts' own planes come first: most neighbouring segments are
  // different planes and fail them, and the merged fit below costs an eigen-decomposition.
  if (fit_a.valid && fit_b.valid) {
    // The depth noise at the parts' combined centroid, from the sums without a fit.
    const Eigen::Vector3d centroid = (a.centroid() * a.count + b.centroid() * b.count) / (a.count + b.count);
    // Eq. 9, first term: the normals agree, up to what their own uncertainty explains.
    const double uncertainty = std::sqrt(normalVariance(a, fit_a) + normalVariance(b, fit_b));
    const double allowed = std::min(angle_ + 3.0 * uncertainty, 1.5);
    // Written as !(>=) so that a NaN anywhere rejects the merge rather than skipping the test.
    if (!(fit_a.normal.dot(fit_b.normal) >= std::cos(allowed))) return false;
    // Eq. 9, second term, both ways.
    const double tolerance = tolerances_.mergeDistance(centroid.norm());
    const Eigen::Vector3d between = fit_a.centroid - fit_b.centroid;
    if (std::abs(between.dot(fit_a.normal)) >= tolerance) return false;
    if (std::abs(between.dot(fit_b.normal)) >= tolerance) return false;
  }

  PlaneSums both = a;
  both.merge(b);
  const PlaneFit merged = both.fit();
  if (!merged.valid) return false;
  // Each part fits the merged plane.
  const double fit_tolerance = tolerances_.mergeFit(merged.centroid.norm());
  const double worst = std::max(a.meanSquaredDistance(merged.normal, merged.offset),
                                b.meanSquaredDistance(merged.normal, merged.offset));
  if (!(worst <= fit_tolerance * fit_tolerance)) return false;
  cost = worst / (fit_tolerance * fit_tolerance);
  return true;
}

bool MergeCriterion::continuous(const PlaneFit& fit_a, const PlaneFit& fit_b, const SegmentBorder& border,
                                double& cost) const {
  if (!fit_a.valid || !fit_b.valid) return false;
  if (!(fit_a.normal.dot(fit_b.normal) >= std::cos(0.5 * angle_))) return false;
  double step = 0.0;
  if (!withoutStep((fit_a.normal + fit_b.normal).normalized(), border, step)) return false;
  cost = 1.0 + step;
  return true;
}

bool MergeCriterion::withoutStep(const Eigen::Vector3d& normal, const SegmentBorder& border, double& step) const {
  if (border.count < kMinBorderPairs) return false;
  const double range = border.meanPoint().norm();
  const double tolerance =
      noiseDeviations(tolerances_.noise(), kDifferenceDeviations, range * range) / std::sqrt(border.count) +
      tolerances_.planeFloor(range);
  step = std::abs(normal.dot(border.meanStep())) / tolerance;
  return step < 1.0;
}

void PlaneMerger::reset(std::size_t segment_count) {
  edges_.clear();
  neighbours_.resize(segment_count);
  for (auto& list : neighbours_) list.clear();
  parent_.resize(segment_count);
  for (std::size_t i = 0; i < segment_count; ++i) parent_[i] = static_cast<std::int32_t>(i);
  merges_ = 0;
}

void PlaneMerger::addEdge(std::int32_t a, std::int32_t b) {
  if (a == b || a <= 0 || b <= 0) return;
  edges_.emplace_back(std::min(a, b), std::max(a, b));
}

void PlaneMerger::consider(std::int32_t a, std::int32_t b, const std::vector<PlaneSums>& sums,
                           const MergeCriterion& criterion, const SegmentBorderMap& borders) {
  double cost = 0.0;
  bool merges = criterion.mergeable(sums[a], fits_[a], sums[b], fits_[b], cost);
  if (!merges) {
    const auto border = borders.find(borderKey(a, b));
    merges = border != borders.end() && criterion.continuous(fits_[a], fits_[b], border->second, cost);
  }
  if (merges) queue_.push({cost, std::min(a, b), std::max(a, b), versions_[std::min(a, b)], versions_[std::max(a, b)]});
}

void PlaneMerger::sortEdges() {
  // Two stable counting passes, by b and then by a (a radix sort with a segment number as
  // its digit): a frame has tens of thousands of edges, most of them repeats, between a few
  // hundred segments, and this is linear in both. Segment numbers are below the count given
  // to reset(), as merge() needs them to be.
  const std::size_t n = parent_.size();
  const auto pass = [&](const auto& from, auto& to, auto digit) {
    edge_counts_.assign(n + 1, 0);
    for (const auto& edge : from) ++edge_counts_[static_cast<std::size_t>(digit(edge)) + 1];
    for (std::size_t d = 1; d <= n; ++d) edge_counts_[d] += edge_counts_[d - 1];
    to.resize(from.size());
    for (const auto& edge : from) to[edge_counts_[static_cast<std::size_t>(digit(edge))]++] = edge;
  };
  pass(edges_, sorted_edges_, [](const auto& edge) { return edge.second; });
  pass(sorted_edges_, edges_, [](const auto& edge) { return edge.first; });
  edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
}

void PlaneMerger::inheritNeighbours(std::int32_t keep, std::int32_t gone, SegmentBorderMap& borders) {
  // The survivor inherits the other's neighbours and its borders with them; they now point
  // at the survivor.
  borders.erase(borderKey(keep, gone));
  std::vector<std::int32_t>& kept = neighbours_[keep];
  for (const std::int32_t other : neighbours_[gone]) {
    if (other == keep) continue;
    kept.push_back(other);
    if (const auto inherited = borders.find(borderKey(gone, other)); inherited != borders.end()) {
      const SegmentBorder moved = inherited->second;  // copied: the insertion below may rehash
      borders.erase(inherited);
      // gone's side of the moved border is keep's side of this one.
      borders[borderKey(keep, other)].merge(moved, (gone < other) != (keep < other));
    }
    std::vector<std::int32_t>& theirs = neighbours_[other];
    std::replace(theirs.begin(), theirs.end(), gone, keep);
    std::sort(theirs.begin(), theirs.end());
    theirs.erase(std::unique(theirs.begin(), theirs.end()), theirs.end());
  }
  neighbours_[gone].clear();
  kept.erase(std::remove(kept.begin(), kept.end(), gone), kept.end());
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
}

void PlaneMerger::merge(std::vector<PlaneSums>& sums, const MergeCriterion& criterion, SegmentBorderMap& borders) {
  const std::size_t n = parent_.size();
  fits_.resize(n);
  for (std::size_t i = 1; i < n; ++i) fits_[i] = sums[i].fit();
  versions_.assign(n, 0);
  queue_ = {};

  sortEdges();
  for (const auto& [a, b] : edges_) {
    neighbours_[a].push_back(b);
    neighbours_[b].push_back(a);
    consider(a, b, sums, criterion, borders);
  }

  while (!queue_.empty()) {
    const Candidate best = queue_.top();
    queue_.pop();
    if (parent_[best.a] != best.a || parent_[best.b] != best.b) continue;
    if (versions_[best.a] != best.version_a || versions_[best.b] != best.version_b) continue;

    // The larger segment survives (the smaller label on a tie), so labels stay stable.
    std::int32_t keep = best.a, gone = best.b;
    if (sums[gone].count > sums[keep].count) std::swap(keep, gone);
    sums[keep].merge(sums[gone]);
    fits_[keep] = sums[keep].fit();
    ++versions_[keep];
    parent_[gone] = keep;
    ++merges_;

    inheritNeighbours(keep, gone, borders);
    for (const std::int32_t other : neighbours_[keep]) consider(keep, other, sums, criterion, borders);
  }

  // Point every segment at its final root.
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t r = static_cast<std::int32_t>(i);
    while (parent_[r] != r) r = parent_[r];
    parent_[i] = r;
  }
}

}  // namespace floodplane
