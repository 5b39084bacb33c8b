// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Sensor models: what a depth camera measures where a ray hits a surface.
//
// `none`: the exact point.
// `scanner`: a close-range structured-light scanner with projector shadows (scanner_model.h).
// `kinect`: a structured-light sensor (Kinect v1 / Asus Xtion), in this order per pixel:
//   1. Axial noise. A Gaussian depth error along the ray: the whole point is scaled so its z
//      changes by the sampled amount. The target spread is the axial model of Nguyen, Izadi
//      and Lovell (2012), sigma_z(z) = 0.0012 + 0.0019 (z - 0.4)^2 m.
//   2. Disparity quantization. The sensor measures disparity = f b / z in steps of 1/8 px
//      (baseline b = 0.075 m, f = 525 px); the depth is rounded to the nearest step:
//      z = f b / (round(8 f b / z) / 8). f is the sensor's own focal length, not the rendered
//      image's, so rendering at another resolution keeps the sensor's depth steps.
//   3. Range limits. No return closer than 0.45 m or beyond 8 m (measured depth).
//   4. Dropouts. A fraction (0.5 %) of the remaining returns is lost at random.
//
// Why the Gaussian of step 1 is narrower than sigma_z: Nguyen et al. measured sigma_z on real
// Kinect depth, which is already quantized, so sigma_z includes the rounding error of step 2.
// Rounding to steps of depth size q = z^2 / (8 f b) adds a variance of about q^2 / 12, so
// step 1 draws from a Gaussian with variance sigma_z^2 - q^2 / 12 and the measured depth ends
// up with the spread sigma_z (q is 3.2 mm at 1 m and 29 mm at 3 m against sigma_z of 1.9 and
// 14 mm; without this the measured spread would be 11 % and 14 % too large). The q^2 / 12 rule
// is exact only for noise wider than the steps; here the noise is 0.4 to 0.5 steps wide, so
// the measured spread still depends on where z falls between two steps and lies within about
// 9 % of sigma_z at any depth (simulated from 0.6 m to 7 m).
//
// Random draws per pixel (PixelRandom): two uniforms for the Gaussian, then one for the
// dropout, in that order.
//
// What a real Kinect adds, each off by default (pcd_synth --bend, --warp), applied to the exact
// depth before step 1, so the reported depth stays on the disparity lattice:
// - Bend (bend_curvature = kappa). A Kinect's depth error grows towards the image's corners and
//   with depth: a few centimetres at the corners at 3-4 m. It comes from a disparity error that
//   varies smoothly over the image (the IR camera's and the projector's residual distortion),
//   growing as the disparity falls (Herrera, Kannala and Heikkila 2012 model it as
//   D(u, v) exp(a0 - a1 d)); a disparity error dd moves the depth by z^2 dd / (f b). Here the
//   disparity error is radial, growing as rho^2 and in proportion to depth, so the depth moves
//   along the ray by
//     e(z, rho) = (kappa / 2) rho^2 z^3 / z_ref,   z_ref = bend_reference_depth = 3.5 m,
//   rho^2 = x^2 + y^2 with x = (u - cx) / fx, y = (v - cy) / fy the ray's tangents. A flat wall
//   facing the camera at depth Z (lateral coordinates X = x Z, Y = y Z) becomes
//   Z + (kappa / 2)(Z / z_ref)(X^2 + Y^2): a bowl of curvature kappa Z / z_ref per metre,
//   kappa itself at 3.5 m, the centre read true, the corners read far for kappa > 0 (near
//   for kappa < 0). Units: kappa in 1/m; e in metres.
//   Magnitudes: a whole wall cannot bend by the 1-1.7 /m the issue quotes. kappa = 1 /m moves
//   the corners of a wall at 3.5 m (rho^2 = 0.58 at 640 x 480, f = 525) by 3.6 m. Quadric fits
//   to office1.pcd's large walls give 0.017 /m (at 3.5 m, 2.9 m across) and 0.08 /m (at 5.3 m,
//   3.4 m across); the 1.0 /m was a strip 0.5 m across. kappa = 0.02 /m (the quirks renders of
//   data/CMakeLists.txt) moves the corners at 3.5 m by 7 cm and bends a wall at 5.3 m by
//   0.03 /m.
// - Calibration warp (RenderSettings::warp, depth_warp.h): a smooth few-millimetre depth error
//   over the field of view, added to e.

#include <cstdint>
#include <optional>
#include <string_view>

#include "synth/pixel_random.h"

namespace floodplane::synth {

enum class SensorModel { none, kinect, scanner };

/// "none", "kinect" or "scanner", as used in file names and on the command line.
const char* sensorModelName(SensorModel model);

/// The model called `name` ("none", "kinect", "scanner"), or nothing.
std::optional<SensorModel> sensorModelFromName(std::string_view name);

struct KinectParams {
  // Axial noise, sigma_z(z) = sigma_constant + sigma_quadratic * (z - sigma_offset)^2
  // (Nguyen, Izadi and Lovell 2012, Eq. 2 with their fitted constants).
  double sigma_constant = 0.0012;   ///< metres
  double sigma_quadratic = 0.0019;  ///< metres per square metre
  double sigma_offset = 0.4;        ///< metres
  // Disparity quantization.
  double baseline = 0.075;            ///< projector-camera baseline b, metres
  double focal_length = 525.0;        ///< f of the disparity, pixels
  double disparity_step = 1.0 / 8.0;  ///< pixels; 0 turns quantization off
  // Range and dropouts.
  double min_range = 0.45;             ///< metres; nearer returns are lost
  double max_range = 8.0;              ///< metres; farther returns are lost
  double dropout_probability = 0.005;  ///< chance that any return is lost
  // Bend (see above).
  double bend_curvature = 0.0;        ///< kappa: curvature of a wall facing the camera at z_ref, 1/m; 0: off
  double bend_reference_depth = 3.5;  ///< z_ref, metres
};

/// sigma_z(z) of Nguyen et al., metres: the spread of the measured depth at depth z.
double axialNoiseSigma(double z, const KinectParams& params);

/// The depth nearest to z that the sensor can report (the disparity lattice); z itself if
/// quantization is off.
double quantizeDepth(double z, const KinectParams& params);

/// The bend's depth error e(z, rho) (see above), metres along the ray: `z` the exact depth,
/// `tangent_squared` = rho^2 = x^2 + y^2 of the pixel's ray (x, y, 1). 0 when the bend is off.
double kinectBendOffset(double z, double tangent_squared, const KinectParams& params);

/// The depth the Kinect model reports for a surface at exact depth `z` (metres), or nothing
/// when the return is lost (out of range or dropped). Draws from `random` as listed above.
std::optional<double> measureKinectDepth(double z, const KinectParams& params, PixelRandom& random);

}  // namespace floodplane::synth
