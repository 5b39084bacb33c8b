// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "seeds/seed_selector.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "models/plane_sums.h"

namespace floodplane {

namespace {

constexpr int kLargestRho = 48;  // bounds the cost of Eq. 7 for points close to the camera
constexpr float kHalfPi = 1.5707963f;

// The cosine of the test angle widened by what the depth noise `noise_band` (3 sigma_depth)
// subtends over `lever` metres.
float widenedCosine(float angle, float noise_band, float lever) {
  const float widened = angle + std::atan2(noise_band, lever);
  return widened >= kHalfPi ? 0.0f : std::cos(widened);
}

// True when the directions of u and v differ by at most acos(cos_angle); same sense only.
bool sameDirection(const Vec3& u, const Vec3& v, float cos_angle) {
  const float dot = u.dot(v);
  return dot > 0.0f && dot * dot >= cos_angle * cos_angle * u.squaredNorm() * v.squaredNorm();
}

// Eq. 6: the normals of the four quadrants of the cross (spanned by the arms from the centre)
// agree within acos(cos_angle).
bool quadrantsAgree(const Vec3& to_right, const Vec3& to_up, const Vec3& to_left, const Vec3& to_down,
                    float cos_angle) {
  const Vec3 normals[4] = {to_right.cross(to_up), to_up.cross(to_left), to_left.cross(to_down),
                           to_down.cross(to_right)};
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) {
      if (!sameDirection(normals[i], normals[j], cos_angle)) return false;
    }
  }
  return true;
}

// Eq. 7, normalised: every point P_i of each arm (up, down, left, right of `center`, `rho`
// long) lies in the direction of the arm's endpoint. To keep the lever long against noise,
// points in the near half of an arm are seen from the endpoint (E - P_i against E - P) and the
// far half from the centre (P_i - P against E - P); an edge anywhere on the arm bends one of
// the two. Adds the centre and every point of the arms to `cross`.
SeedVerdict testArms(const PointGrid& grid, std::size_t center, int width, int rho, const Vec3& p,
                     const std::array<const Vec3*, 4>& endpoints, float cos_fine, PlaneSums& cross) {
  const std::ptrdiff_t steps[4] = {-static_cast<std::ptrdiff_t>(width), static_cast<std::ptrdiff_t>(width), -1, 1};
  cross.add(p);
  for (int arm = 0; arm < 4; ++arm) {
    const Vec3& end = *endpoints[static_cast<std::size_t>(arm)];
    const Vec3 chord = end - p;
    cross.add(end);
    for (int i = 1; i < rho; ++i) {
      const Vec3 pi =
          Vec3::load(grid.point(static_cast<std::size_t>(static_cast<std::ptrdiff_t>(center) + i * steps[arm])));
      cross.add(pi);
      const Vec3 direction = 2 * i >= rho ? pi - p : end - pi;
      if (!sameDirection(direction, chord, cos_fine)) {
        return std::isfinite(direction.squaredNorm()) ? SeedVerdict::kFineCurvature : SeedVerdict::kHole;
      }
    }
  }
  return SeedVerdict::kAccepted;
}

}  // namespace

void SeedSelector::configure(const Params& params, const Tolerances& tolerances, double scale, float angular_pitch,
                             int width, int height) {
  tolerances_ = tolerances;
  scale_ = scale;
  angle_ = static_cast<float>(params.angular_threshold);
  cos_angle_ = std::cos(angle_);
  angular_pitch_ = angular_pitch;
  width_ = width;
  height_ = height;
  const int fits = (std::min(width, height) - 1) / 2;
  max_rho_ = fits >= 2 ? std::min(kLargestRho, fits) : 0;
}

float SeedSelector::seedSizeAt(float range) const {
  return static_cast<float>(2.0 * tolerances_.seedHalfSide(range, scale_));
}

int SeedSelector::rhoAt(float range) const {
  // Fig. 3: the corners of the cube's far face (range + side/2) project closest to the
  // centre: rho = f (side/2) / (range + side/2), with f = 1 / angular pitch.
  const float half_side = 0.5f * seedSizeAt(range);
  const float rho = half_side / (angular_pitch_ * (range + half_side));
  if (!(rho >= 2.0f)) return std::min(2, max_rho_);
  return std::min(static_cast<int>(std::lround(rho)), max_rho_);
}

