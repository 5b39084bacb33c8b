// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "frame/noise_estimator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "models/plane_sums.h"
#include "util/vec3.h"

namespace floodplane {

namespace {

constexpr int kPatchSide = 5;
constexpr int kPatchPoints = kPatchSide * kPatchSide;
constexpr double kPatchDegreesOfFreedom = kPatchPoints - 3;  // a plane has three
// About this many patches a frame: enough for a dozen range bins of 80, cheap (a few percent
// of a segmentation).
constexpr double kPatchesPerFrame = 1000.0;
constexpr std::size_t kBins = 12;
constexpr std::size_t kSmallestBin = 16;
// A surface seen at more than about 75 degrees from its normal makes the along-ray residual
// the quotient of two small numbers.
constexpr double kSmallestIncidenceCosine = 0.25;
// Each bin's noise is this quantile of its patches' residuals: low enough to stay clear of
// the patches on edges and curves (often a third of a cluttered frame), high enough to be
// stable with a few dozen patches.
constexpr double kResidualQuantile = 0.25;
// Residuals below this share of the range are float round-off.
constexpr float kRoundOff = 1e-6f;
// A bin is quantized when its depths take at most this share of the distinct depths of its
// patches counted patch by patch (continuous depths: all of them).
constexpr double kLatticeShare = 0.5;

// The kResidualQuantile quantile of sqrt(chi^2_k / k): the factor by which that quantile of
// the residual RMS of Gaussian noise falls short of sigma (Wilson-Hilferty approximation).
double quantileBias(double degrees_of_freedom) {
  constexpr double kNormalQuantile = -0.6744898;  // of 0.25
  const double h = 2.0 / (9.0 * degrees_of_freedom);
  const double cube = 1.0 - h + kNormalQuantile * std::sqrt(h);
  return std::sqrt(cube * cube * cube);
}

double quantile(std::vector<float>& values, double q) {
  const auto rank = values.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), rank, values.end());
  return *rank;
}

struct Bin {
  double range = 0.0;
  double value = 0.0;
};

// A robust fit of value = a + b r^2 with a, b >= 0 (Theil-Sen: b is the median of the
// slopes between pairs of bins, a the median of what b leaves), so that a bin spoilt by
// clutter or a surface the lattice hit only edge-on does not tilt the model. Over a narrow
// range of r^2 the slopes say nothing: everything goes into b, the shape of a triangulating
// sensor.
void fitQuadratic(const std::vector<Bin>& bins, std::vector<float>& scratch, double& a, double& b) {
  a = b = 0.0;
  if (bins.empty()) return;
  const double r_min = bins.front().range, r_max = bins.back().range;
  scratch.clear();
  if (r_max * r_max > 1.25 * r_min * r_min) {
    for (std::size_t i = 0; i < bins.size(); ++i) {
      for (std::size_t j = i + 1; j < bins.size(); ++j) {
        const double dx = bins[j].range * bins[j].range - bins[i].range * bins[i].range;
        if (dx > 0.05 * bins[j].range * bins[j].range)
          scratch.push_back(static_cast<float>((bins[j].value - bins[i].value) / dx));
      }
    }
  }
  if (scratch.size() >= 3) {
    b = std::max(0.0, quantile(scratch, 0.5));
    scratch.clear();
    for (const Bin& bin : bins) scratch.push_back(static_cast<float>(bin.value - b * bin.range * bin.range));
    a = quantile(scratch, 0.5);
    if (a < 0.0) {  // refit with a = 0: the median of value / r^2
      a = 0.0;
      scratch.clear();
      for (const Bin& bin : bins) scratch.push_back(static_cast<float>(bin.value / (bin.range * bin.range)));
      b = quantile(scratch, 0.5);
    }
    return;
  }
  scratch.clear();
  for (const Bin& bin : bins) scratch.push_back(static_cast<float>(bin.value / (bin.range * bin.range)));
  b = quantile(scratch, 0.5);
}

}  // namespace

double NoiseEstimator::latticeStep(std::size_t begin, std::size_t end) {
  // Among the patches whose depths vary at all (a patch of an exactly frontal plane of exact
  // data has one depth), those of a quantized sensor share their depths: the bin's depths
  // take fewer values than its patches take each. Continuous depths differ from patch to
  // patch, even where a patch repeats its own (exact data of a floor parallel to the image
  // rows has one depth per row).
  std::size_t varying = 0, levels = 0, scattered = 0;
  for (std::size_t i = begin; i < end; ++i) {
    // Exact data (surfaces parallel to the image rows have one depth per row there too) fit
    // their planes to round-off; steps leave residuals where a patch spans a level change.
    scattered += patches_[i].sigma > kRoundOff * patches_[i].range ? 1 : 0;
    if (patches_[i].levels < 2) continue;
    ++varying;
    levels += static_cast<std::size_t>(patches_[i].levels);
  }
  if (varying < kSmallestBin / 2 || 4 * scattered < end - begin) return 0.0;
  // The distinct depths of those patches, counted in an open-addressing set of their bit
  // patterns (+0 and -0 as one, as ==); continuous depths, most bins of a smoothed frame, pass
  // the limit early and end the count there.
  const double limit = kLatticeShare * static_cast<double>(levels);
  int bits_of_capacity = 4;
  while ((std::size_t{1} << bits_of_capacity) < 2 * varying * kPatchPoints) ++bits_of_capacity;
  constexpr std::uint32_t kEmpty = 0xffffffffu;  // a NaN: never a depth here
  distinct_.assign(std::size_t{1} << bits_of_capacity, kEmpty);
  const std::uint32_t mask = static_cast<std::uint32_t>(distinct_.size() - 1);
  std::size_t values = 0;
  for (std::size_t i = begin; i < end; ++i) {
    if (patches_[i].levels < 2) continue;
    const float* depths = depths_.data() + patches_[i].first_depth;
    for (int k = 0; k < kPatchPoints; ++k) {
      std::uint32_t bits = 0;
      if (depths[k] != 0.f) std::memcpy(&bits, &depths[k], sizeof bits);
      std::uint32_t slot = (bits * 0x9e3779b1u) >> (32 - bits_of_capacity);
      while (distinct_[slot] != kEmpty && distinct_[slot] != bits) slot = (slot + 1) & mask;
      if (distinct_[slot] == bits) continue;
      distinct_[slot] = bits;
      if (static_cast<double>(++values) > limit) return 0.0;
    }
  }
  scratch_.clear();
  for (std::size_t i = begin; i < end; ++i)
    if (patches_[i].levels >= 2) scratch_.push_back(patches_[i].smallest_gap);
  return quantile(scratch_, 0.5);
}

