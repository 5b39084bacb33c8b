// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-D: the merge test of Eq. 9 between two segments and the best-first agglomerative
// merging of the segment graph.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "flood/plane_merger.h"
#include "support/stage_fixture.h"

namespace floodplane {
namespace {

using test::exactParams;

// A checkerboard of +-0.1 mm off the plane: the residual of a real surface. Exactly planar
// patches are tested on their own (RejectsTwoExactPlanesAtAnAngleAboveTheThreshold).
constexpr float kRoughness = 1e-4f;
float rough(int i, int j, float roughness) { return (i + j) % 2 == 0 ? roughness : -roughness; }

// Points of a rectangular patch x in [x0, x1], y in [y0, y1] on the plane
// z = z0 + slope (x - x0), on a 21 x 21 grid.
PlaneSums patch(float x0, float x1, float z0, float slope = 0.f, float y0 = -0.05f, float y1 = 0.05f,
                float roughness = kRoughness) {
  PlaneSums sums;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const float x = x0 + (x1 - x0) * static_cast<float>(i) / 20.f;
      const float y = y0 + (y1 - y0) * static_cast<float>(j) / 20.f;
      sums.add({x, y, z0 + slope * (x - x0) + rough(i, j, roughness)});
    }
  return sums;
}

// A patch 2 cm square centred on (cx, 0, cz), tilted about the y axis by `tilt` radians.
PlaneSums smallPatch(float cx, float cz, float tilt, float roughness = kRoughness) {
  PlaneSums sums;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j) {
      const float s = 0.002f * static_cast<float>(i);
      const float w = rough(i + 5, j + 5, roughness);  // along the patch's normal
      sums.add({cx + s * std::cos(tilt) - w * std::sin(tilt), 0.002f * static_cast<float>(j),
                cz + s * std::sin(tilt) + w * std::cos(tilt)});
    }
  return sums;
}

MergeCriterion criterionFor(const Params& params) {
  NoiseModel noise;
  noise.sigma_quadratic = params.depth_noise_coefficient.value_or(0.0);
  return MergeCriterion(params, Tolerances(params, noise, 1.0 / 525.0, 640 * 480));
}

bool mergeable(const MergeCriterion& criterion, const PlaneSums& a, const PlaneSums& b, double* cost = nullptr) {
  double c = -1.0;
  const bool result = criterion.mergeable(a, a.fit(), b, b.fit(), c);
  if (cost) *cost = c;
  return result;
}

// --- MergeCriterion ---------------------------------------------------------------------------

TEST(MergeCriterion, AcceptsTwoHalvesOfOnePlane) {
  const MergeCriterion criterion = criterionFor(exactParams());
  double cost = -1.0;
  EXPECT_TRUE(mergeable(criterion, patch(-0.5f, 0.f, 2.f), patch(0.f, 0.5f, 2.f), &cost));
  EXPECT_LT(cost, 0.01);  // they fit one plane up to their roughness
}

TEST(MergeCriterion, AcceptsHalvesOfATiltedPlaneInEitherOrder) {
  const MergeCriterion criterion = criterionFor(exactParams());
  const PlaneSums left = patch(-0.4f, 0.f, 2.f, 0.5f), right = patch(0.f, 0.4f, 2.2f, 0.5f);
  EXPECT_TRUE(mergeable(criterion, left, right));
  EXPECT_TRUE(mergeable(criterion, right, left));
}

TEST(MergeCriterion, RejectsTwoPlanesAtAnAngleAboveTheThreshold) {
  // Two 2 cm patches side by side, tilted by -0.1 and +0.1 rad (0.2 rad apart), centroids on
  // one plane and each within 1 mm of the merged plane: only the normals tell them apart.
  const MergeCriterion criterion = criterionFor(exactParams());
  EXPECT_FALSE(mergeable(criterion, smallPatch(-0.05f, 2.f, -0.1f), smallPatch(0.05f, 2.f, 0.1f)));
  // The same patches 0.08 rad apart pass.
  EXPECT_TRUE(mergeable(criterion, smallPatch(-0.05f, 2.f, -0.04f), smallPatch(0.05f, 2.f, 0.04f)));
}

