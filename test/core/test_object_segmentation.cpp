// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// segmentObjects and its steps on small grids made by hand: a table 2 m ahead of a pinhole
// camera looking straight at it (test/support/pinhole_grid.h) with boxes, a ridge, a valley
// and a curved body on it, and plane labels given by hand (not by the segmenter), so that each
// rule is tested alone: the supports, the clearance above them, depth steps, LCCP's convexity.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <vector>

#include "floodplane/object_segmentation.h"
#include "objects/convex_joining.h"
#include "objects/support_planes.h"
#include "objects/surface_patches.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

using test::PinholeGrid;

constexpr int kWidth = 80;
constexpr int kHeight = 60;
constexpr double kTable = 2.0;  // the table's depth [m]; a pixel is 2 cm wide on it

// A scene: depth per pixel and the plane label per pixel (0: no plane).
struct Scene {
  std::function<double(int, int)> depth;
  std::function<std::uint32_t(int, int)> plane;
};

// The least-squares fit of the points labelled `label`.
PlaneFit fitOf(const PinholeGrid& grid, const std::vector<std::uint32_t>& labels, std::uint32_t label) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d squares = Eigen::Matrix3d::Zero();
  double count = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != label) continue;
    const float* p = &grid.data[i * grid.stride];
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    sum += point;
    squares += point * point.transpose();
    count += 1;
  }
  PlaneFit fit;
  if (count < 3) return fit;
  fit.centroid = sum / count;
  fit.covariance = squares / count - fit.centroid * fit.centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(fit.covariance);
  fit.eigenvalues = solver.eigenvalues();
  fit.normal = solver.eigenvectors().col(0);
  if (fit.normal.dot(fit.centroid) > 0) fit.normal = -fit.normal;
  fit.offset = -fit.normal.dot(fit.centroid);
  fit.valid = true;
  return fit;
}

// The grid of `scene` and its segmentation by hand: the planes numbered as labelled, with a
// Kinect-like noise model.
struct Made {
  PinholeGrid grid;
  Segmentation planes;
};

Made make(const Scene& scene) {
  Made made{PinholeGrid(kWidth, kHeight, scene.depth), Segmentation()};
  Segmentation& s = made.planes;
  s.width = kWidth;
  s.height = kHeight;
  s.labels.resize(made.grid.data.size() / 3);
  std::uint32_t largest = 0;
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      s.labels[made.grid.index(u, v)] = scene.plane(u, v);
      largest = std::max(largest, scene.plane(u, v));
    }
  }
  for (std::uint32_t k = 1; k <= largest; ++k) {
    SegmentedPlane plane;
    plane.fit = fitOf(made.grid, s.labels, k);
    plane.inlier_count = static_cast<std::uint32_t>(std::count(s.labels.begin(), s.labels.end(), k));
    s.planes.push_back(plane);
  }
  s.noise.sigma_constant = 0.0005;
  s.noise.sigma_quadratic = 0.0015;
  return made;
}

bool inBox(int u, int v, int u0, int v0, int u1, int v1) { return u >= u0 && u < u1 && v >= v0 && v < v1; }

// The object ids found over a box of pixels (0 included when some are on none).
std::set<std::uint32_t> idsIn(const ObjectSegmentation& objects, int u0, int v0, int u1, int v1) {
  std::set<std::uint32_t> ids;
  for (int v = v0; v < v1; ++v) {
    for (int u = u0; u < u1; ++u) ids.insert(objects.labels[static_cast<std::size_t>(v) * kWidth + u]);
  }
  return ids;
}

