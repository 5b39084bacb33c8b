// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/point_grid.h"
#include "models/tolerances.h"
#include "util/vec3.h"

namespace floodplane {

/// A pixel accepted as the start of a flood, with what the flood needs from it.
struct Seed {
  std::size_t index = 0;           ///< linear pixel index
  Vec3 point;                      ///< P_seed
  Vec3 normal;                     ///< n_seed, unit, facing the sensor (see SeedSelector)
  float normal_uncertainty = 0.f;  ///< standard deviation of n_seed's direction [rad]
  float spacing = 0.f;             ///< sigma_euclidean of Eq. 8: metres per pixel at the seed
  int rho = 0;                     ///< the seed cube's half side in pixels (Fig. 3)
};

/// Why a seed candidate was accepted or rejected, in the order the tests run.
enum class SeedVerdict {
  kAccepted,
  kHole,                   ///< the candidate or a pixel of its cross is not a finite point
  kNearBorder,             ///< the seed cross of radius rho does not fit in the grid
  kDistanceDiscontinuity,  ///< Eq. 5 failed
  kCoarseCurvature,        ///< Eq. 6 failed
  kFineCurvature,          ///< Eq. 7 failed
};

/// Seed selection of Sec. III-C. The sensor is at the origin of the grid's frame.
///
/// Deviations from the paper, each for a stated reason:
/// - Angles: Sec. IV gives theta_angle = 0.1 rad "about 6 degrees", but Eqs. 6, 7 and 9
///   compare 1 - |n_i . n_j| with it, which allows 26 degrees. We compare the angle itself
///   with theta_angle, as Sec. IV describes.
/// - Eq. 7 compares vectors it never normalises; we compare directions (unit vectors).
/// - Noise: with a depth noise coefficient c > 0 the angle tolerance grows by the angle that
///   3 sigma_depth(r) subtends over the lever arm of the test, so that a Kinect's noise at 3 m
///   is not mistaken for curvature. With c = 0 the tests are the paper's.
/// - The four normals of Eq. 6 are taken from the endpoints of the seed cross (rho pixels
///   away), not from the immediate neighbours: on a depth camera neighbouring pixels are
///   closer together than the depth noise, so their cross products are mostly noise.
/// - The seed cube grows with the depth noise, to a side of at least 6 sigma_depth(r), so
///   that the cross's arms are three noise deviations long (a Kinect cannot resolve smaller
///   planes at that range; at 5 m the 6 cm cube of the paper is one noise deviation).
/// - n_seed: Eq. 6's cross products decide that the seed is flat; the normal itself is the
///   least-squares normal of the 4 rho + 1 points of the cross (those Eq. 7 visits). Without
///   noise both are the same plane; with noise the fit uses all the points instead of four.
class SeedSelector {
 public:
  /// Prepares the tests for one grid. `angular_pitch` is the angle between the viewing rays
  /// of neighbouring pixels (1/f for a pinhole camera of focal length f pixels).
  /// `scale` shrinks the seed cube's fixed part (the finer second pass: 1/2, 1/3 on frames
  /// without noise, see segmenter.cpp).
  void configure(const Params& params, const Tolerances& tolerances, double scale, float angular_pitch, int width,
                 int height);

  /// The side of the seed cube at range r: twice Tolerances::seedHalfSide.
  float seedSizeAt(float range) const;
  /// rho of Fig. 3: the pixel distance that the seed cube spans around a point at range
  /// `range`. Clamped to [2, max_rho()].
  int rhoAt(float range) const;
  /// The largest rho that fits the grid (0 when the grid is too small for any seed).
  int maxRho() const { return max_rho_; }

  /// Runs the tests of Eqs. 5-7 on pixel (x, y) and, if it passes, fills `seed` (Eq. 8).
  SeedVerdict test(const PointGrid& grid, int x, int y, Seed& seed) const;

  /// The angle between neighbouring viewing rays on the optical axis (1 / f for a pinhole),
  /// the 98th percentile over a sample of neighbouring finite points; `fallback` when the
  /// grid has no neighbouring finite points.
  static float estimateAngularPitch(const PointGrid& grid, std::vector<float>& scratch, float fallback = 1.0f / 525.0f);

 private:
  Tolerances tolerances_;  // a copy: the caller's may not outlive configure()
  double scale_ = 1.0;
  float cos_angle_ = 1.f;
  float angle_ = 0.1f;
  float angular_pitch_ = 1.0f / 525.0f;
  int max_rho_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace floodplane
