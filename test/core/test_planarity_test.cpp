// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Beyond the paper: the planarity test. A noisy plane is kept, a wall bent by a sensor's
// calibration is kept, patches of a column and of a ball are rejected; two touching strips of
// a column, each flat within the noise, are one curved surface, and two faces meeting at a
// crease are not.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "models/planarity_test.h"
#include "models/plane_sums.h"
#include "models/tolerances.h"

namespace floodplane {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPitch = 1.0 / 525.0;  // a Kinect's angle between neighbouring pixels

// Kinect-like noise along the rays: sigma(r) = c r^2.
Tolerances tolerancesFor(double quadratic) {
  static const Params params;
  NoiseModel noise;
  noise.sigma_quadratic = quadratic;
  return Tolerances(params, noise, kPitch, 640 * 480);
}

// Points of a surface given as a function of two parameters in [0, 1], each moved along its
// viewing ray by Gaussian noise of sigma(r) = c r^2.
std::vector<Eigen::Vector3d> sample(const std::function<Eigen::Vector3d(double, double)>& surface, int n,
                                    double quadratic, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      Eigen::Vector3d p = surface((i + 0.5) / n, (j + 0.5) / n);
      const double r = p.norm();
      p *= 1.0 + quadratic * r * r * gauss(rng) / r;
      points.push_back(p);
    }
  }
  return points;
}

// Whether the planarity test calls the points, as one plane, curved.
bool curved(const std::vector<Eigen::Vector3d>& points, const Tolerances& tolerances) {
  PlaneSums sums;
  for (const Eigen::Vector3d& p : points) sums.add(Vec3{float(p.x()), float(p.y()), float(p.z())});
  PlanarityTest test;
  test.reset({sums.fit()});
  for (const Eigen::Vector3d& p : points) test.add(1, Vec3{float(p.x()), float(p.y()), float(p.z())});
  return test.curved(1, tolerances);
}

// A 60 cm square facing the camera at 2 m, tilted 30 degrees about the vertical.
Eigen::Vector3d tiltedSquare(double a, double b) {
  const double u = (a - 0.5) * 0.6, v = (b - 0.5) * 0.6;
  return {u * std::cos(kPi / 6), v, 2.0 + u * std::sin(kPi / 6)};
}

// The front of an upright column (radius 20 cm, axis 2.2 m away), 100 degrees of arc, 60 cm
// high.
Eigen::Vector3d columnFront(double a, double b) {
  const double radius = 0.2, angle = (a - 0.5) * (100.0 * kPi / 180.0);
  return {radius * std::sin(angle), (b - 0.5) * 0.6, 2.0 + radius - radius * std::cos(angle)};
}

// The cap of a ball (radius 30 cm, centre 2.3 m away) facing the camera, 90 degrees across.
Eigen::Vector3d ballCap(double a, double b) {
  const double radius = 0.3, theta = (a - 0.5) * (kPi / 2), phi = (b - 0.5) * (kPi / 2);
  const Eigen::Vector3d outward(std::sin(theta) * std::cos(phi), std::sin(phi), -std::cos(theta) * std::cos(phi));
  return Eigen::Vector3d(0, 0, 2.0 + radius) + radius * outward;
}

// A 3 m wide wall at 2 m bent with a radius of 50 m (a depth camera's calibration bends real
// walls far less).
Eigen::Vector3d bentWall(double a, double b) {
  const double x = (a - 0.5) * 3.0, radius = 50.0;
  return {x, (b - 0.5) * 2.0, 2.0 + x * x / (2.0 * radius)};
}

TEST(PlanarityTest, KeepsANoisyPlane) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    EXPECT_FALSE(curved(sample(tiltedSquare, 80, 0.0019, seed), tolerancesFor(0.0019))) << seed;
    EXPECT_FALSE(curved(sample(tiltedSquare, 80, 0.0, seed), tolerancesFor(0.0))) << seed;
  }
}

TEST(PlanarityTest, RejectsAPatchOfAColumn) {
  EXPECT_TRUE(curved(sample(columnFront, 60, 0.0019, 4), tolerancesFor(0.0019)));
  EXPECT_TRUE(curved(sample(columnFront, 60, 0.0, 4), tolerancesFor(0.0)));
}

TEST(PlanarityTest, RejectsAPatchOfABall) {
  EXPECT_TRUE(curved(sample(ballCap, 60, 0.0019, 5), tolerancesFor(0.0019)));
  EXPECT_TRUE(curved(sample(ballCap, 60, 0.0, 5), tolerancesFor(0.0)));
}

// The unweighted sums (two at a time where the core has SIMD) are bit for bit those of a
// weight of one (the per-monomial scalar loop): every judgement follows from them.
TEST(PlanarityTest, UnweightedSumsAreThoseOfAWeightOfOne) {
  const std::vector<Eigen::Vector3d> points = sample(columnFront, 40, 0.0019, 7);
  PlaneSums sums;
  for (const Eigen::Vector3d& p : points) sums.add(Vec3{float(p.x()), float(p.y()), float(p.z())});
  PlanarityTest plain, weighted;
  plain.reset({sums.fit(), sums.fit()});
  weighted.reset({sums.fit(), sums.fit()});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p{float(points[i].x()), float(points[i].y()), float(points[i].z())};
    const std::uint32_t k = 1 + static_cast<std::uint32_t>(i % 2);  // plane 2's sums are not 16-byte aligned
    plain.add(k, p);
    weighted.add(k, p, 1.0);
  }
  for (const std::uint32_t k : {1u, 2u}) {
    EXPECT_EQ(plain.curvature(k), weighted.curvature(k)) << k;
    EXPECT_GT(plain.curvature(k), 0.0) << k;
  }
  PlaneSums joint = sums;
  EXPECT_EQ(plain.unionCurvature(1, 2, joint.fit()), weighted.unionCurvature(1, 2, joint.fit()));
}