// Regression: the same two patches without roughness merged. For exactly planar points
// Eigen's closed-form solver can return a smallest eigenvalue of -1.3e-15; normalUncertainty()
// then took sqrt(negative) = NaN, MergeCriterion::mergeable's `allowed` angle became NaN, and
// `dot < cos(NaN)` was false: the normal test of Eq. 9 was skipped. Noise-free renders
// (pcd_synth --sensor none) are exactly this case. Eigenvalues are now clamped at zero and
// the angle test rejects on NaN.
TEST(MergeCriterion, RejectsTwoExactPlanesAtAnAngleAboveTheThreshold) {
  const MergeCriterion criterion = criterionFor(exactParams());
  EXPECT_FALSE(mergeable(criterion, smallPatch(-0.05f, 2.f, -0.1f, 0.f), smallPatch(0.05f, 2.f, 0.1f, 0.f)));
}

TEST(MergeCriterion, RejectsAWallAndAFloorMeetingAtAnEdge) {
  const MergeCriterion criterion = criterionFor(exactParams());
  PlaneSums wall, floor;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      const float a = 0.05f * static_cast<float>(i), b = 0.05f * static_cast<float>(j);
      wall.add({-0.5f + a, -0.5f + b, 3.f});
      floor.add({-0.5f + a, 0.5f, 2.f + b});
    }
  EXPECT_FALSE(mergeable(criterion, wall, floor));
}

TEST(MergeCriterion, RejectsParallelPlanesOffsetByMoreThanTheMergeDistance) {
  // Two small parallel patches 1 m apart sideways: a plane tilted by 2 or 4 cm per metre fits
  // both, so only Eq. 9's centroid-to-plane distance (3 cm) separates them.
  const MergeCriterion criterion = criterionFor(exactParams());
  EXPECT_TRUE(mergeable(criterion, smallPatch(-0.5f, 2.f, 0.f), smallPatch(0.5f, 2.02f, 0.f)));
  EXPECT_FALSE(mergeable(criterion, smallPatch(-0.5f, 2.f, 0.f), smallPatch(0.5f, 2.04f, 0.f)));
}

TEST(MergeCriterion, WidensTheMergeDistanceWithTheDepthNoiseAtRange) {
  Params noisy = exactParams();
  noisy.depth_noise_coefficient = 0.0019;  // 3 sigma at 4 m: 9.1 cm; at 2 m: 2.3 cm < 3 cm
  const MergeCriterion criterion = criterionFor(noisy);
  EXPECT_TRUE(mergeable(criterion, smallPatch(-0.5f, 4.f, 0.f), smallPatch(0.5f, 4.04f, 0.f)));
  EXPECT_FALSE(mergeable(criterion, smallPatch(-0.5f, 2.f, 0.f), smallPatch(0.5f, 2.04f, 0.f)));
  // Without the noise model, 4 cm at 4 m is as far apart as 4 cm at 2 m.
  EXPECT_FALSE(mergeable(criterionFor(exactParams()), smallPatch(-0.5f, 4.f, 0.f), smallPatch(0.5f, 4.04f, 0.f)));
}

TEST(MergeCriterion, RejectsABoardTwoCentimetresInFrontOfAWall) {
  // Eq. 9 alone would merge them (the board's centroid is 2 cm < 3 cm from the wall's
  // plane, same normal); the board does not fit the merged plane (RMS 2 cm > 5 mm).
  const MergeCriterion criterion = criterionFor(exactParams());
  const PlaneSums wall = patch(-1.f, 1.f, 3.f, 0.f, -1.f, 1.f);
  const PlaneSums board = patch(-0.2f, 0.2f, 2.98f, 0.f, -0.2f, 0.2f);
  EXPECT_FALSE(mergeable(criterion, wall, board));
  EXPECT_FALSE(mergeable(criterion, board, wall));
}

TEST(MergeCriterion, CostsMoreTheWorseThePartsFitOnePlane) {
  const MergeCriterion criterion = criterionFor(exactParams());
  double flat = -1.0, kinked = -1.0;
  ASSERT_TRUE(mergeable(criterion, patch(-0.1f, 0.f, 2.f), patch(0.f, 0.1f, 2.f), &flat));
  ASSERT_TRUE(mergeable(criterion, patch(-0.1f, 0.f, 2.f), patch(0.f, 0.1f, 2.f, 0.05f), &kinked));
  EXPECT_LT(flat, kinked);
  EXPECT_GT(kinked, 0.0);
  EXPECT_LE(kinked, 1.0);  // cost = worst mean square / tolerance^2
}

