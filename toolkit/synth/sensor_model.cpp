// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/sensor_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace floodplane::synth {

const char* sensorModelName(SensorModel model) {
  switch (model) {
    case SensorModel::none:
      return "none";
    case SensorModel::kinect:
      return "kinect";
    case SensorModel::scanner:
      return "scanner";
  }
  return "unknown";
}

std::optional<SensorModel> sensorModelFromName(std::string_view name) {
  if (name == "none") {
    return SensorModel::none;
  }
  if (name == "kinect") {
    return SensorModel::kinect;
  }
  if (name == "scanner") {
    return SensorModel::scanner;
  }
  return std::nullopt;
}

double axialNoiseSigma(double z, const KinectParams& params) {
  const double offset = z - params.sigma_offset;
  return params.sigma_constant + params.sigma_quadratic * offset * offset;
}

double quantizeDepth(double z, const KinectParams& params) {
  if (params.disparity_step <= 0.0) {
    return z;
  }
  const double focal_baseline = params.focal_length * params.baseline;
  const double steps = std::round(focal_baseline / z / params.disparity_step);
  // Zero disparity is infinitely far: no depth to report.
  return steps > 0.0 ? focal_baseline / (steps * params.disparity_step) : std::numeric_limits<double>::infinity();
}

double kinectBendOffset(double z, double tangent_squared, const KinectParams& params) {
  return 0.5 * params.bend_curvature * tangent_squared * z * z * z / params.bend_reference_depth;
}

std::optional<double> measureKinectDepth(double z, const KinectParams& params, PixelRandom& random) {
  // The Gaussian's variance leaves room for the variance quantization adds (see the header).
  const double sigma_z = axialNoiseSigma(z, params);
  const double depth_step = params.disparity_step * z * z / (params.focal_length * params.baseline);
  const double gaussian_variance = std::max(0.0, sigma_z * sigma_z - depth_step * depth_step / 12.0);
  const double noisy = z + std::sqrt(gaussian_variance) * random.gaussian();
  const bool dropped = random.uniform() < params.dropout_probability;
  const double measured = quantizeDepth(noisy, params);
  if (dropped || !(measured >= params.min_range && measured <= params.max_range)) {
    return std::nullopt;
  }
  return measured;
}

}  // namespace floodplane::synth