void NoiseEstimator::measurePatch(const PointGrid& grid, int x0, int y0, int spacing) {
  PlaneSums sums;
  float depths[kPatchPoints];
  int n = 0;
  for (int y = y0; y < y0 + kPatchSide * spacing; y += spacing) {
    for (int x = x0; x < x0 + kPatchSide * spacing; x += spacing) {
      const std::size_t i =
          static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(x);
      const Vec3 p = Vec3::load(grid.point(i));
      if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) return;  // holes: no clean patch
      sums.add(p);
      depths[n++] = p.z;
    }
  }
  const PlaneFit fit = sums.fit();
  if (!fit.valid) return;
  const double range = fit.centroid.norm();
  const double incidence = std::abs(fit.normal.dot(fit.centroid)) / range;
  if (!(incidence >= kSmallestIncidenceCosine)) return;
  Patch patch;
  patch.range = static_cast<float>(range);
  patch.sigma = static_cast<float>(std::sqrt(fit.eigenvalues(0) * kPatchPoints / kPatchDegreesOfFreedom) / incidence);
  // The patch's distinct depths and the smallest gap between them (one step on a lattice).
  std::sort(depths, depths + kPatchPoints);
  patch.first_depth = static_cast<std::uint32_t>(depths_.size());
  depths_.insert(depths_.end(), depths, depths + kPatchPoints);
  const float resolution = 1e-6f * std::abs(depths[kPatchPoints - 1]);  // float round-off, not steps
  patch.levels = 1;
  patch.smallest_gap = 0.f;
  for (int k = 1; k < kPatchPoints; ++k) {
    const float gap = depths[k] - depths[k - 1];
    if (!(gap > resolution)) continue;
    ++patch.levels;
    if (patch.smallest_gap == 0.f || gap < patch.smallest_gap) patch.smallest_gap = gap;
  }
  patches_.push_back(patch);
}

NoiseModel NoiseEstimator::estimate(const PointGrid& grid, int spacing) {
  NoiseModel model;
  model.estimated = true;
  patches_.clear();
  depths_.clear();
  if (grid.width < kPatchSide || grid.height < kPatchSide) return model;
  const double area = static_cast<double>(grid.width) * static_cast<double>(grid.height);
  const int step = std::max(kPatchSide, static_cast<int>(std::sqrt(area / kPatchesPerFrame)));
  const int span = kPatchSide * spacing;
  for (int y = (grid.height % step) / 2; y + span <= grid.height; y += step)
    for (int x = (grid.width % step) / 2; x + span <= grid.width; x += step) measurePatch(grid, x, y, spacing);
  model.patches = patches_.size();
  if (patches_.size() < kMinimumPatches) return model;

  // Range bins of equal counts, nearest first.
  std::sort(patches_.begin(), patches_.end(), [](const Patch& a, const Patch& b) { return a.range < b.range; });
  const std::size_t per_bin = std::max(kSmallestBin, patches_.size() / kBins);
  const std::size_t bins = std::max<std::size_t>(1, patches_.size() / per_bin);
  const double bias = quantileBias(kPatchDegreesOfFreedom);
  std::vector<Bin> noise_bins, step_bins;
  for (std::size_t b = 0; b < bins; ++b) {
    const std::size_t begin = b * patches_.size() / bins, end = (b + 1) * patches_.size() / bins;
    Bin noise;
    noise.range = patches_[(begin + end) / 2].range;
    scratch_.clear();
    for (std::size_t i = begin; i < end; ++i) scratch_.push_back(patches_[i].sigma);
    noise.value = quantile(scratch_, kResidualQuantile) / bias;
    noise_bins.push_back(noise);

    // Quantized when the bin's depths repeat: continuous depths almost never do, depths on a
    // lattice (a scanner's fixed steps, a Kinect's disparity steps) fall on a few values, one
    // step apart. A step also bounds the noise from below: depths on a lattice scatter by at
    // least a uniform step's q / sqrt(12) about the surface, which the residuals miss where all
    // of a patch falls on one level.
    const double depth_step = latticeStep(begin, end);
    if (depth_step > 0.0) {
      step_bins.push_back({noise.range, depth_step});
      noise_bins.back().value = std::max(noise_bins.back().value, depth_step / std::sqrt(12.0));
    }
  }
  fitQuadratic(noise_bins, scratch_, model.sigma_constant, model.sigma_quadratic);
  // Steps only where most of the frame shows them: a few quantized bins are chance.
  if (2 * step_bins.size() >= noise_bins.size())
    fitQuadratic(step_bins, scratch_, model.step_constant, model.step_quadratic);
  return model;
}

}  // namespace floodplane
