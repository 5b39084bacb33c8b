// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The running sums behind every plane fit (Sec. III-B refits, Sec. III-D merges): adding,
// removing and merging points, and the least-squares plane they give.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "models/plane_sums.h"

namespace floodplane {
namespace {

Vec3 toVec3(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}
Eigen::Vector3d toEigen(const Vec3& p) { return {p.x, p.y, p.z}; }

PlaneSums sumsOf(const std::vector<Vec3>& points) {
  PlaneSums sums;
  for (const Vec3& p : points) sums.add(p);
  return sums;
}

void expectSameSums(const PlaneSums& a, const PlaneSums& b, double tolerance) {
  EXPECT_NEAR(a.count, b.count, 0.0);
  EXPECT_NEAR(a.sx, b.sx, tolerance);
  EXPECT_NEAR(a.sy, b.sy, tolerance);
  EXPECT_NEAR(a.sz, b.sz, tolerance);
  EXPECT_NEAR(a.sxx, b.sxx, tolerance);
  EXPECT_NEAR(a.sxy, b.sxy, tolerance);
  EXPECT_NEAR(a.sxz, b.sxz, tolerance);
  EXPECT_NEAR(a.syy, b.syy, tolerance);
  EXPECT_NEAR(a.syz, b.syz, tolerance);
  EXPECT_NEAR(a.szz, b.szz, tolerance);
}

// Random points near the plane z = 2 + 0.1 x (seeded).
std::vector<Vec3> cloud(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> side(-1.f, 1.f);
  std::normal_distribution<float> noise(0.f, 0.005f);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    const float x = side(rng), y = side(rng);
    points.push_back({x, y, 2.f + 0.1f * x + noise(rng)});
  }
  return points;
}

// The plane n . P + d = 0 with unit n and an orthonormal basis (u, v) in it.
struct KnownPlane {
  Eigen::Vector3d n, u, v;
  double d;
  Eigen::Vector3d at(double a, double b, double w = 0.0) const { return -d * n + a * u + b * v + w * n; }
};

// n = (1, 2, -2) / 3, d = 2: the point of the plane nearest the sensor is -d n = (-2/3,
// -4/3, 4/3), in front of the camera, and n points back to the sensor.
KnownPlane tiltedPlane() {
  KnownPlane p;
  p.n = Eigen::Vector3d(1, 2, -2) / 3.0;
  p.d = 2.0;
  p.u = p.n.unitOrthogonal();
  p.v = p.n.cross(p.u);
  return p;
}

// --- sums -------------------------------------------------------------------------------------

TEST(PlaneSums, AddAccumulatesCountSumsAndProducts) {
  PlaneSums sums;
  sums.add({1, 2, 3});
  sums.add({-1, 0, 2});
  EXPECT_DOUBLE_EQ(sums.count, 2.0);
  EXPECT_DOUBLE_EQ(sums.sx, 0.0);
  EXPECT_DOUBLE_EQ(sums.sy, 2.0);
  EXPECT_DOUBLE_EQ(sums.sz, 5.0);
  EXPECT_DOUBLE_EQ(sums.sxx, 2.0);
  EXPECT_DOUBLE_EQ(sums.sxy, 2.0);
  EXPECT_DOUBLE_EQ(sums.sxz, 1.0);
  EXPECT_DOUBLE_EQ(sums.syy, 4.0);
  EXPECT_DOUBLE_EQ(sums.syz, 6.0);
  EXPECT_DOUBLE_EQ(sums.szz, 13.0);
  EXPECT_TRUE(sums.centroid().isApprox(Eigen::Vector3d(0.0, 1.0, 2.5)));
}

TEST(PlaneSums, RemoveUndoesAdd) {
  const std::vector<Vec3> points = cloud(50, 1);
  PlaneSums sums = sumsOf(points);
  const std::vector<Vec3> extra = cloud(20, 2);
  for (const Vec3& p : extra) sums.add(p);
  for (const Vec3& p : extra) sums.remove(p);
  expectSameSums(sums, sumsOf(points), 1e-9);
}

TEST(PlaneSums, MergeEqualsSummingBothSetsDirectly) {
  const std::vector<Vec3> a = cloud(40, 3), b = cloud(60, 4);
  PlaneSums merged = sumsOf(a);
  merged.merge(sumsOf(b));
  std::vector<Vec3> both = a;
  both.insert(both.end(), b.begin(), b.end());
  const PlaneSums direct = sumsOf(both);
  expectSameSums(merged, direct, 1e-9);
  const PlaneFit f1 = merged.fit(), f2 = direct.fit();
  ASSERT_TRUE(f1.valid);
  EXPECT_TRUE(f1.normal.isApprox(f2.normal, 1e-9));
  EXPECT_NEAR(f1.offset, f2.offset, 1e-9);
  EXPECT_NEAR(f1.mean_squared_error, f2.mean_squared_error, 1e-12);
}

TEST(PlaneSums, CentroidOfNoPointsIsZero) { EXPECT_EQ(PlaneSums{}.centroid(), Eigen::Vector3d::Zero()); }

// --- fit ----------------------------------------------------------------------------------------

TEST(PlaneSums, FitsExactPointsToTheirPlane) {
  const KnownPlane plane = tiltedPlane();
  PlaneSums sums;
  for (int i = -3; i <= 3; ++i)
    for (int j = -2; j <= 2; ++j) sums.add(toVec3(plane.at(0.1 * i, 0.07 * j)));
  const PlaneFit fit = sums.fit();
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.normal.norm(), 1.0, 1e-12);
  EXPECT_NEAR(fit.normal.dot(plane.n), 1.0, 1e-6);  // same direction, not just same line
  EXPECT_NEAR(fit.offset, plane.d, 1e-6);
  EXPECT_NEAR(fit.mean_squared_error, 0.0, 1e-12);
  EXPECT_TRUE(fit.centroid.isApprox(plane.at(0, 0), 1e-6));
}

