// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/scanner_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace floodplane::synth {

CameraIntrinsics scannerIntrinsics() { return {512, 512, 1600.0, 1600.0, 255.5, 255.5}; }

double scannerNoiseSigma(double z, const ScannerParams& params) { return params.sigma_at_1m * z * z; }

double scannerDepthStep(double z, const ScannerParams& params) { return params.depth_step_at_1m * z * z; }

double scannerRangeCodeStep(const ScannerParams& params) {
  if (params.range_bits <= 0) {
    return 0.0;
  }
  const double largest_code = std::ldexp(1.0, params.range_bits) - 1.0;
  return (params.range_code_far - params.range_code_near) / largest_code;
}

double quantizeScannerDepth(double z, const ScannerParams& params) {
  if (params.range_bits > 0) {
    const double step = scannerRangeCodeStep(params);
    const double code = std::round((z - params.range_code_near) / step);
    const double largest_code = std::ldexp(1.0, params.range_bits) - 1.0;
    // Beyond the window no code is left to write: the scanner reports nothing.
    return code >= 0.0 && code <= largest_code ? params.range_code_near + code * step
                                               : std::numeric_limits<double>::quiet_NaN();
  }
  if (params.depth_step_at_1m <= 0.0) {
    return z;
  }
  // 1/z in steps of q_1 (per metre squared, so with z in metres the step is q_1 itself).
  const double steps = std::round(1.0 / (z * params.depth_step_at_1m));
  return steps > 0.0 ? 1.0 / (steps * params.depth_step_at_1m) : std::numeric_limits<double>::infinity();
}

double scannerReturnSignal(double albedo, double camera_cosine, double projector_cosine) {
  return albedo * std::min(camera_cosine, projector_cosine);
}

double scannerLossProbability(double return_signal, const ScannerParams& params) {
  const double weak = std::clamp(
      (params.full_return_signal - return_signal) / (params.full_return_signal - params.no_return_signal), 0.0, 1.0);
  return 1.0 - (1.0 - params.dropout_probability) * (1.0 - weak);
}

std::optional<double> measureScannerDepth(double z, double return_signal, const ScannerParams& params,
                                          PixelRandom& random) {
  const double sigma = scannerNoiseSigma(z, params);
  const double step = scannerDepthStep(z, params);
  const double gaussian_variance = std::max(0.0, sigma * sigma - step * step / 12.0);
  const double noisy = z + std::sqrt(gaussian_variance) * random.gaussian();
  const bool lost = random.uniform() < scannerLossProbability(return_signal, params);
  if (lost) {
    return std::nullopt;
  }
  return reportScannerDepth(noisy, params);
}

std::optional<double> reportScannerDepth(double z, const ScannerParams& params) {
  const double reported = quantizeScannerDepth(z, params);
  // NaN (no code) fails both comparisons.
  if (!(reported >= params.min_range && reported <= params.max_range)) {
    return std::nullopt;
  }
  return reported;
}

}  // namespace floodplane::synth
