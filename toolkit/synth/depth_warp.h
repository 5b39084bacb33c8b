// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A depth sensor's calibration warp: what a real scanner's or depth camera's calibration
// leaves behind (a lens or projector model almost, not exactly, right), a depth error that
// varies smoothly over the field of view and is the same in every frame. A flat surface then
// bends by a few millimetres over its width: on real structured-light scans of blocks before a
// wall the wall and the table come out as two or three planes each, parallel within 0.5
// degrees and offset by several millimetres.
//
// The warp is a low-order polynomial in the ray's normalized tangents s = (x, y) / t_corner,
// x = (u - cx) / fx, y = (v - cy) / fy, with t_corner the largest |(x, y)| over the image's
// pixels (so |s| <= 1 whatever the resolution or aspect, and the same camera at another
// resolution gets about the same warp):
//   w(s) = A (b |s|^2 + c (s_x^2 - s_y^2) + e s_x s_y + g s_x + h s_y - m) / p,
// a bowl (|b| uniform in 0.6-1, either sign: the centre reads near or far) with a weaker saddle
// (c, e uniform in +-0.3) and a tilt (g, h uniform in +-0.3). m makes the mean of w over the
// image's pixels 0 (the warp bends the scene, it does not move it), and p makes the peak |w|
// over the pixels exactly A, the amplitude. The coefficients depend on the seed alone: one
// calibration per seed, the same in every frame of a sequence. The renderer adds w to the
// exact depth of the hit before the sensor model measures it, so the point moves along its
// ray and the sensor's own steps (lattice, range code) still apply.
//
// A best-fit plane takes up the tilt and part of the bowl, so a flat wall filling the image
// deviates from its best-fit plane by about 0.6-1 A at the peak: 2-3 mm over the scanner's
// 0.32 m field at 1 m for A = 3 mm.

#include <cstdint>

#include "synth/camera.h"

namespace floodplane::synth {

struct DepthWarpParams {
  double amplitude = 0.0;  ///< A: the peak |w| over the image, metres; 0 turns the warp off
  std::uint64_t seed = 1;  ///< picks the shape (b, c, e, g, h)
};

class DepthWarp {
 public:
  /// The warp over the pixels of `intrinsics`. Throws std::invalid_argument for a negative or
  /// non-finite amplitude.
  DepthWarp(const DepthWarpParams& params, const CameraIntrinsics& intrinsics);

  /// w at pixel (u, v), metres along the ray's depth; 0 everywhere when the amplitude is 0.
  double at(int u, int v) const;

 private:
  // The polynomial before m and p.
  double shape(int u, int v) const;

  CameraIntrinsics intrinsics_;
  double inverse_corner_tangent_ = 1.0;                                           // 1 / t_corner
  double bowl_ = 0.0, saddle_ = 0.0, twist_ = 0.0, tilt_x_ = 0.0, tilt_y_ = 0.0;  // b, c, e, g, h
  double mean_ = 0.0;                                                             // m
  double scale_ = 0.0;                                                            // A / p
};

}  // namespace floodplane::synth
