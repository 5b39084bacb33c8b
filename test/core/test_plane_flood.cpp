// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-A, III-B: one flood from a hand-made seed over hand-made grids. Eq. 2 (plane
// distance) and Eq. 3 (Euclidean neighbours) each stop it on their own, Eq. 4 takes pixels from
// another segment only when they fit better (by the takeover margin between estimates of one
// plane), the plane is refit once the segment holds max(16, rho^2) pixels, and pixels rejected
// under the seed's plane are tested again under the refit one.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "flood/plane_flood.h"
#include "support/pinhole_grid.h"
#include "util/distance_buffer.h"
#include "util/simd.h"

namespace floodplane {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kFocal = test::kPinholeFocal;

using Grid = test::PinholeGrid;

// One flood's world: buffer, segments (0 is "none"), edges.
struct Flood {
  DistanceBuffer buffer;
  std::vector<Segment> segments;
  std::vector<SegmentEdge> edges;
  PlaneFlood flood;
  Params params;
  NoiseModel noise;  // none: the paper's fixed thresholds

  explicit Flood(const Grid& g) {
    params.distance_threshold = 0.01;  // the paper's sigma_plane
    buffer.reset(static_cast<std::size_t>(g.width * g.height));
    segments.assign(1, Segment());
    flood.beginFrame();
  }
  // A seed at (u, v) with the given normal and Eq. 8's spacing (metres between neighbouring
  // pixels at the seed).
  Seed seedAt(const Grid& g, int u, int v, Vec3 normal, float spacing, int rho = 2) const {
    Seed seed;
    seed.index = g.index(u, v);
    seed.point = g.point(u, v);
    seed.normal = normal * (1.0f / normal.norm());
    seed.normal_uncertainty = 0.05f;
    seed.spacing = spacing;
    seed.rho = rho;
    return seed;
  }
  std::size_t grow(const Grid& g, const Seed& seed) {
    const std::int32_t label = static_cast<std::int32_t>(segments.size());
    segments.emplace_back();
    const Tolerances tolerances(params, noise, 1.0 / kFocal, static_cast<std::size_t>(g.width * g.height));
    return flood.grow(g.grid(), seed, label, params, tolerances, {buffer, segments, edges});
  }
  std::size_t count(std::int32_t label) const {
    std::size_t n = 0;
    for (const std::int32_t l : buffer.labels()) n += l == label ? 1 : 0;
    return n;
  }
};

const Vec3 kFacing{0, 0, -1};  // a frontal plane's normal, towards the camera
// Pixels are 2 cm apart at 2 m (focal 100 px).
constexpr float kSpacingAt2m = 0.02f;

TEST(PlaneFlood, ClaimsEveryPixelOfAPlaneAndSumsThem) {
  const Grid g(40, 30, [](int, int) { return 2.0; });
  Flood f(g);
  EXPECT_EQ(f.grow(g, f.seedAt(g, 20, 15, kFacing, kSpacingAt2m)), 0u);
  EXPECT_EQ(f.count(1), 40u * 30u);
  EXPECT_DOUBLE_EQ(f.segments[1].sums.count, 1200.0);
  EXPECT_NEAR(f.segments[1].sums.centroid().z(), 2.0, 1e-6);
  EXPECT_TRUE(f.edges.empty());
}

TEST(PlaneFlood, Equation2StopsItWherePointsLeaveThePlane) {
  // The right half is 3 cm behind the left: beyond sigma_plane = 1 cm. A huge seed spacing
  // switches Eq. 3 off, so only the plane distance can stop the flood.
  const Grid g(40, 30, [](int u, int) { return u < 20 ? 2.0 : 2.03; });
  Flood f(g);
  f.grow(g, f.seedAt(g, 5, 15, kFacing, 10.0f));
  EXPECT_EQ(f.count(1), 20u * 30u);
  EXPECT_EQ(f.buffer.label(g.index(19, 3)), 1);
  EXPECT_EQ(f.buffer.label(g.index(20, 3)), 0);

  Flood wide(g);
  wide.params.distance_threshold = 0.05;  // the step is now within the plane tolerance
  wide.grow(g, wide.seedAt(g, 5, 15, kFacing, 10.0f));
  EXPECT_EQ(wide.count(1), 40u * 30u);
}

TEST(PlaneFlood, Equation3StopsItAtAGapAlongThePlane) {
  // Both halves lie on z = 2, but the right one is shifted 20 cm sideways: its first column
  // is 22 cm from its left neighbour, beyond twice the seed's spacing (4 cm).
  Grid g(40, 30, [](int, int) { return 2.0; });
  for (int v = 0; v < 30; ++v)
    for (int u = 20; u < 40; ++u) g.data[g.index(u, v) * g.stride] += 0.2f;
  Flood f(g);
  f.grow(g, f.seedAt(g, 5, 15, kFacing, kSpacingAt2m));
  EXPECT_EQ(f.count(1), 20u * 30u);

  Flood loose(g);  // a seed that saw a 20 cm spacing accepts the gap
  loose.grow(g, loose.seedAt(g, 5, 15, kFacing, 0.2f));
  EXPECT_EQ(loose.count(1), 40u * 30u);
}

TEST(PlaneFlood, DoesNotCrossHolesButFloodsAroundThem) {
  // A column of holes with a gap at the bottom row: the right half is reached around it.
  const Grid g(30, 20, [](int u, int v) { return (u == 15 && v < 19) ? static_cast<double>(kNaN) : 2.0; });
  Flood f(g);
  f.grow(g, f.seedAt(g, 5, 5, kFacing, kSpacingAt2m));
  EXPECT_EQ(f.count(1), 30u * 20u - 19u);
  EXPECT_EQ(f.buffer.label(g.index(15, 5)), 0);
  EXPECT_EQ(f.buffer.label(g.index(25, 5)), 1);
}

// A segment 1 that owns the right half at `owned_distance` under `owner_normal`.
void claimRightHalf(Flood& f, const Grid& g, float owned_distance, Vec3 owner_normal) {
  f.segments.emplace_back();
  Segment& owner = f.segments[1];
  owner.criterion.normal = owner_normal * (1.0f / owner_normal.norm());
  for (int v = 0; v < g.height; ++v) {
    for (int u = g.width / 2; u < g.width; ++u) {
      f.buffer.claim(g.index(u, v), 1, owned_distance);
      owner.sums.add(g.point(u, v));
    }
  }
}

TEST(PlaneFlood, Equation4TakesPixelsThatFitItsPlaneBetter) {
  // The owner is another plane (45 degrees off) that claimed the pixels at 8 mm; they lie
  // exactly on this flood's plane.
  const Grid g(40, 30, [](int, int) { return 2.0; });
  Flood f(g);
  claimRightHalf(f, g, 0.008f, {0, 1, -1});
  const double owned = f.segments[1].sums.count;
  EXPECT_EQ(f.grow(g, f.seedAt(g, 5, 15, kFacing, kSpacingAt2m)), 600u);
  EXPECT_EQ(f.count(2), 1200u);
  EXPECT_TRUE(f.segments[1].lost_pixels);
  EXPECT_NEAR(f.segments[1].sums.count, owned - 600.0, 1e-9);
  EXPECT_NEAR(f.segments[2].sums.count, 1200.0, 1e-9);
}

TEST(PlaneFlood, Equation4KeepsPixelsOfAnEstimateOfTheSamePlaneWithinTheMargin) {
  // The owner is an estimate of the same plane: a pixel changes hands only if this flood fits
  // it better by a quarter of the tolerance (2.5 mm of 1 cm).
  const Grid g(40, 30, [](int, int) { return 2.0; });
  Flood close(g);
  claimRightHalf(close, g, 0.002f, kFacing);  // 0 + 2.5 mm is not below 2 mm
  EXPECT_EQ(close.grow(g, close.seedAt(g, 5, 15, kFacing, kSpacingAt2m)), 0u);
  EXPECT_EQ(close.count(2), 600u);
  EXPECT_FALSE(close.segments[1].lost_pixels);
  // It stopped at the owner: the two touch.
  ASSERT_EQ(close.edges.size(), 1u);
  EXPECT_EQ(close.edges[0], SegmentEdge(2, 1));

  Flood worse(g);
  claimRightHalf(worse, g, 0.004f, kFacing);  // 0 + 2.5 mm < 4 mm: taken
  EXPECT_EQ(worse.grow(g, worse.seedAt(g, 5, 15, kFacing, kSpacingAt2m)), 600u);
  EXPECT_EQ(worse.count(2), 1200u);
}

TEST(PlaneFlood, RecordsTheSegmentItStopsAtOnlyOnce) {
  // The right half belongs to a plane 3 cm behind; the flood stops along the whole border.
  const Grid g(40, 30, [](int u, int) { return u < 20 ? 2.0 : 2.03; });
  Flood f(g);
  claimRightHalf(f, g, 0.0f, kFacing);
  f.grow(g, f.seedAt(g, 5, 15, kFacing, kSpacingAt2m));
  EXPECT_EQ(f.count(2), 600u);
  ASSERT_EQ(f.edges.size(), 1u);
  EXPECT_EQ(f.edges[0], SegmentEdge(2, 1));
}

// A plane z = 2 + 0.2 x (tilted about the vertical axis), seen from a seed whose normal is
// off by about 3 degrees about the same axis.
double tiltedDepth(int u, int width) {
  // On the ray through u: z = 2 + 0.2 x with x = (u - c) / f z, so z = 2 / (1 - 0.2 (u - c) / f).
  return 2.0 / (1.0 - 0.2 * (u - (width - 1) / 2.0) / kFocal);
}
const Vec3 kTiltedNormal{0.2f, 0.f, -1.f};
const Vec3 kSeedNormalOff{0.25f, 0.f, -1.f};  // 2.7 degrees from the true normal

TEST(PlaneFlood, RefitsThePlaneAsItGrows) {
  // Under the seed's plane only a band of about 0.2 m either side of the seed fits within
  // 1 cm; the refits during the fill (at 16, 32, 64, ... pixels) carry it across the plane.
  const int width = 120;
  const Grid g(width, 20, [&](int u, int) { return tiltedDepth(u, width); });
  Flood f(g);
  f.grow(g, f.seedAt(g, 60, 10, kSeedNormalOff, 0.03f));
  EXPECT_EQ(f.count(1), static_cast<std::size_t>(width * 20));
  const Vec3 truth = kTiltedNormal * (1.0f / kTiltedNormal.norm());
  EXPECT_GT(f.segments[1].criterion.normal.dot(truth), std::cos(0.001f));
}

TEST(PlaneFlood, RetestsWhatTheSeedPlaneRejectedUnderTheRefitPlane) {
  // With rho = 40 the first refit during the fill would come at 1600 pixels, but only about
  // 360 fit the seed's plane: the fill runs dry at the band's edges. The refit after it, and
  // the retest of the pixels it rejected, carry the segment across the whole plane.
  const int width = 120;
  const Grid g(width, 20, [&](int u, int) { return tiltedDepth(u, width); });
  Flood f(g);
  f.grow(g, f.seedAt(g, 60, 10, kSeedNormalOff, 0.03f, /*rho=*/40));
  EXPECT_EQ(f.count(1), static_cast<std::size_t>(width * 20));
}

// Whether the flood over an island of `columns` x `rows` pixels of the tilted plane kept the
// seed's plane (no refit) or refit it.
bool keepsTheSeedPlane(int columns, int rows, int rho) {
  const int width = 120;
  const Grid g(width, 20, [&](int u, int v) {
    const bool inside = u >= 60 && u < 60 + columns && v >= 8 && v < 8 + rows;
    return inside ? tiltedDepth(u, width) : static_cast<double>(kNaN);
  });
  Flood f(g);
  f.grow(g, f.seedAt(g, 60, 10, kSeedNormalOff, 0.03f, rho));
  EXPECT_EQ(f.count(1), static_cast<std::size_t>(columns * rows));
  const Vec3 seed_normal = kSeedNormalOff * (1.0f / kSeedNormalOff.norm());
  return f.segments[1].criterion.normal.dot(seed_normal) > 1.0f - 1e-7f;
}

TEST(PlaneFlood, FirstRefitsAtSixteenPixelsOrRhoSquared) {
  // The first refit comes when the segment holds max(16, rho^2) pixels (the frontier's retest
  // after the fill refits too, but only when pixels were rejected: none are on an island).
  EXPECT_TRUE(keepsTheSeedPlane(3, 5, 2));   // 15 < 16
  EXPECT_FALSE(keepsTheSeedPlane(4, 4, 2));  // 16
  EXPECT_TRUE(keepsTheSeedPlane(4, 6, 5));   // 24 < 25
  EXPECT_FALSE(keepsTheSeedPlane(5, 5, 5));  // 25
}

TEST(PlaneFlood, WidensTheToleranceWithTheDepthNoiseAtRange) {
  // The right half is 3 cm behind: beyond 1 cm, within 3 sigma = 3 * 0.003 * 2^2 = 3.6 cm.
  const Grid g(40, 30, [](int u, int) { return u < 20 ? 2.0 : 2.03; });
  Flood f(g);
  f.noise.sigma_quadratic = 0.003;
  f.grow(g, f.seedAt(g, 5, 15, kFacing, 10.0f));
  EXPECT_EQ(f.count(1), 1200u);
}

TEST(PlaneFlood, DecidesFourPixelsAtATimeAsPixelByPixel) {
  if (!simdEnabled()) GTEST_SKIP() << "built without SIMD (FLOODPLANE_SIMD=OFF): there is no four-pixel path";
  // Stride 4 takes the four-pixel path, stride 3 the pixel-by-pixel one; a takeover in the
  // middle and a step at the right make both kinds of group of four and borders.
  const auto depth = [](int u, int v) { return u > 50 ? 2.03 : 2.0 + 0.0005 * ((u * 7 + v * 3) % 5); };
  const Grid by_pixel(61, 23, depth, 3), by_group(61, 23, depth, 4);
  Flood a(by_pixel), b(by_group);
  // The owner is an estimate of the same plane: Eq. 4's margin decides pixel by pixel.
  claimRightHalf(a, by_pixel, 0.0035f, kFacing);
  claimRightHalf(b, by_group, 0.0035f, kFacing);
  EXPECT_EQ(a.grow(by_pixel, a.seedAt(by_pixel, 3, 11, kFacing, kSpacingAt2m)),
            b.grow(by_group, b.seedAt(by_group, 3, 11, kFacing, kSpacingAt2m)));
  EXPECT_EQ(a.buffer.labels(), b.buffer.labels());
  EXPECT_EQ(a.buffer.distances(), b.buffer.distances());
  EXPECT_NEAR(a.segments[2].sums.sz, b.segments[2].sums.sz, 1e-9);
  EXPECT_NEAR(a.segments[1].sums.count, b.segments[1].sums.count, 1e-9);
}

}  // namespace
}  // namespace floodplane