SeedVerdict SeedSelector::test(const PointGrid& grid, int x, int y, Seed& seed) const {
  const std::size_t center =
      static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  const Vec3 p = Vec3::load(grid.point(center));
  const float range_sq = p.squaredNorm();
  if (!std::isfinite(range_sq)) return SeedVerdict::kHole;
  if (max_rho_ == 0) return SeedVerdict::kNearBorder;
  const float range = std::sqrt(range_sq);
  const int rho = rhoAt(range);
  if (x < rho || y < rho || x + rho >= width_ || y + rho >= height_) return SeedVerdict::kNearBorder;

  const std::size_t up_index = center - static_cast<std::size_t>(rho) * width_;
  const std::size_t down_index = center + static_cast<std::size_t>(rho) * width_;
  const Vec3 up = Vec3::load(grid.point(up_index));
  const Vec3 down = Vec3::load(grid.point(down_index));
  const Vec3 left = Vec3::load(grid.point(center - rho));
  const Vec3 right = Vec3::load(grid.point(center + rho));

  // Eq. 5: the centroid of the four endpoints stays within sigma_seed of P.
  const Vec3 centroid_offset = (up + down + left + right) * 0.25f - p;
  const float seed_side = seedSizeAt(range);
  if (!(centroid_offset.squaredNorm() <= seed_side * seed_side)) {
    return std::isfinite(centroid_offset.squaredNorm()) ? SeedVerdict::kDistanceDiscontinuity : SeedVerdict::kHole;
  }

  // Eq. 6: the normals of the four quadrants of the cross agree.
  const Vec3 to_right = right - p, to_up = up - p, to_left = left - p, to_down = down - p;
  const float lever_sq = std::min(std::min(to_right.squaredNorm(), to_left.squaredNorm()),
                                  std::min(to_up.squaredNorm(), to_down.squaredNorm()));
  const float lever = std::sqrt(lever_sq);
  const float noise_band = noiseDeviations(tolerances_.noise(), kPointDeviations, range_sq);
  const float cos_coarse = widenedCosine(angle_, noise_band, lever);
  if (!quadrantsAgree(to_right, to_up, to_left, to_down, cos_coarse)) return SeedVerdict::kCoarseCurvature;

  // Eq. 7 over the half lever: every point of each arm lies in the direction of its endpoint.
  const float cos_fine = widenedCosine(angle_, noise_band, 0.5f * lever);
  PlaneSums cross;  // the points of the cross, for n_seed
  const SeedVerdict arms = testArms(grid, center, width_, rho, p, {&up, &down, &left, &right}, cos_fine, cross);
  if (arms != SeedVerdict::kAccepted) return arms;

  // n_seed: the least-squares normal of the cross, facing the sensor at 0 (fit() does).
  const PlaneFit fit = cross.fit();
  if (!fit.valid || !facesSensor(fit.normal, fit.centroid)) return SeedVerdict::kCoarseCurvature;
  const Vec3 normal{static_cast<float>(fit.normal.x()), static_cast<float>(fit.normal.y()),
                    static_cast<float>(fit.normal.z())};

  // Eq. 8: sigma_euclidean, the largest mean spacing between the seed and an endpoint.
  const float longest_sq = std::max(std::max(to_right.squaredNorm(), to_left.squaredNorm()),
                                    std::max(to_up.squaredNorm(), to_down.squaredNorm()));
  seed.index = center;
  seed.point = p;
  seed.normal = normal;
  seed.normal_uncertainty = static_cast<float>(normalUncertainty(fit, cross.count));
  seed.spacing = std::sqrt(longest_sq) / static_cast<float>(rho);
  seed.rho = rho;
  return SeedVerdict::kAccepted;
}

float SeedSelector::estimateAngularPitch(const PointGrid& grid, std::vector<float>& scratch, float fallback) {
  scratch.clear();
  if (grid.width < 1 || grid.height < 1) return fallback;
  // Pairs of horizontal neighbours on a sparse lattice (vertical ones for a single column).
  const bool horizontal = grid.width > 1;
  const int step_y = std::max(1, grid.height / 32);
  const int step_x = std::max(1, grid.width / 64);
  for (int y = 0; y + (horizontal ? 0 : 1) < grid.height; y += step_y) {
    for (int x = 0; x + (horizontal ? 1 : 0) < grid.width; x += step_x) {
      const std::size_t a = static_cast<std::size_t>(y) * grid.width + x;
      const std::size_t b = horizontal ? a + 1 : a + grid.width;
      const Vec3 pa = Vec3::load(grid.point(a));
      const Vec3 pb = Vec3::load(grid.point(b));
      const float na = pa.norm(), nb = pb.norm();
      if (!(na > 0.0f && nb > 0.0f) || !std::isfinite(na) || !std::isfinite(nb)) continue;
      // The chord between the unit rays equals the angle for small angles.
      const float angle = (pa * (1.0f / na) - pb * (1.0f / nb)).norm();
      if (angle > 1e-6f && std::isfinite(angle)) scratch.push_back(angle);
    }
  }
  if (scratch.empty()) return fallback;
  // A pinhole's rays are furthest apart on its axis (1 / f) and closer by cos^2 of the
  // off-axis angle towards the corners, so the median would understate 1 / f by about 10 %
  // for a Kinect. Only pairs within about 0.1 rad of the axis come within 1 % of 1 / f, a
  // few percent of the image, so the estimate is the 98th percentile: close to the axis and
  // still clear of the odd pair whose points noise moved sideways.
  auto rank = scratch.begin() + static_cast<std::ptrdiff_t>(scratch.size() * 49 / 50);
  std::nth_element(scratch.begin(), rank, scratch.end());
  return *rank;
}

}  // namespace floodplane
