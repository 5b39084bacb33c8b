// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>

/// \file
/// floodplane::NoiseModel, the depth noise a segmentation assumed.

namespace floodplane {

/// The sensor noise a segmentation assumed: the depth noise along a viewing ray at range r,
///   sigma(r) = sigma_0 + c r^2,
/// and, where the sensor reports depths on a lattice, the depth step q(r) = q_0 + q_2 r^2
/// (0 where it does not). Measured on the frame (self-calibration) unless Params fixes it.
struct NoiseModel {
  double sigma_constant = 0.0;   ///< sigma_0 [m]
  double sigma_quadratic = 0.0;  ///< c [1/m]
  double step_constant = 0.0;    ///< q_0 [m]
  double step_quadratic = 0.0;   ///< q_2 [1/m]
  std::size_t patches = 0;       ///< flat 5 x 5 patches the estimate rests on
  bool estimated = false;        ///< false: taken from Params

  /// The depth noise's standard deviation sigma(r) [m].
  /// \param range r [m], the distance from the sensor along the viewing ray
  /// \return sigma(r) [m]
  double sigma(double range) const { return sigma_constant + sigma_quadratic * range * range; }
  /// The depth step q(r) [m] of the sensor's depth lattice (0: no lattice).
  /// \param range r [m], the distance from the sensor along the viewing ray
  /// \return q(r) [m]
  double step(double range) const { return step_constant + step_quadratic * range * range; }
};

}  // namespace floodplane