// --- PlaneMerger ----------------------------------------------------------------------------

// Merges with no border known between any two segments: Eq. 9 and the fit test alone.
void mergeWithoutBorders(PlaneMerger& merger, std::vector<PlaneSums>& sums, const MergeCriterion& criterion) {
  SegmentBorderMap borders;
  merger.merge(sums, criterion, borders);
}

// Segments 1..4: strips of the plane z = 2, 10 cm wide, side by side; 5 and 6: two more
// strips of the same plane far to the right, touching each other but nothing else.
std::vector<PlaneSums> coplanarStrips() {
  std::vector<PlaneSums> sums(7);
  for (int s = 1; s <= 4; ++s)
    sums[s] = patch(-0.2f + 0.1f * static_cast<float>(s - 1), -0.1f + 0.1f * static_cast<float>(s - 1), 2.f);
  sums[5] = patch(1.0f, 1.1f, 2.f);
  sums[6] = patch(1.1f, 1.2f, 2.f);
  return sums;
}

TEST(PlaneMerger, MergesAChainOfCoplanarSegmentsIntoOneCluster) {
  std::vector<PlaneSums> sums = coplanarStrips();
  PlaneMerger merger;
  merger.reset(5);
  sums.resize(5);
  merger.addEdge(1, 2);
  merger.addEdge(3, 2);  // either order
  merger.addEdge(3, 4);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.mergeCount(), 3u);
  const std::int32_t root = merger.root(1);
  for (std::int32_t s = 1; s <= 4; ++s) EXPECT_EQ(merger.root(s), root) << "segment " << s;
  // The root's sums became those of the whole cluster.
  EXPECT_DOUBLE_EQ(sums[root].count, 4.0 * 21 * 21);
}

TEST(PlaneMerger, KeepsCoplanarSegmentsWithoutAnEdgeApart) {
  // Two coplanar table tops that do not touch: 1-2 touch, 5-6 touch, nothing in between.
  std::vector<PlaneSums> sums = coplanarStrips();
  PlaneMerger merger;
  merger.reset(sums.size());
  merger.addEdge(1, 2);
  merger.addEdge(5, 6);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.mergeCount(), 2u);
  EXPECT_EQ(merger.root(1), merger.root(2));
  EXPECT_EQ(merger.root(5), merger.root(6));
  EXPECT_NE(merger.root(1), merger.root(5));
  EXPECT_EQ(merger.root(3), 3);  // no edges at all
  EXPECT_EQ(merger.root(4), 4);
}

TEST(PlaneMerger, RootDataMapsEverySegmentToItsFinalRoot) {
  std::vector<PlaneSums> sums = coplanarStrips();
  PlaneMerger merger;
  merger.reset(sums.size());
  merger.addEdge(1, 2);
  merger.addEdge(2, 3);
  merger.addEdge(5, 6);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  const std::int32_t* roots = merger.rootData();
  EXPECT_EQ(roots[0], 0);  // "no segment" stays itself
  for (std::int32_t s = 0; s < 7; ++s) {
    EXPECT_EQ(roots[s], merger.root(s)) << "segment " << s;
    EXPECT_EQ(roots[roots[s]], roots[s]) << "a root is its own root, segment " << s;
  }
  EXPECT_EQ(roots[1], roots[3]);
  EXPECT_EQ(roots[4], 4);
}

TEST(PlaneMerger, KeepsTheLargerSegmentAsRoot) {
  std::vector<PlaneSums> sums(3);
  sums[1] = patch(-0.1f, 0.f, 2.f);                       // 441 points
  sums[2] = patch(0.f, 0.3f, 2.f, 0.f, -0.1f, 0.1f);      // 441 points too...
  sums[2].merge(patch(0.f, 0.3f, 2.f, 0.f, 0.1f, 0.2f));  // ...and 441 more
  PlaneMerger merger;
  merger.reset(3);
  merger.addEdge(1, 2);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.root(1), 2);
  EXPECT_EQ(merger.root(2), 2);
  EXPECT_DOUBLE_EQ(sums[2].count, 3.0 * 441);
}

