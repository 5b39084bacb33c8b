// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The structured-light scanner model: a close-range triangulation scanner of the kind the
// SegComp structured-light data sets were taken with (objects on a table about 1 m away): a
// camera (scannerIntrinsics()) and a projector 0.3 m to its right (a triangulation angle of 17
// degrees at 1 m) aimed at the point 1 m ahead of the camera. What it measures where a camera
// ray hits a surface, in this order per pixel:
//   1. Projector light. The point returns nothing unless the projector lights it: the point is
//      inside the projector's field (tan 0.135 either side across the baseline, a little less
//      than the camera's 0.16, as a projector rarely covers the whole camera image; tan 0.18 up
//      and down), the surface faces the projector, and the segment from the projector to the
//      point is free (else it lies in the projector's shadow). Geometry, not chance: the
//      renderer casts the ray from the projector (projector_view.h).
//   2. Axial noise. A Gaussian depth error along the camera ray, sigma(z) = sigma_1 (z / 1 m)^2
//      with sigma_1 = 1 mm: triangulation depth error grows with the square of the range (for a
//      fixed disparity error dd, dz = z^2 dd / (f b)).
//   3. Quantization. The sensor reports depths on an inverse-depth lattice, as a disparity
//      quantized in fixed steps gives: 1/z in steps of q_1 / (1 m)^2, so the depth step is
//      q_1 = 1.3 mm at 1 m and q_1 (z / 1 m)^2 elsewhere. As in the Kinect model, the Gaussian
//      of step 2 has variance sigma^2 - q^2 / 12 so that the reported depth has spread sigma
//      (the noise is 0.77 steps wide at every depth, wide enough for the rule to hold: 1.002 mm
//      measured on a wall at 1 m).
//   4. Range limits: no return nearer than 0.3 m or beyond 3 m (reported depth).
//   5. Lost returns. Every lit return is lost with a base chance of 3 % (speckle,
//      interreflections), and with a chance that rises as too little of the pattern comes
//      back: the return signal is s = albedo * c, with c the smaller of the cosines of the
//      angles between the surface normal and the directions to the camera and to the projector
//      (at grazing incidence the stripes smear; dark surfaces send little light back). No extra
//      loss for s >= 0.5 (a white surface within 60 degrees of facing both), certain loss for
//      s <= 0.1 (white beyond 84 degrees; a surface of albedo 0.2 facing the scanner loses
//      75 %), linear in s in between.
// On the generated blocks scenes 20-35 % of the pixels return nothing (27 % on average): the
// field's edges about 13 %, shadows 4 %, weak and dropped returns the rest.
//
// Random draws per pixel (PixelRandom): two uniforms for the Gaussian, then one for the loss,
// in that order, whether or not the pixel is lit.
//
// What a real scanner adds, each off by default (pcd_synth --quantize-bits, --warp, --speckle):
// - Range code (range_bits = N > 0). The scanner writes its range as an N-bit number over a
//   fixed working window [range_code_near, range_code_far], uniform in depth, as the 8-bit
//   range images of the SegComp scanners are: the reported depth is the nearest of the 2^N
//   depths near + k (far - near) / (2^N - 1), k = 0 .. 2^N - 1, in place of the inverse-depth
//   lattice of step 3, and a depth outside the window has no code, so no return. The Gaussian of
//   step 2 stays as it is (the sensor's own noise, before the number is written). The default
//   window, 0.7-1.5 m, holds every depth of the generated blocks scenes (0.79-1.34 m over seeds
//   1-20, each scene spanning at most 0.5 m) with a margin. The real scanner's window is
//   narrower: its 1.3 mm steps are 8 bits over 0.33 m, less than the up to 0.5 m of depth our
//   scenes span, seen from 35-70 degrees above the table. Over 0.7-1.5 m, 8 bits give steps of
//   3.1 mm, 3.4 times the Gaussian's 0.93 mm at 1 m: a plane seen obliquely shows terraces a
//   step apart joined by short noisy risers, as the real scans do (there the staircase shows
//   through the noise, so their noise lies well below their 1.3 mm step, as ours lies below
//   3.1 mm); 10 bits (0.78 mm) already drown the steps in the noise.
// - Calibration warp (RenderSettings::warp, depth_warp.h): the exact depth moved along the ray
//   by a smooth few-millimetre error over the field of view before the steps above.
// - Speckle (speckle = true, scanner_speckle.h): near depth discontinuities and shadow edges,
//   isolated spurious returns and short stripes of lost ones, drawn after every pixel is
//   measured, from generators of their own, so the draws above are unchanged.

