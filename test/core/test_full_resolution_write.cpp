// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Coarse to fine, the one full-resolution write: labels of blocks brought to the pixels. Blocks
// inside a plane take it whole; border blocks are decided pixel by pixel (Eq. 2), where two
// planes meet by the side of their crease line; the planes' sums and first pixels are those
// of the pixels written.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "stages/full_resolution_write.h"
#include "support/pinhole_grid.h"
#include "util/simd.h"

namespace floodplane {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr float kPitch = static_cast<float>(1.0 / test::kPinholeFocal);
using Grid = test::PinholeGrid;

// Writes the labels of `grid`, read in s x s blocks, from block labels given by
// `block_plane(bx, by)`, for planes (normal, offset) with a noise of `sigma` along the rays.
struct Written {
  BlockGrid blocks;
  std::vector<std::uint32_t> block_labels;
  std::vector<std::uint32_t> identity;
  PlaneCandidates planes;
  std::vector<FloodCriterion> criteria;
  std::vector<Vec3> centroids;
  std::vector<std::uint32_t> labels;
  FullResolutionWrite writer;

  Written(const Grid& grid, int s, const std::function<std::uint32_t(int, int)>& block_plane,
          const std::vector<std::pair<Vec3, Vec3>>& plane_normal_and_point, double sigma) {
    blocks.read(grid.grid(), s);
    const PointGrid& means = blocks.means();
    for (int by = 0; by < means.height; ++by)
      for (int bx = 0; bx < means.width; ++bx) block_labels.push_back(block_plane(bx, by));
    Params params;
    params.distance_threshold = 0.001;
    params.depth_noise_constant = sigma;
    NoiseModel noise;
    noise.sigma_constant = sigma;
    const Tolerances tolerances(params, noise, kPitch, grid.data.size() / grid.stride);
    for (const auto& [normal, point] : plane_normal_and_point) {
      PlaneFit fit;
      fit.normal = Eigen::Vector3d(normal.x, normal.y, normal.z).normalized();
      fit.centroid = Eigen::Vector3d(point.x, point.y, point.z);
      fit.offset = -fit.normal.dot(fit.centroid);
      fit.valid = true;
      criteria.push_back(planeCriterion(fit, tolerances, kPitch));
      centroids.push_back(point);
      planes.list().emplace_back();
    }
    identity.resize(planes.list().size() + 1);
    for (std::uint32_t k = 0; k < identity.size(); ++k) identity[k] = k;
    writer.write(grid.grid(), blocks, RenumberedLabels{block_labels.data(), identity.data()}, criteria, centroids,
                 planes, labels);
  }
};

TEST(FullResolutionWrite, GivesEveryPixelOfABlockInsideAPlaneItsLabel) {
  const Grid grid(
      32, 24, [](int, int) { return 2.0; }, 4);
  const Written w(
      grid, 4, [](int, int) { return 1u; }, {{{0, 0, -1}, {0, 0, 2}}}, 0.0);
  for (const std::uint32_t label : w.labels) ASSERT_EQ(label, 1u);
  EXPECT_EQ(w.planes.list()[0].sums.count, 32.0 * 24.0);
  EXPECT_EQ(w.planes.list()[0].first_pixel, 0u);
}

TEST(FullResolutionWrite, DecidesTheBlockOfAnObjectInFrontOfAPlanePixelByPixel) {
  // One pixel 10 cm in front of a wall: its block fails the band test, and it alone is left out.
  const auto depth = [](int u, int v) { return u == 13 && v == 9 ? 1.9 : 2.0; };
  for (const std::size_t stride : {3u, 4u}) {
    const Grid grid(32, 24, depth, stride);
    const Written w(
        grid, 4, [](int, int) { return 1u; }, {{{0, 0, -1}, {0, 0, 2}}}, 0.0);
    for (int v = 0; v < 24; ++v)
      for (int u = 0; u < 32; ++u)
        ASSERT_EQ(w.labels[grid.index(u, v)], u == 13 && v == 9 ? 0u : 1u) << u << ", " << v << " stride " << stride;
    EXPECT_EQ(w.planes.list()[0].sums.count, 32.0 * 24.0 - 1.0);
  }
}

TEST(FullResolutionWrite, LeavesHolesAndBlocksWithoutAPlaneAroundUnlabelled) {
  const auto depth = [](int u, int v) { return (u + v) % 5 == 0 ? kNaN : 2.0; };
  const Grid grid(32, 24, depth, 4);
  // Planes on the left half of the blocks only.
  const Written w(
      grid, 4, [](int bx, int) { return bx < 4 ? 1u : 0u; }, {{{0, 0, -1}, {0, 0, 2}}}, 0.0);
  double count = 0.0;
  for (int v = 0; v < 24; ++v)
    for (int u = 0; u < 32; ++u) {
      const std::uint32_t label = w.labels[grid.index(u, v)];
      if ((u + v) % 5 == 0) {
        EXPECT_EQ(label, 0u);
      } else if (u >= 20) {  // two block columns away from every labelled block
        EXPECT_EQ(label, 0u);
      } else if (u < 16) {
        EXPECT_EQ(label, 1u);
      }
      count += label == 1u ? 1.0 : 0.0;
    }
  // The border block column (16-19) is decided pixel by pixel: its pixels are on the plane.
  for (int v = 0; v < 24; ++v) {
    for (int u = 16; u < 20; ++u) {
      if ((u + v) % 5 != 0) {
        EXPECT_EQ(w.labels[grid.index(u, v)], 1u);
      }
    }
  }
  EXPECT_EQ(w.planes.list()[0].sums.count, count);
}

TEST(FullResolutionWrite, SumsAndFirstPixelsAreThoseOfTheLabelledPixels) {
  std::mt19937 random(5);
  std::normal_distribution<double> noise(0.0, 0.004);
  std::vector<double> offsets(40 * 32);
  for (double& o : offsets) o = noise(random);
  // Two walls meeting at column 20; noise of 4 mm.
  const auto depth = [&](int u, int v) { return (u < 20 ? 2.0 : 2.0 + 0.02 * (u - 20)) + offsets[v * 40 + u]; };
  const Grid grid(40, 32, depth, 4);
  const Written w(
      grid, 4, [](int bx, int) { return bx < 5 ? 1u : 2u; },
      {{{0, 0, -1}, {0, 0, 2}}, {{0.2f, 0, -1}, {0.1f, 0, 2.05f}}}, 0.004);
  for (std::uint32_t k = 1; k <= 2; ++k) {
    PlaneSums expected;
    std::size_t first = kNoPixel;
    for (std::size_t i = 0; i < w.labels.size(); ++i) {
      if (w.labels[i] != k) continue;
      expected.add(grid.point(i));
      if (first == kNoPixel) first = i;
    }
    const PlaneSums& sums = w.planes.list()[k - 1].sums;
    EXPECT_EQ(sums.count, expected.count) << k;
    EXPECT_NEAR(sums.sz, expected.sz, 1e-6 * std::abs(expected.sz)) << k;
    EXPECT_NEAR(sums.szz, expected.szz, 1e-6 * std::abs(expected.szz)) << k;
    EXPECT_EQ(w.planes.list()[k - 1].first_pixel, first) << k;
  }
}

// A concave crease (a room's corner) and a convex one (a box's edge), seen through noise
// several times the planes' separation near the crease: the pixels there go to the plane on
// their side of the crease line, not to whichever plane the noise brings them nearer.
TEST(FullResolutionWrite, GivesThePixelsAlongACreaseThePlaneOnTheirSide) {
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.01);
  // The right plane recedes (a convex edge, as a box's seen from the front) or comes closer (a
  // concave corner, as a room's).
  for (const double slope : {0.05, -0.05}) {
    SCOPED_TRACE(slope > 0 ? "convex" : "concave");
    std::vector<double> offsets(64 * 16);
    for (double& o : offsets) o = noise(random);
    const auto depth = [&](int u, int v) {
      return (u < 32 ? 3.0 : 3.0 + slope * (u - 31.5)) + offsets[static_cast<std::size_t>(v * 64 + u)];
    };
    const Grid grid(64, 16, depth, 4);
    // The planes through the noise-free points, as fits of the two sides would give them.
    const Grid exact(
        64, 16, [&](int u, int) { return u < 32 ? 3.0 : 3.0 + slope * (u - 31.5); }, 4);
    const Vec3 left_a = exact.point(0, 0), left_b = exact.point(0, 15), left_c = exact.point(20, 0);
    const Vec3 right_a = exact.point(63, 0), right_b = exact.point(63, 15), right_c = exact.point(44, 0);
    const Vec3 left_normal = (left_b - left_a).cross(left_c - left_a);
    const Vec3 right_normal = (right_b - right_a).cross(right_c - right_a);
    const auto facing = [](Vec3 n, Vec3 p) { return n.dot(p) > 0 ? n * -1.f : n; };
    const Vec3 centre_left = exact.point(10, 8), centre_right = exact.point(53, 8);
    const Written w(
        grid, 4, [](int bx, int) { return bx < 7   ? 1u
                                          : bx > 8 ? 2u
                                                   : 0u; },
        {{facing(left_normal, left_a), centre_left}, {facing(right_normal, right_a), centre_right}}, 0.01);
    int wrong = 0;
    for (int v = 0; v < 16; ++v)
      for (int u = 26; u < 38; ++u) {
        const std::uint32_t label = w.labels[grid.index(u, v)];
        if (label != 0 && label != (u < 32 ? 1u : 2u)) ++wrong;
      }
    EXPECT_LE(wrong, 4) << "of 192 pixels within 6 of the crease";
  }
}

}  // namespace
}  // namespace floodplane