TEST(PlaneMerger, KeepsTheSmallerLabelAsRootBetweenEqualSizes) {
  std::vector<PlaneSums> sums(3);
  sums[1] = patch(0.f, 0.1f, 2.f);
  sums[2] = patch(-0.1f, 0.f, 2.f);
  PlaneMerger merger;
  merger.reset(3);
  merger.addEdge(2, 1);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.root(2), 1);
}

TEST(PlaneMerger, IgnoresSelfEdgesAndEdgesToNoSegment) {
  std::vector<PlaneSums> sums = coplanarStrips();
  PlaneMerger merger;
  merger.reset(sums.size());
  merger.addEdge(1, 1);
  merger.addEdge(0, 2);
  merger.addEdge(3, 0);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.mergeCount(), 0u);
  for (std::int32_t s = 0; s < 7; ++s) EXPECT_EQ(merger.root(s), s);
}

TEST(PlaneMerger, DoesNotMergeNeighboursThatFailTheCriterion) {
  std::vector<PlaneSums> sums(3);
  sums[1] = patch(-1.f, 1.f, 3.f, 0.f, -1.f, 1.f);        // wall
  sums[2] = patch(-0.2f, 0.2f, 2.98f, 0.f, -0.2f, 0.2f);  // board 2 cm in front
  PlaneMerger merger;
  merger.reset(3);
  merger.addEdge(1, 2);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.mergeCount(), 0u);
  EXPECT_NE(merger.root(1), merger.root(2));
}

// A bent strip: A (x in [-0.15, -0.05]) flat, B (next 10 cm) rising at `slope_b`, C (next
// 10 cm) at `slope_c`; continuous at the seams.
std::vector<PlaneSums> bentStrip(float slope_b, float slope_c) {
  std::vector<PlaneSums> sums(4);
  sums[1] = patch(-0.15f, -0.05f, 2.f, 0.f);
  sums[2] = patch(-0.05f, 0.05f, 2.f, slope_b);
  sums[3] = patch(0.05f, 0.15f, 2.f + 0.1f * slope_b, slope_c);
  return sums;
}

TEST(PlaneMerger, MergesTheMostSimilarPairFirst) {
  // Slopes 0, 0.085 and 0.14: A-B are 0.085 rad apart, B-C 0.055 rad; both pairs may merge,
  // B-C more tightly. Once B and C are one segment (slope ~0.11) A is too steep a step away
  // from it. Merging in label order instead (A-B first) would end with one cluster, since A+B
  // and C may merge: the order decides the result.
  const MergeCriterion criterion = criterionFor(exactParams());
  std::vector<PlaneSums> sums = bentStrip(0.085f, 0.14f);
  double cost_ab = -1.0, cost_bc = -1.0;
  ASSERT_TRUE(mergeable(criterion, sums[1], sums[2], &cost_ab));
  ASSERT_TRUE(mergeable(criterion, sums[2], sums[3], &cost_bc));
  ASSERT_LT(cost_bc, cost_ab) << "B-C must be the tighter pair for this scene";
  PlaneSums ab = sums[1], bc = sums[2];
  ab.merge(sums[2]);
  bc.merge(sums[3]);
  ASSERT_FALSE(mergeable(criterion, sums[1], bc)) << "A must not join B+C";
  ASSERT_TRUE(mergeable(criterion, ab, sums[3])) << "A+B may take C: label order merges all";

  PlaneMerger merger;
  merger.reset(4);
  merger.addEdge(1, 2);
  merger.addEdge(2, 3);
  mergeWithoutBorders(merger, sums, criterion);
  EXPECT_EQ(merger.mergeCount(), 1u);
  EXPECT_EQ(merger.root(1), 1);
  EXPECT_EQ(merger.root(2), 2);
  EXPECT_EQ(merger.root(3), 2);
}