TEST(PlaneSums, TurnsTheNormalTowardsTheSensorWhicheverSideItIsOn) {
  // A wall at z = 3 and a floor 1 m below the camera (y down): normals (0, 0, -1), (0, -1, 0).
  PlaneSums wall, floor;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) {
      const float a = 0.2f * static_cast<float>(i), b = 0.2f * static_cast<float>(j);
      wall.add({a, b, 3.f});
      floor.add({a, 1.f, 2.f + b});
    }
  const PlaneFit w = wall.fit(), f = floor.fit();
  ASSERT_TRUE(w.valid);
  ASSERT_TRUE(f.valid);
  EXPECT_TRUE(w.normal.isApprox(Eigen::Vector3d(0, 0, -1), 1e-9)) << w.normal.transpose();
  EXPECT_NEAR(w.offset, 3.0, 1e-9);
  EXPECT_TRUE(f.normal.isApprox(Eigen::Vector3d(0, -1, 0), 1e-9)) << f.normal.transpose();
  EXPECT_NEAR(f.offset, 1.0, 1e-9);
  // The sensor is on the side the normal points to: n . 0 + d > 0.
  EXPECT_GT(w.offset, 0.0);
  EXPECT_GT(f.offset, 0.0);
}

TEST(PlaneSums, GivesAscendingEigenvaluesOfTheScatter) {
  // Corners (+-a, +-b) in the plane, each lifted by e s_a s_b along the normal: the
  // covariance is diagonal in (n, v, u) with variances (e^2, b^2, a^2).
  const KnownPlane plane = tiltedPlane();
  const double a = 1.0, b = 0.5, e = 0.01;
  PlaneSums sums;
  for (int sa : {-1, 1})
    for (int sb : {-1, 1}) sums.add(toVec3(plane.at(sa * a, sb * b, e * sa * sb)));
  const PlaneFit fit = sums.fit();
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.eigenvalues(0), e * e, 1e-6);
  EXPECT_NEAR(fit.eigenvalues(1), b * b, 1e-6);
  EXPECT_NEAR(fit.eigenvalues(2), a * a, 1e-6);
  EXPECT_LE(fit.eigenvalues(0), fit.eigenvalues(1));
  EXPECT_LE(fit.eigenvalues(1), fit.eigenvalues(2));
  EXPECT_NEAR(fit.mean_squared_error, e * e, 1e-6);
  EXPECT_NEAR(fit.curvature, e * e / (e * e + b * b + a * a), 1e-6);
  EXPECT_NEAR(std::abs(fit.normal.dot(plane.n)), 1.0, 1e-6);
}