TEST(PlanarityTest, KeepsAWallBentByFarLessThanTheCurvedThingsInRooms) {
  // The bend is significant (centimetres over a low noise) but its radius is far beyond
  // that of a column or a ball.
  EXPECT_FALSE(curved(sample(bentWall, 80, 0.0002, 6), tolerancesFor(0.0002)));
}

TEST(PlanarityTest, NeedsEnoughPointsToCallAPlaneCurved) {
  // Five by five points of the ball: too few to tell a bend from noise.
  EXPECT_FALSE(curved(sample(ballCap, 4, 0.0, 7), tolerancesFor(0.0)));
}

TEST(PlanarityTest, ReportsTheCurvatureOfTheSurface) {
  PlaneSums sums;
  const std::vector<Eigen::Vector3d> points = sample(columnFront, 60, 0.0, 8);
  for (const Eigen::Vector3d& p : points) sums.add(Vec3{float(p.x()), float(p.y()), float(p.z())});
  PlanarityTest test;
  test.reset({sums.fit()});
  for (const Eigen::Vector3d& p : points) test.add(1, Vec3{float(p.x()), float(p.y()), float(p.z())});
  // A quadratic over 100 degrees of a circle of radius 0.2 m: about 1 / 0.2 m.
  EXPECT_NEAR(test.curvature(1), 5.0, 1.5);
}

// Two touching surfaces, as RegionBuilder::dropCurvedPlanes judges a facet pair: whether they
// are one curved surface, and whether their union, as one plane, fails the single test. Each alone must
// pass the test: that is what the pair test is for.
struct PairVerdict {
  bool curved_pair = false, union_bends = false;
};
PairVerdict judgePair(const std::vector<Eigen::Vector3d>& first, const std::vector<Eigen::Vector3d>& second,
                      const Tolerances& tolerances) {
  const auto vec = [](const Eigen::Vector3d& p) { return Vec3{float(p.x()), float(p.y()), float(p.z())}; };
  PlaneSums a, b;
  for (const Eigen::Vector3d& p : first) a.add(vec(p));
  for (const Eigen::Vector3d& p : second) b.add(vec(p));
  PlaneSums joint = a;
  joint.merge(b);
  PlanarityTest test;
  test.reset({a.fit(), b.fit(), joint.fit()});
  for (const Eigen::Vector3d& p : first) {
    test.add(1, vec(p));
    test.add(3, vec(p));
  }
  for (const Eigen::Vector3d& p : second) {
    test.add(2, vec(p));
    test.add(3, vec(p));
  }
  EXPECT_FALSE(test.curved(1, tolerances));
  EXPECT_FALSE(test.curved(2, tolerances));
  return {test.curvedPair(1, 2, joint.fit(), tolerances), test.curved(3, tolerances)};
}

constexpr double kColumnRadius = 0.25;

// A point of an upright column (axis 2.25 m away) at `degrees` of arc from the side facing
// the camera, `b` in [0, 1] up its 60 cm.
Eigen::Vector3d onColumn(double degrees, double b) {
  const double angle = degrees * kPi / 180.0;
  return {kColumnRadius * std::sin(angle), (b - 0.5) * 0.6, 2.0 + kColumnRadius * (1.0 - std::cos(angle))};
}

// The strip of the column between `from` and `to` degrees: a facet as the flood cuts it, its
// sagitta within a Kinect's noise band.
std::function<Eigen::Vector3d(double, double)> columnStrip(double from, double to) {
  return [from, to](double a, double b) { return onColumn(from + a * (to - from), b); };
}

// The flat face between the column's edges at `from` and `to` degrees (the chord).
std::function<Eigen::Vector3d(double, double)> chord(double from, double to) {
  return [from, to](double a, double b) {
    Eigen::Vector3d point = onColumn(from, b) + a * (onColumn(to, b) - onColumn(from, b));
    return point;
  };
}

TEST(PlanarityTest, TwoFacetsOfAColumnAreOneCurvedSurface) {
  // Kinect-like noise (exact strips are curved each on its own).
  for (const unsigned seed : {11u, 12u, 13u}) {
    EXPECT_TRUE(judgePair(sample(columnStrip(-14, 0), 40, 0.0019, seed),
                          sample(columnStrip(0, 14), 40, 0.0019, seed + 100), tolerancesFor(0.0019))
                    .curved_pair)
        << seed;
  }
}

TEST(PlanarityTest, TwoFacesMeetingAtACreaseAreNotACurvedSurface) {
  // Two flat faces, each the chord of 30 degrees of the column, meeting at 30 degrees: the
  // union bends as much as two facets of the column do, but two planes fit it better than any
  // smooth quadratic.
  for (const unsigned seed : {11u, 12u, 13u}) {
    for (const double noise : {0.0019, 0.0}) {
      const PairVerdict verdict = judgePair(sample(chord(-30, 0), 40, noise, seed),
                                            sample(chord(0, 30), 40, noise, seed + 100), tolerancesFor(noise));
      EXPECT_TRUE(verdict.union_bends) << seed << " " << noise;  // what the pair test has to tell apart
      EXPECT_FALSE(verdict.curved_pair) << seed << " " << noise;
    }
  }
}

}  // namespace
}  // namespace floodplane