TEST(PlaneMerger, MergesTheCheaperPairFirstWhateverTheLabels) {
  // The mirror image: now A-B is the tighter pair (0.055 rad) and B-C the looser (0.085).
  const MergeCriterion criterion = criterionFor(exactParams());
  std::vector<PlaneSums> sums = bentStrip(0.055f, 0.14f);
  double cost_ab = -1.0, cost_bc = -1.0;
  ASSERT_TRUE(mergeable(criterion, sums[1], sums[2], &cost_ab));
  ASSERT_TRUE(mergeable(criterion, sums[2], sums[3], &cost_bc));
  ASSERT_LT(cost_ab, cost_bc);
  PlaneMerger merger;
  merger.reset(4);
  merger.addEdge(2, 3);
  merger.addEdge(1, 2);
  mergeWithoutBorders(merger, sums, criterion);
  EXPECT_EQ(merger.root(2), 1);
}

TEST(PlaneMerger, CanBeResetAndRunAgain) {
  PlaneMerger merger;
  std::vector<PlaneSums> sums = coplanarStrips();
  merger.reset(sums.size());
  merger.addEdge(1, 2);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  ASSERT_EQ(merger.mergeCount(), 1u);
  sums = coplanarStrips();
  merger.reset(sums.size());
  merger.addEdge(3, 4);
  mergeWithoutBorders(merger, sums, criterionFor(exactParams()));
  EXPECT_EQ(merger.mergeCount(), 1u);
  EXPECT_EQ(merger.root(2), 2) << "the edge 1-2 of the last run is forgotten";
  EXPECT_EQ(merger.root(4), merger.root(3));
}

// --- One surface that bends: the continuity test at the border ------------------------------

// Tight fixed tolerances (sigma_plane 2 mm, sigma_plane-merge 3 mm, no noise): a surface that
// bends by a few millimetres over a metre fails Eq. 9 and the fit test.
Params tightParams() {
  Params params;
  params.distance_threshold = 0.002;
  params.merge_distance = 0.003;
  params.depth_noise_coefficient = 0.0;
  return params;
}

// The bent surface z = z0 + kBend x^2 (plus `step` where x > 0: a board's edge), sampled
// every centimetre over x in [x0, x1), y in [-0.2, 0.2].
constexpr float kBend = 0.04f;  // 1 cm over the 50 cm from the middle to either end
float bentDepth(float x, float step) { return 2.f + kBend * x * x + (x > 0.f ? step : 0.f); }
PlaneSums bentPart(float x0, float x1, float step = 0.f) {
  PlaneSums sums;
  for (float x = x0; x < x1 - 1e-4f; x += 0.01f)
    for (int j = 0; j <= 40; ++j) sums.add({x, -0.2f + 0.01f * static_cast<float>(j), bentDepth(x, step)});
  return sums;
}
// The border at x = `at` between the part left of it (low label) and the one right of it:
// the pixel pairs (at - 5 mm, at + 5 mm) along y.
SegmentBorder bentBorder(float at, float step = 0.f) {
  SegmentBorder border;
  for (int j = 0; j <= 40; ++j) {
    const float y = -0.2f + 0.01f * static_cast<float>(j);
    border.add({at - 0.005f, y, bentDepth(at - 0.005f, step)}, {at + 0.005f, y, bentDepth(at + 0.005f, step)});
  }
  return border;
}

bool continuous(const MergeCriterion& criterion, const PlaneSums& a, const PlaneSums& b, const SegmentBorder& border) {
  double cost = -1.0;
  const bool result = criterion.continuous(a.fit(), b.fit(), border, cost);
  if (result) {
    EXPECT_GT(cost, 1.0) << "a continuity merge costs more than any Eq. 9 merge";
  }
  return result;
}

TEST(MergeCriterion, JoinsTheHalvesOfABentSurfaceThatEquationNineRefuses) {
  const MergeCriterion criterion = criterionFor(tightParams());
  const PlaneSums left = bentPart(-0.5f, 0.f), right = bentPart(0.f, 0.5f);
  ASSERT_FALSE(mergeable(criterion, left, right)) << "the scene must be one Eq. 9 refuses";
  EXPECT_TRUE(continuous(criterion, left, right, bentBorder(0.f)));
}