TEST(PlaneSums, CovarianceIsThePopulationCovariance) {
  PlaneSums sums;
  sums.add({0, 0, 1});
  sums.add({2, 0, 1});
  sums.add({0, 2, 1});
  sums.add({2, 2, 1});
  const PlaneFit fit = sums.fit();
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.covariance(0, 0), 1.0, 1e-12);  // 1/N sum (x - 1)^2 = 1, not 4/3
  EXPECT_NEAR(fit.covariance(1, 1), 1.0, 1e-12);
  EXPECT_NEAR(fit.covariance(0, 1), 0.0, 1e-12);
  EXPECT_NEAR(fit.covariance(2, 2), 0.0, 1e-12);
}

TEST(PlaneSums, FitIsInvalidForFewerThanThreePoints) {
  PlaneSums sums;
  EXPECT_FALSE(sums.fit().valid);
  sums.add({0, 0, 1});
  sums.add({1, 0, 1});
  EXPECT_FALSE(sums.fit().valid);
}

// Regression: five points on the z axis gave a "valid" fit with normal (-1, 0, 0). Eigen's
// closed-form solver (computeDirect) returns the eigenvalues (-1.4e-9, 1.4e-9, 0.5) for the
// covariance diag(0, 0, 0.5), and the line test was `eigenvalues(1) > 0.0`; it is now
// relative to the largest eigenvalue.
TEST(PlaneSums, FitIsInvalidForCollinearPoints) {
  PlaneSums line;
  for (int i = 0; i < 5; ++i) line.add({0.f, 0.f, 1.f + 0.5f * static_cast<float>(i)});
  const PlaneFit fit = line.fit();
  EXPECT_FALSE(fit.valid) << "eigenvalues " << fit.eigenvalues.transpose() << ", normal " << fit.normal.transpose();
}

TEST(PlaneSums, FitIsInvalidForCoincidentPoints) {
  PlaneSums point;
  for (int i = 0; i < 5; ++i) point.add({0.5f, 0.5f, 2.f});
  EXPECT_FALSE(point.fit().valid);
}

// --- meanSquaredDistance ---------------------------------------------------------------------------

TEST(PlaneSums, MeanSquaredDistanceMatchesABruteForceSum) {
  const std::vector<Vec3> points = cloud(200, 5);
  const PlaneSums sums = sumsOf(points);
  const Eigen::Vector3d n = Eigen::Vector3d(0.1, 0.3, -1.0).normalized();
  const double d = 1.9;
  double brute = 0.0;
  for (const Vec3& p : points) {
    const double distance = n.dot(toEigen(p)) + d;
    brute += distance * distance;
  }
  brute /= static_cast<double>(points.size());
  EXPECT_GT(brute, 1e-3) << "the plane should be clearly off the points";
  EXPECT_NEAR(sums.meanSquaredDistance(n, d), brute, 1e-9 * (1.0 + brute));
}

TEST(PlaneSums, MeanSquaredDistanceToTheFittedPlaneIsTheSmallestEigenvalue) {
  const PlaneSums sums = sumsOf(cloud(300, 6));
  const PlaneFit fit = sums.fit();
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(sums.meanSquaredDistance(fit.normal, fit.offset), fit.mean_squared_error, 1e-9);
  // Any other plane fits worse.
  EXPECT_GT(sums.meanSquaredDistance(fit.normal, fit.offset + 0.01), fit.mean_squared_error);
}

TEST(PlaneSums, MeanSquaredDistanceOfNoPointsIsZero) {
  EXPECT_EQ(PlaneSums{}.meanSquaredDistance(Eigen::Vector3d::UnitZ(), 1.0), 0.0);
}

// --- normalUncertainty ----------------------------------------------------------------------------

TEST(NormalUncertainty, IsFiniteAndAsExpectedForATwoDimensionalSpread) {
  // Eigenvalues (e^2, b^2, a^2) as above: sigma = sqrt(e^2 / (N b^2)) = 0.01 / (2 * 0.5).
  const KnownPlane plane = tiltedPlane();
  PlaneSums sums;
  for (int sa : {-1, 1})
    for (int sb : {-1, 1}) sums.add(toVec3(plane.at(sa * 1.0, sb * 0.5, 0.01 * sa * sb)));
  const PlaneFit fit = sums.fit();
  const double sigma = normalUncertainty(fit, sums.count);
  ASSERT_TRUE(std::isfinite(sigma));
  EXPECT_NEAR(sigma, 0.01, 1e-5);
  // More points with the same spread: smaller uncertainty, as 1 / sqrt(N).
  EXPECT_NEAR(normalUncertainty(fit, 4.0 * sums.count), 0.005, 1e-5);
}

