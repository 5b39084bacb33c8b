// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/params.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace floodplane {

bool isValidSubsampling(int factor) { return factor == 1 || factor == 2 || factor == 4 || factor == 8; }

namespace {

std::string positive(double value, const char* name, const char* unit) {
  if (std::isfinite(value) && value > 0.0) return {};
  return std::string(name) + " must be a finite number of " + unit + " > 0, got " + std::to_string(value);
}
std::string positive(const std::optional<double>& value, const char* name, const char* unit) {
  return value ? positive(*value, name, unit) : std::string();
}

std::string nonNegative(double value, const char* name) {
  if (std::isfinite(value) && value >= 0.0) return {};
  return std::string(name) + " must be a finite number >= 0, got " + std::to_string(value);
}
std::string nonNegative(const std::optional<double>& value, const char* name) {
  return value ? nonNegative(*value, name) : std::string();
}

}  // namespace

std::string Params::problem() const {
  for (std::string problem :
       {positive(distance_threshold, "distance_threshold", "metres"), positive(seed_size, "seed_size", "metres"),
        positive(angular_threshold, "angular_threshold", "radians"),
        positive(merge_distance, "merge_distance", "metres"), nonNegative(maximum_curvature, "maximum_curvature"),
        nonNegative(depth_noise_coefficient, "depth_noise_coefficient"),
        nonNegative(depth_noise_constant, "depth_noise_constant")}) {
    if (!problem.empty()) return problem;
  }
  if (angular_threshold >= M_PI / 2)
    return "angular_threshold must be < pi/2 radians, got " + std::to_string(angular_threshold);
  if (!isValidSubsampling(subsampling)) return "subsampling must be 1, 2, 4 or 8, got " + std::to_string(subsampling);
  return {};
}

void Params::validate() const {
  const std::string what = problem();
  if (!what.empty()) throw std::invalid_argument("floodplane::Params: " + what);
}

}  // namespace floodplane