TEST(MergeCriterion, KeepsASurfaceApartFromOneAStepBehindIt) {
  // The same halves, the right one 1 cm further away: a board's edge on a wall.
  const MergeCriterion criterion = criterionFor(tightParams());
  EXPECT_FALSE(continuous(criterion, bentPart(-0.5f, 0.f), bentPart(0.f, 0.5f, 0.01f), bentBorder(0.f, 0.01f)));
  // 1.5 mm is within sigma_plane (2 mm): one surface.
  EXPECT_TRUE(continuous(criterion, bentPart(-0.5f, 0.f), bentPart(0.f, 0.5f, 0.0015f), bentBorder(0.f, 0.0015f)));
}

TEST(MergeCriterion, KeepsACreaseApartWhereverItsBorderMeets) {
  // Two planes meeting without a step at an angle of 0.06 rad, above half the angular
  // threshold (0.05 rad): a crease, not a bend.
  const MergeCriterion criterion = criterionFor(tightParams());
  const PlaneSums flat = patch(-0.5f, 0.f, 2.f), tilted = patch(0.f, 0.5f, 2.f, 0.06f);
  SegmentBorder border;
  for (int j = 0; j <= 20; ++j) border.add({-0.005f, 0.f, 2.f}, {0.005f, 0.f, 2.f + 0.0003f});
  EXPECT_FALSE(continuous(criterion, flat, tilted, border));
  // At 0.04 rad the same border is a bend.
  EXPECT_TRUE(continuous(criterion, flat, patch(0.f, 0.5f, 2.f, 0.04f), border));
}

TEST(MergeCriterion, NeedsABorderOfSeveralPixelPairs) {
  const MergeCriterion criterion = criterionFor(tightParams());
  SegmentBorder corner;
  for (int j = 0; j < 7; ++j) corner.add({-0.005f, 0.f, 2.f}, {0.005f, 0.f, 2.f});
  EXPECT_FALSE(continuous(criterion, bentPart(-0.5f, 0.f), bentPart(0.f, 0.5f), corner));
  corner.add({-0.005f, 0.f, 2.f}, {0.005f, 0.f, 2.f});
  EXPECT_TRUE(continuous(criterion, bentPart(-0.5f, 0.f), bentPart(0.f, 0.5f), corner));
}

TEST(PlaneMerger, JoinsABentSurfaceAcrossItsBordersAndInheritsThemOnMerging) {
  // Three parts of the bent surface, left to right 1, 2, 3, borders 1-2 and 2-3 only. Whichever
  // pair merges first, the survivor must inherit the other border for the third part to join.
  const MergeCriterion criterion = criterionFor(tightParams());
  std::vector<PlaneSums> sums = {PlaneSums(), bentPart(-0.5f, -0.15f), bentPart(-0.15f, 0.15f), bentPart(0.15f, 0.5f)};
  const std::vector<PlaneSums> original = sums;
  PlaneMerger merger;
  merger.reset(4);
  merger.addEdge(1, 2);
  merger.addEdge(2, 3);
  mergeWithoutBorders(merger, sums, criterion);
  ASSERT_LT(merger.mergeCount(), 2u) << "the scene must be one Eq. 9 does not join whole";

  sums = original;
  SegmentBorderMap borders;
  borders[borderKey(1, 2)] = bentBorder(-0.15f);
  borders[borderKey(2, 3)] = bentBorder(0.15f);
  merger.reset(4);
  merger.addEdge(1, 2);
  merger.addEdge(2, 3);
  merger.merge(sums, criterion, borders);
  EXPECT_EQ(merger.mergeCount(), 2u);
  EXPECT_EQ(merger.root(1), merger.root(3));
  EXPECT_EQ(merger.root(2), merger.root(3));
  EXPECT_TRUE(borders.empty()) << "the borders inside the merged surface are gone";
}

TEST(PlaneMerger, KeepsABoardOnABentWallApartThroughItsBorder) {
  const MergeCriterion criterion = criterionFor(tightParams());
  std::vector<PlaneSums> sums = {PlaneSums(), bentPart(-0.5f, 0.f), bentPart(0.f, 0.5f, -0.02f)};
  SegmentBorderMap borders;
  borders[borderKey(1, 2)] = bentBorder(0.f, -0.02f);
  PlaneMerger merger;
  merger.reset(3);
  merger.addEdge(1, 2);
  merger.merge(sums, criterion, borders);
  EXPECT_EQ(merger.mergeCount(), 0u);
}

}  // namespace
}  // namespace floodplane
