// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Every field of floodplane::Params in one list, in the struct's order. Everything that
// handles the parameters one by one follows from it: their validation (Params::problem), their
// JSON (io/params_json.cpp), the Python keywords (python/src/params_kwargs.cpp), the
// command-line flags and the flag names in the apps' error messages (toolkit/cli/
// param_options.cpp), and, at build time, the Python stubs' keywords and the ROS node's
// dynamic_reconfigure entries (codegen/param_lists.cpp). The PCL class's setters are written by
// hand, for their documentation; test_param_options calls the setter named here for every
// entry, so a missing one does not compile. So is the ROS nodelet's reading of its config:
// test_param_lists (test/params) holds it and the generated lists to this list. A new
// parameter: a field in Params, a line here, a setter in FloodFillPlaneSegmentation, its row in
// the README (CONTRIBUTING.md).
//
// X(field, Kind, flag, setter, help):
//   field   the Params member;
//   Kind    what values it takes, one of the tags below (the validation and the readers follow
//           from it and from the member's type);
//   flag    pcd_segment's and pcd_compare's command-line option;
//   setter  the member function of FloodFillPlaneSegmentation that sets it;
//   help    the flag's --help text.
#define FLOODPLANE_PARAMETERS(X)                                                                                     \
  X(distance_threshold, Length, "--distance-threshold", setDistanceThreshold,                                        \
    "sigma_plane [m]: largest point-to-plane distance in the flood (Eq. 2); default: 3 noise deviations (the "       \
    "paper: 0.01)")                                                                                                  \
  X(seed_size, Length, "--seed-size", setSeedSize,                                                                   \
    "sigma_seed [m]: side of the seed cube; default: from the noise and the pixel size (the paper: 0.06)")           \
  X(angular_threshold, Angle, "--angular-threshold", setAngularThreshold,                                            \
    "theta_angle [rad]: largest angle between normals in the seed and merge tests")                                  \
  X(merge_distance, Length, "--merge-distance", setMergeDistance,                                                    \
    "sigma_plane-merge [m]: largest centroid-to-plane distance of merging planes; default: 3 noise deviations (the " \
    "paper: 0.03)")                                                                                                  \
  X(min_inliers, Count, "--min-inliers", setMinInliers,                                                              \
    "Smallest number of points of a plane; default: one pixel in a thousand")                                        \
  X(maximum_curvature, Fraction, "--maximum-curvature", setMaximumCurvature,                                         \
    "Largest curvature of a plane (1/3 accepts every plane)")                                                        \
  X(subsampling, Subsampling, "--subsample", setSubsampling,                                                         \
    "Coarse to fine: the big planes found on s x s blocks (1, 2, 4 or 8) first; 1: every pixel from the start")      \
  X(depth_noise_coefficient, Noise, "--depth-noise-coefficient", setDepthNoiseCoefficient,                           \
    "c [1/m] of the depth noise sigma_0 + c r^2; default: measured on each frame")                                   \
  X(depth_noise_constant, Noise, "--depth-noise-constant", setDepthNoiseConstant,                                    \
    "sigma_0 [m] of the depth noise sigma_0 + c r^2; default: measured on each frame")

namespace floodplane::params_table {

// The kinds of value (Params::problem() holds each to its rule).
struct Length {};       // std::optional<double>, metres > 0; unset: derived from the frame
struct Angle {};        // double, radians in (0, pi/2)
struct Count {};        // std::optional<std::uint32_t>; unset: derived from the frame size
struct Fraction {};     // double >= 0
struct Subsampling {};  // int: 1, 2, 4 or 8
struct Noise {};        // std::optional<double> >= 0; unset (both): measured on the frame

#define FLOODPLANE_PARAMETERS_COUNT_ONE(field, kind, flag, setter, help) +1
/// How many parameters the list has (a test holds it to the number of Params' fields).
inline constexpr int kCount = 0 FLOODPLANE_PARAMETERS(FLOODPLANE_PARAMETERS_COUNT_ONE);
#undef FLOODPLANE_PARAMETERS_COUNT_ONE

}  // namespace floodplane::params_table