#include <optional>

#include "synth/camera.h"
#include "synth/pixel_random.h"

namespace floodplane::synth {

struct ScannerParams {
  double baseline = 0.3;                ///< projector offset along the camera's +x axis, metres
  double convergence_distance = 1.0;    ///< the projector aims at this point of the camera's axis, metres
  double projector_half_width = 0.135;  ///< tangent of half the projector's field across the baseline
  double projector_half_height = 0.18;  ///< tangent of half the projector's field along y
  double sigma_at_1m = 0.001;           ///< sigma_1: depth noise at 1 m, metres
  double depth_step_at_1m = 0.0013;     ///< q_1: quantization step at 1 m, metres; 0 turns it off
  double min_range = 0.3;               ///< metres; nearer returns are lost
  double max_range = 3.0;               ///< metres; farther returns are lost
  double dropout_probability = 0.03;    ///< base chance that any lit return is lost
  double full_return_signal = 0.5;      ///< no extra loss for a return signal at or above this
  double no_return_signal = 0.1;        ///< always lost at or below this
  // Range code (see above).
  int range_bits = 0;            ///< N: the range is reported as an N-bit code (1-16); 0 turns it off
  double range_code_near = 0.7;  ///< depth of code 0, metres
  double range_code_far = 1.5;   ///< depth of code 2^N - 1, metres
  // Speckle and stripes of lost returns along depth discontinuities and shadow edges
  // (scanner_speckle.h).
  bool speckle = false;                        ///< off by default
  double speckle_depth_jump = 0.01;            ///< a discontinuity: a depth step over this times the depth
  int speckle_band = 2;                        ///< pixels (Chebyshev distance) from an edge
  double speckle_stripe_probability = 0.06;    ///< chance that a return in the band starts a lost stripe
  int speckle_stripe_min_length = 2;           ///< pixels down the column, the first one included
  int speckle_stripe_max_length = 6;           ///< pixels
  double speckle_spurious_probability = 0.1;   ///< chance that a band pixel without a return gets one
  double speckle_spurious_error_at_1m = 0.02;  ///< a spurious depth's largest error at 1 m (times z^2), metres
};

/// The scanner's camera: 512 x 512 pixels, fx = fy = 1600 px (a field of view of 18.2
/// degrees: 0.32 m across at 1 m, 0.6 mm a pixel), principal point at the image centre.
CameraIntrinsics scannerIntrinsics();

/// sigma(z) = sigma_1 (z / 1 m)^2, metres: the spread of the reported depth at depth z.
double scannerNoiseSigma(double z, const ScannerParams& params);

/// The depth step of the lattice at depth z, q_1 (z / 1 m)^2 (0 if quantization is off).
double scannerDepthStep(double z, const ScannerParams& params);

/// The depth step of the range code, (far - near) / (2^N - 1) metres; 0 if the code is off.
double scannerRangeCodeStep(const ScannerParams& params);

/// The depth the scanner reports for z: with the range code on, the nearest code depth (NaN
/// outside the code's window: no code, no return); else the lattice depth nearest to z in
/// inverse depth; z itself if both are off.
double quantizeScannerDepth(double z, const ScannerParams& params);

/// What the scanner reports for a (noisy) depth z: quantizeScannerDepth(z), or nothing when
/// that falls outside the range limits (step 4) or has no code.
std::optional<double> reportScannerDepth(double z, const ScannerParams& params);

/// The return signal albedo * c of step 5: c is the smaller of the cosines of the angles between
/// the surface normal and the directions to the camera and to the projector.
double scannerReturnSignal(double albedo, double camera_cosine, double projector_cosine);

/// The chance that a lit return with `return_signal` is lost (step 5).
double scannerLossProbability(double return_signal, const ScannerParams& params);

/// The depth the scanner reports for a lit surface at exact depth `z` (metres) with
/// `return_signal`, or nothing when the return is lost. Draws from `random` as listed above.
std::optional<double> measureScannerDepth(double z, double return_signal, const ScannerParams& params,
                                          PixelRandom& random);

}  // namespace floodplane::synth