TEST(ObjectSegmentation, BoxOnTableIsOneObjectAndTheTableNone) {
  // Table: plane 1. A box 20 cm high whose top (plane 2) covers pixels 30..49 x 20..39.
  const Made made = make({[](int u, int v) { return inBox(u, v, 30, 20, 50, 40) ? kTable - 0.2 : kTable; },
                          [](int u, int v) { return inBox(u, v, 30, 20, 50, 40) ? 2u : 1u; }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(objects.supports, std::vector<std::uint32_t>{1});
  EXPECT_EQ(idsIn(objects, 30, 20, 50, 40), std::set<std::uint32_t>{1});
  std::size_t labelled = 0;
  for (std::uint32_t id : objects.labels) labelled += id != 0;
  EXPECT_EQ(labelled, 400u);  // the box's pixels and no table pixel
  const SegmentedObject& box = objects.objects[0];
  EXPECT_EQ(box.id, 1u);
  EXPECT_EQ(box.pixel_count, 400u);
  EXPECT_EQ(box.support, 1u);
  EXPECT_NEAR(box.centroid.z(), kTable - 0.2, 1e-6);
  EXPECT_NEAR(box.min.z(), kTable - 0.2, 1e-6);
  EXPECT_NEAR(box.max.x() - box.min.x(), 19 * (kTable - 0.2) / test::kPinholeFocal, 1e-5);
}

TEST(ObjectSegmentation, PointsOnNoPlaneNearTheTableAreNoObject) {
  // The table's own points left out of its plane (a ring on no plane, 2 mm off it: noise)
  // stay out of objects: they are within the clearance.
  const Made made = make({[](int u, int v) { return inBox(u, v, 10, 10, 70, 50) ? kTable - 0.002 : kTable; },
                          [](int u, int v) { return inBox(u, v, 10, 10, 70, 50) ? 0u : 1u; }});
  // The table's fit then comes from the border alone, still the plane z = 2.
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  EXPECT_TRUE(objects.objects.empty());
  EXPECT_EQ(objects.supports, std::vector<std::uint32_t>{1});
}

TEST(ObjectSegmentation, APlaneSeenInTwoPartsIsTwoObjects) {
  // A box's top (plane 2) cut in two by a post 30 cm nearer before it (plane 3): as the image
  // shows them, three objects, though both parts of the top are one plane.
  const Made made = make({[](int u, int v) {
                            if (inBox(u, v, 38, 10, 42, 50)) return kTable - 0.5;
                            return inBox(u, v, 30, 20, 50, 40) ? kTable - 0.2 : kTable;
                          },
                          [](int u, int v) {
                            if (inBox(u, v, 38, 10, 42, 50)) return 3u;
                            return inBox(u, v, 30, 20, 50, 40) ? 2u : 1u;
                          }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 3u);
  const std::set<std::uint32_t> left = idsIn(objects, 30, 20, 38, 40);
  const std::set<std::uint32_t> right = idsIn(objects, 42, 20, 50, 40);
  const std::set<std::uint32_t> post = idsIn(objects, 38, 10, 42, 50);
  ASSERT_EQ(left.size(), 1u);
  ASSERT_EQ(right.size(), 1u);
  ASSERT_EQ(post.size(), 1u);
  EXPECT_EQ((std::set<std::uint32_t>{*left.begin(), *right.begin(), *post.begin()}),
            (std::set<std::uint32_t>{1, 2, 3}));
}

TEST(ObjectSegmentation, DepthStepSplitsTwoTouchingBoxes) {
  // Two boxes side by side, touching in the image, tops 30 and 10 cm high: a 20 cm step.
  const Made made = make({[](int u, int v) {
                            if (inBox(u, v, 20, 20, 40, 40)) return kTable - 0.3;
                            if (inBox(u, v, 40, 20, 60, 40)) return kTable - 0.1;
                            return kTable;
                          },
                          [](int u, int v) {
                            if (inBox(u, v, 20, 20, 40, 40)) return 2u;
                            if (inBox(u, v, 40, 20, 60, 40)) return 3u;
                            return 1u;
                          }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 2u);
  const std::set<std::uint32_t> left = idsIn(objects, 20, 20, 40, 40);
  const std::set<std::uint32_t> right = idsIn(objects, 40, 20, 60, 40);
  ASSERT_EQ(left.size(), 1u);
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NE(*left.begin(), *right.begin());
  EXPECT_NE(*left.begin(), 0u);
  EXPECT_NE(*right.begin(), 0u);
}

// A roof (the ridge towards the camera: convex) or a valley (concave) over pixels 20..59 x
// 22..37 (each face 30 x 27 cm: no support), its two faces planes 2 and 3, 5 mm of depth per pixel from the middle
// column (normals about 37 degrees apart).
Scene ridge(bool convex) {
  return {[convex](int u, int v) {
            if (!inBox(u, v, 20, 22, 60, 38)) return kTable;
            const double away = std::abs(u - 39.5);
            return convex ? 1.6 + 0.005 * away : 1.8 - 0.005 * away;
          },
          [](int u, int v) {
            if (!inBox(u, v, 20, 22, 60, 38)) return 1u;
            return u < 40 ? 2u : 3u;
          }};
}

TEST(ObjectSegmentation, ConvexRidgeIsOneObject) {
  const Made made = make(ridge(true));
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(idsIn(objects, 20, 22, 60, 38), std::set<std::uint32_t>{1});
}

TEST(ObjectSegmentation, ConcaveValleySplitsIntoTwo) {
  const Made made = make(ridge(false));
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 2u);
  const std::set<std::uint32_t> left = idsIn(objects, 20, 22, 40, 38);
  const std::set<std::uint32_t> right = idsIn(objects, 40, 22, 60, 38);
  ASSERT_EQ(left.size(), 1u);
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NE(*left.begin(), *right.begin());
}

// The ridge and the valley with two columns beside their crease on no plane (as the segmenter
// leaves a crease), within one square: a strip too narrow for a normal of its own, across
// which the faces are judged.
Scene creasedRidge(bool convex) {
  Scene scene = ridge(convex);
  const auto plane = scene.plane;
  scene.plane = [plane](int u, int v) {
    return (u == 38 || u == 39) && inBox(u, v, 20, 22, 60, 38) ? 0u : plane(u, v);
  };
  return scene;
}

TEST(ObjectSegmentation, FacesJoinAcrossAStripOnNoPlaneWhenConvex) {
  const Made convex = make(creasedRidge(true));
  const ObjectSegmentation one = segmentObjects(convex.grid.grid(), convex.planes);
  ASSERT_EQ(one.objects.size(), 1u);
  EXPECT_EQ(idsIn(one, 20, 22, 60, 38), std::set<std::uint32_t>{1});
  const Made concave = make(creasedRidge(false));
  const ObjectSegmentation two = segmentObjects(concave.grid.grid(), concave.planes);
  ASSERT_EQ(two.objects.size(), 2u);
  EXPECT_EQ(idsIn(two, 20, 22, 38, 38).size(), 1u);
  EXPECT_EQ(idsIn(two, 40, 22, 60, 38).size(), 1u);
  EXPECT_NE(*idsIn(two, 20, 22, 38, 38).begin(), *idsIn(two, 40, 22, 60, 38).begin());
}

TEST(ObjectSegmentation, CurvedBodyOnNoPlaneIsOneObject) {
  // A lying cylinder of 20 cm radius whose axis runs along v, on no plane: the small local
  // patches over it all meet convexly.
  const auto depth = [](int u, int v) {
    if (!inBox(u, v, 25, 10, 55, 50)) return kTable;
    const double x = (u - 39.5) * 0.014;  // metres across the axis
    return 1.9 - std::sqrt(std::max(0.0, 0.04 - x * x));
  };
  const Made made = make({depth, [](int u, int v) { return inBox(u, v, 25, 10, 55, 50) ? 0u : 1u; }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(idsIn(objects, 25, 10, 55, 50), std::set<std::uint32_t>{1});
  EXPECT_EQ(objects.objects[0].pixel_count, 30u * 40u);
}

TEST(ObjectSegmentation, SmallFringesAreDropped) {
  ObjectOptions options;
  options.min_object_pixels = 50;
  // A box of 7 x 7 pixels (49) is below the limit, one of 8 x 8 (64) is not.
  const Made made = make(
      {[](int u, int v) { return inBox(u, v, 10, 10, 17, 17) || inBox(u, v, 50, 30, 58, 38) ? kTable - 0.1 : kTable; },
       [](int u, int v) { return inBox(u, v, 10, 10, 17, 17) || inBox(u, v, 50, 30, 58, 38) ? 0u : 1u; }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes, options);
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(objects.objects[0].pixel_count, 64u);
  EXPECT_EQ(idsIn(objects, 10, 10, 17, 17), std::set<std::uint32_t>{0});
}

TEST(ObjectSegmentation, LargestObjectFirst) {
  const Made made = make(
      {[](int u, int v) { return inBox(u, v, 5, 5, 15, 15) || inBox(u, v, 40, 20, 60, 40) ? kTable - 0.1 : kTable; },
       [](int u, int v) {
         if (inBox(u, v, 5, 5, 15, 15)) return 3u;
         if (inBox(u, v, 40, 20, 60, 40)) return 2u;
         return 1u;
       }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 2u);
  EXPECT_EQ(objects.objects[0].pixel_count, 400u);
  EXPECT_EQ(objects.objects[1].pixel_count, 100u);
  EXPECT_EQ(idsIn(objects, 40, 20, 60, 40), std::set<std::uint32_t>{1});
  EXPECT_EQ(idsIn(objects, 5, 5, 15, 15), std::set<std::uint32_t>{2});
}

TEST(ObjectSegmentation, BuffersKeptBetweenCallsCarryNothingOver) {
  // segmentObjects keeps its buffers per thread: a frame segmented after a busier one (more
  // object points, patches and contacts) and then the busier one again give what they give
  // alone.
  const Made busy = make(
      {[](int u, int v) { return inBox(u, v, 5, 5, 15, 15) || inBox(u, v, 40, 20, 60, 40) ? kTable - 0.1 : kTable; },
       [](int u, int v) { return inBox(u, v, 5, 5, 15, 15)     ? 0u
                                 : inBox(u, v, 40, 20, 60, 40) ? 2u
                                                               : 1u; }});
  const Made quiet = make({[](int u, int v) { return inBox(u, v, 30, 20, 50, 40) ? kTable - 0.2 : kTable; },
                           [](int u, int v) { return inBox(u, v, 30, 20, 50, 40) ? 2u : 1u; }});
  const ObjectSegmentation first = segmentObjects(busy.grid.grid(), busy.planes);
  const ObjectSegmentation second = segmentObjects(quiet.grid.grid(), quiet.planes);
  const ObjectSegmentation again = segmentObjects(busy.grid.grid(), busy.planes);
  ASSERT_EQ(first.objects.size(), 2u);
  ASSERT_EQ(second.objects.size(), 1u);
  EXPECT_EQ(second.objects[0].pixel_count, 400u);
  EXPECT_EQ(idsIn(second, 30, 20, 50, 40), std::set<std::uint32_t>{1});
  EXPECT_EQ(again.labels, first.labels);
  ASSERT_EQ(again.objects.size(), first.objects.size());
  for (std::size_t k = 0; k < first.objects.size(); ++k) {
    EXPECT_EQ(again.objects[k].pixel_count, first.objects[k].pixel_count);
    EXPECT_EQ(again.objects[k].centroid, first.objects[k].centroid);
    EXPECT_EQ(again.objects[k].support, first.objects[k].support);
  }
}

TEST(ObjectSegmentation, NoSupportMeansEverySurfaceIsAnObject) {
  // A small board (40 x 30 cm at 2 m: 0.12 m^2, below the support area) alone: no support,
  // so it is an object of its own standing on nothing.
  const Made made = make(
      {[](int u, int v) { return inBox(u, v, 30, 20, 50, 35) ? kTable : std::numeric_limits<double>::quiet_NaN(); },
       [](int u, int v) { return inBox(u, v, 30, 20, 50, 35) ? 1u : 0u; }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  EXPECT_TRUE(objects.supports.empty());
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(objects.objects[0].support, 0u);
  EXPECT_EQ(objects.objects[0].pixel_count, 300u);
}

TEST(ObjectSegmentation, TablePiecesInItsPlaneAreSupportsToo) {
  // The table cut by a box into plane 1 (the left part) and plane 3 (a strip on the right):
  // the strip is in the table's plane, so no object.
  const Made made = make({[](int u, int v) { return inBox(u, v, 30, 20, 50, 40) ? kTable - 0.2 : kTable; },
                          [](int u, int v) {
                            if (inBox(u, v, 30, 20, 50, 40)) return 2u;
                            return u >= 70 ? 3u : 1u;
                          }});
  const ObjectSegmentation objects = segmentObjects(made.grid.grid(), made.planes);
  ASSERT_EQ(objects.objects.size(), 1u);
  EXPECT_EQ(objects.objects[0].pixel_count, 400u);
  EXPECT_EQ(idsIn(objects, 70, 0, 80, 60), std::set<std::uint32_t>{0});
}

TEST(ObjectSegmentation, RejectsBadOptionsAndSizes) {
  const Made made = make(ridge(true));
  ObjectOptions bad;
  bad.concavity_tolerance_rad = 2.0;
  EXPECT_THROW(segmentObjects(made.grid.grid(), made.planes, bad), std::invalid_argument);
  bad = ObjectOptions();
  bad.support_clearance_m = std::nan("");
  EXPECT_THROW(segmentObjects(made.grid.grid(), made.planes, bad), std::invalid_argument);
  bad = ObjectOptions();
  bad.local_patch_pixels = 0;
  EXPECT_THROW(segmentObjects(made.grid.grid(), made.planes, bad), std::invalid_argument);
  Segmentation wrong = made.planes;
  wrong.width = kWidth - 1;
  EXPECT_THROW(segmentObjects(made.grid.grid(), wrong), std::invalid_argument);
}

TEST(ConvexJoining, LccpTestTellsConvexFromConcave) {
  // A box's edge seen from above: its top (normal up, towards the camera at +y) and its front.
  SurfacePatch top;
  top.centroid = Eigen::Vector3d(-1, 0, 0);
  top.normal = Eigen::Vector3d(0, 1, 0);
  SurfacePatch front;
  front.centroid = Eigen::Vector3d(0, -1, 0);
  front.normal = Eigen::Vector3d(1, 0, 0);
  EXPECT_TRUE(convexContact(top, front, 0.17));
  EXPECT_TRUE(convexContact(front, top, 0.17));
  // The table beside a box's side: a concave crease.
  SurfacePatch table;
  table.centroid = Eigen::Vector3d(1, 0, 0);
  table.normal = Eigen::Vector3d(0, 1, 0);
  SurfacePatch side;
  side.centroid = Eigen::Vector3d(0, 1, 0);
  side.normal = Eigen::Vector3d(1, 0, 0);
  EXPECT_FALSE(convexContact(table, side, 0.17));
  // Nearly parallel normals join whatever the line between them (noise on a flat surface).
  SurfacePatch tilted = side;
  tilted.normal = Eigen::Vector3d(1, 0.1, 0).normalized();
  tilted.centroid = Eigen::Vector3d(0, 0, 1);
  EXPECT_TRUE(convexContact(side, tilted, 0.17));
  // Below their angle, the line decides: here it bends concavely.
  EXPECT_FALSE(convexContact(side, tilted, 0.05));
  // No normal: never convex.
  EXPECT_FALSE(convexContact(SurfacePatch(), top, 0.17));
}

TEST(SupportPlanes, LargePlanesAndTheirPiecesSupport) {
  std::vector<SegmentedPlane> planes(3);
  // A table 1 x 0.8 m (its rectangle's eigenvalues l^2 / 12) facing the camera at z = 2.
  for (SegmentedPlane& p : planes) {
    p.fit.valid = true;
    p.fit.normal = Eigen::Vector3d(0, 0, -1);
  }
  planes[0].fit.centroid = Eigen::Vector3d(0, 0, 2);
  planes[0].fit.eigenvalues = Eigen::Vector3d(0, 0.64 / 12, 1.0 / 12);
  // A box top 20 x 20 cm 10 cm above it: neither large nor in its plane.
  planes[1].fit.centroid = Eigen::Vector3d(0, 0, 1.9);
  planes[1].fit.eigenvalues = Eigen::Vector3d(0, 0.04 / 12, 0.04 / 12);
  // A strip of the table 1 cm off its plane (the fit's error): a piece of it.
  planes[2].fit.centroid = Eigen::Vector3d(0.6, 0, 2.01);
  planes[2].fit.eigenvalues = Eigen::Vector3d(0, 0.0001, 0.04 / 12);
  const Supports supports = findSupports(planes, ObjectOptions());
  ASSERT_EQ(supports.surfaces.size(), 1u);
  EXPECT_EQ(supports.surfaces[0].label, 1u);
  EXPECT_NEAR(coveredArea(planes[0].fit), 0.8, 1e-9);
  EXPECT_EQ(supports.is_support, (std::vector<bool>{false, true, false, true}));
  EXPECT_NEAR(supports.surfaces[0].height(Eigen::Vector3d(0, 0, 1.9)), 0.1, 1e-12);
}

TEST(SurfacePatches, PlanesAndSquaresWithTheirContacts) {
  // A flat 16 x 8 pixel patch of points on no plane, at 1 m: two 8 x 8 squares, touching
  // over 8 pixel pairs; then a step of 10 cm splits the right square from its neighbours.
  PinholeGrid flat(16, 8, [](int, int) { return 1.0; });
  std::vector<std::uint32_t> labels(16 * 8, 0);
  ObjectPoints candidate;
  for (std::size_t i = 0; i < 16 * 8; ++i) candidate.add(flat.grid(), i);
  SurfaceStep step;
  step.noise.sigma_constant = 0.001;
  step.pitch = angularPitch(flat.grid());
  EXPECT_NEAR(step.pitch, 1.0 / test::kPinholeFocal, 1e-4);
  SurfacePatches patches;
  buildSurfacePatches(flat.grid(), labels, candidate, step, 8, patches);
  ASSERT_EQ(patches.patches.size(), 2u);
  ASSERT_EQ(patches.contacts.size(), 1u);
  EXPECT_EQ(patches.contacts[0].pairs, 8u);
  EXPECT_NEAR(patches.patches[0].normal.z(), -1.0, 1e-6);
  PinholeGrid stepped(16, 8, [](int u, int) { return u >= 8 ? 1.1 : 1.0; });
  buildSurfacePatches(stepped.grid(), labels, candidate, step, 8, patches);
  EXPECT_EQ(patches.patches.size(), 2u);
  EXPECT_TRUE(patches.contacts.empty());
  // A plane over both squares: still a patch per square, each with the plane's normal.
  std::vector<std::uint32_t> one_plane(16 * 8, 4);
  buildSurfacePatches(flat.grid(), one_plane, candidate, step, 8, patches);
  ASSERT_EQ(patches.patches.size(), 2u);
  EXPECT_EQ(patches.patches[0].plane, 4u);
  EXPECT_EQ(patches.patches[1].pixels, 64u);
  EXPECT_NEAR(patches.patches[1].normal.z(), -1.0, 1e-6);
}

}  // namespace
}  // namespace floodplane
