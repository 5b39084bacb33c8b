// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/params_json.h"

#include <sstream>

namespace floodplane::io {

namespace {

template <class Value>
nlohmann::ordered_json orNull(const std::optional<Value>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}

template <class Value>
std::string orAuto(const std::optional<Value>& value, const char* unit) {
  if (!value) return "auto";
  std::ostringstream text;
  text << *value << unit;
  return text.str();
}

}  // namespace

nlohmann::ordered_json paramsJson(const Params& p) {
  return {{"distance_threshold", orNull(p.distance_threshold)},
          {"seed_size", orNull(p.seed_size)},
          {"angular_threshold", p.angular_threshold},
          {"merge_distance", orNull(p.merge_distance)},
          {"min_inliers", orNull(p.min_inliers)},
          {"subsampling", p.subsampling},
          {"maximum_curvature", p.maximum_curvature},
          {"project_points", p.project_points},
          {"depth_noise_coefficient", orNull(p.depth_noise_coefficient)},
          {"depth_noise_constant", orNull(p.depth_noise_constant)}};
}

nlohmann::ordered_json noiseJson(const NoiseModel& noise) {
  return {{"estimated", noise.estimated},
          {"sigma_constant", noise.sigma_constant},
          {"sigma_quadratic", noise.sigma_quadratic},
          {"step_constant", noise.step_constant},
          {"step_quadratic", noise.step_quadratic},
          {"patches", noise.patches}};
}

std::string describeParams(const Params& p) {
  std::ostringstream text;
  text << "distance threshold " << orAuto(p.distance_threshold, " m") << ", seed size " << orAuto(p.seed_size, " m")
       << ", angular threshold " << p.angular_threshold << " rad, merge distance " << orAuto(p.merge_distance, " m")
       << ", min inliers " << orAuto(p.min_inliers, "") << ", maximum curvature " << p.maximum_curvature
       << ", depth noise "
       << (p.estimatesNoise()
               ? std::string("estimated per frame")
               : "c " + orAuto(p.depth_noise_coefficient, " 1/m") + ", sigma_0 " + orAuto(p.depth_noise_constant, " m"))
       << ", sub-sampling " << p.subsampling;
  return text.str();
}

}  // namespace floodplane::io