TEST(NormalUncertainty, IsInfiniteForCollinearPoints) {
  // A line in a general direction: rounding may leave the fit "valid" with two tiny
  // eigenvalues, but the points do not span a plane.
  PlaneSums sums;
  const Eigen::Vector3d start(0.2, -0.1, 1.5), direction = Eigen::Vector3d(0.3, 0.5, 0.8).normalized();
  for (int i = 0; i < 50; ++i) sums.add(toVec3(start + 0.02 * i * direction));
  EXPECT_TRUE(std::isinf(normalUncertainty(sums.fit(), sums.count)));
}

// Regression: for the z-axis line above the fit's smallest eigenvalue was negative (-1.4e-9),
// so `eigenvalues(1) >= 4 eigenvalues(0)` held and the result was sqrt(negative) = NaN, not
// infinity; in MergeCriterion::mergeable a NaN uncertainty skipped Eq. 9's normal test.
TEST(NormalUncertainty, IsInfiniteNotNaNForPointsOnACoordinateAxis) {
  PlaneSums line;
  for (int i = 0; i < 5; ++i) line.add({0.f, 0.f, 1.f + 0.5f * static_cast<float>(i)});
  const double sigma = normalUncertainty(line.fit(), line.count);
  EXPECT_TRUE(std::isinf(sigma)) << "got " << sigma;
}

TEST(NormalUncertainty, IsInfiniteForAStripNoWiderThanItsNoise) {
  // 1 m long, 4 mm wide, 3 mm of noise off the plane: lambda_1 < 4 lambda_0.
  const KnownPlane plane = tiltedPlane();
  PlaneSums sums;
  for (int i = 0; i < 100; ++i)
    for (int sb : {-1, 1})
      for (int sw : {-1, 1}) sums.add(toVec3(plane.at(0.01 * i, 0.002 * sb, 0.003 * sw * sb * (i % 2 ? 1 : -1))));
  const PlaneFit fit = sums.fit();
  ASSERT_TRUE(fit.valid);
  EXPECT_LT(fit.eigenvalues(1), 4.0 * fit.eigenvalues(0));
  EXPECT_TRUE(std::isinf(normalUncertainty(fit, sums.count)));
}

TEST(NormalUncertainty, IsInfiniteForAnInvalidFitOrNoPoints) {
  EXPECT_TRUE(std::isinf(normalUncertainty(PlaneFit{}, 10.0)));
  const KnownPlane plane = tiltedPlane();
  PlaneSums sums;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j) sums.add(toVec3(plane.at(0.1 * i, 0.1 * j, 0.001 * ((i + j) % 2))));
  ASSERT_TRUE(std::isfinite(normalUncertainty(sums.fit(), sums.count)));
  EXPECT_TRUE(std::isinf(normalUncertainty(sums.fit(), 0.0)));
}

// --- facesSensor ------------------------------------------------------------------------------

TEST(FacesSensor, AcceptsAPlaneSeenHeadOn) {
  EXPECT_TRUE(facesSensor(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, 2)));
  EXPECT_TRUE(facesSensor(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 2)));  // either sign
}

TEST(FacesSensor, RejectsAPlaneSeenEdgeOn) {
  // The normal is perpendicular to the viewing ray: the plane contains the ray.
  EXPECT_FALSE(facesSensor(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 2)));
  EXPECT_FALSE(facesSensor(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0.5, 0, 2)));
}

TEST(FacesSensor, DrawsTheLineAtTheMinimumIncidenceCosine) {
  const Eigen::Vector3d point(0, 0, 3);
  const auto normalAt = [](double cosine) { return Eigen::Vector3d(std::sqrt(1.0 - cosine * cosine), 0.0, -cosine); };
  EXPECT_TRUE(facesSensor(normalAt(kMinIncidenceCosine * 1.01), point));
  EXPECT_FALSE(facesSensor(normalAt(kMinIncidenceCosine * 0.99), point));
}

TEST(FacesSensor, RejectsAPointAtTheSensor) {
  EXPECT_FALSE(facesSensor(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d::Zero()));
}

}  // namespace
}  // namespace floodplane
