// The walking camera of pcd_synth --sequence: one pose per frame starting at the scene's own,
// steps of a walking pace and turns of a walking person's rate, clearance from every surface
// kept in random rooms, the leash and turn limit of scene files, determinism, the errors; and
// one ground-truth id per surface over a sequence (SequenceSurfaces), checked by following the
// pixels of each frame into the next.

#include "synth/camera_path.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "synth/renderer.h"
#include "synth/scene_generator.h"
#include "synth/sequence_labels.h"
#include "synth/surface_distance.h"

namespace {

using namespace floodplane::synth;

constexpr double kPi = 3.14159265358979323846;

double degrees(double radians) { return radians * 180.0 / kPi; }

// A floor of 40 x 40 m and nothing else, the camera 1.5 m above its middle looking along +x
// and 20 degrees down: nothing in the way.
Scene openFloor() {
  Scene scene;
  scene.name = "open_floor";
  scene.source = "open floor";
  scene.primitives.push_back({"floor", Rectangle{Eigen::Vector3d::Zero(), {40, 0, 0}, {0, 40, 0}}, 1.0});
  scene.world_from_camera = lookAt({0, 0, 1.5}, {1, 0, 1.5 - std::tan(20 * kPi / 180)}, Eigen::Vector3d::UnitZ());
  return scene;
}

// The heading (degrees, about +z) of a pose's viewing direction.
double headingOf(const Eigen::Isometry3d& pose) {
  const Eigen::Vector3d forward = pose.linear().col(2);
  return degrees(std::atan2(forward.y(), forward.x()));
}

double rotationBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return degrees(Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle());
}

TEST(CameraPath, PoseZeroIsTheScenesCameraAndThereIsOnePosePerFrame) {
  const Scene scene = openFloor();
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 50, 1);
  ASSERT_EQ(poses.size(), 50U);
  EXPECT_TRUE(poses[0].isApprox(scene.world_from_camera, 1e-12));
  EXPECT_EQ(walkingCameraPath(scene, 1, 1).size(), 1U);
}

TEST(CameraPath, OnOpenGroundTheCameraWalksAtWalkingPaceAndTurnsSmoothly) {
  const WalkSettings settings;
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(openFloor(), 300, 7);
  double longest = 0.0;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const double step = (poses[k].translation() - poses[k - 1].translation()).norm();
    longest = std::max(longest, step);
    EXPECT_LE(step, settings.max_speed / settings.frame_rate + 1e-12) << "frame " << k;
    // 30 deg/s of yaw at 30 Hz, and a little nodding.
    EXPECT_LE(rotationBetween(poses[k - 1], poses[k]), 1.2) << "frame " << k;
    EXPECT_NEAR(poses[k].translation().z(), 1.5, 1e-12) << "walks on the level";
  }
  // Up to walking speed (1 m/s^2 from standing), then 1.0-1.4 m a second: frames 30-299 are 9 s.
  EXPECT_GE(longest, settings.min_speed / settings.frame_rate - 1e-12);
  double walked = 0.0;
  for (std::size_t k = 31; k < poses.size(); ++k)
    walked += (poses[k].translation() - poses[k - 1].translation()).norm();
  EXPECT_GT(walked, 8.0);
  EXPECT_LT(walked, 1.4 * 9.0);
}

TEST(CameraPath, InRandomRoomsTheCameraKeepsItsClearanceAndStillWalks) {
  const WalkSettings settings;
  for (const std::uint64_t seed : {1, 2, 3, 4}) {
    const Scene scene = generateRoomScene(seed);
    const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 300, seed);
    double walked = 0.0;
    double turned = 0.0;
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const Eigen::Vector3d position = poses[k].translation();
      EXPECT_GE(nearestSurfaceDistance(scene, position), settings.min_clearance) << "seed " << seed << " frame " << k;
      EXPECT_FALSE(insideAnySolid(scene, position)) << "seed " << seed << " frame " << k;
      if (k == 0) continue;
      const double step = (position - poses[k - 1].translation()).norm();
      EXPECT_LE(step, settings.max_speed / settings.frame_rate + 1e-12);
      EXPECT_LE(rotationBetween(poses[k - 1], poses[k]), 1.2);
      walked += step;
      turned += rotationBetween(poses[k - 1], poses[k]);
    }
    EXPECT_GT(walked, 1.0) << "seed " << seed;
    EXPECT_GT(turned, 10.0) << "seed " << seed;
  }
}

TEST(CameraPath, TheSameSeedGivesTheSamePathAndAnotherSeedAnother) {
  const Scene scene = generateRoomScene(5);
  const std::vector<Eigen::Isometry3d> first = walkingCameraPath(scene, 120, 5);
  const std::vector<Eigen::Isometry3d> again = walkingCameraPath(scene, 120, 5);
  const std::vector<Eigen::Isometry3d> other = walkingCameraPath(scene, 120, 6);
  for (std::size_t k = 0; k < first.size(); ++k) {
    EXPECT_TRUE(first[k].matrix() == again[k].matrix()) << "frame " << k;
  }
  EXPECT_FALSE(first.back().matrix() == other.back().matrix());
}

TEST(CameraPath, TheLeashAndTheTurnLimitHold) {
  WalkSettings settings;
  settings.max_distance_from_start = 0.5;
  settings.max_turn = 25.0;
  const Scene scene = openFloor();
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 600, 3, settings);
  const double start_heading = headingOf(poses[0]);
  double farthest = 0.0;
  for (const Eigen::Isometry3d& pose : poses) {
    farthest = std::max(farthest, (pose.translation() - poses[0].translation()).norm());
    // The turn back starts at the limit, so the heading overshoots it by a few degrees.
    EXPECT_LE(std::abs(headingOf(pose) - start_heading), 25.0 + 10.0);
  }
  EXPECT_LE(farthest, 0.5 + 1e-12);
  EXPECT_GT(farthest, 0.3);
}

TEST(CameraPath, BadFrameCountsSettingsAndStartsAreRejected) {
  const Scene scene = openFloor();
  EXPECT_THROW(walkingCameraPath(scene, 0, 1), std::invalid_argument);
  WalkSettings settings;
  settings.max_speed = 0.5;  // below min_speed
  EXPECT_THROW(walkingCameraPath(scene, 10, 1, settings), std::invalid_argument);
  Scene low = scene;
  low.world_from_camera.translation().z() = 0.2;  // nearer than 0.5 m to the floor
  EXPECT_THROW(walkingCameraPath(low, 10, 1), SceneError);
  Scene down = scene;
  down.world_from_camera = lookAt({0, 0, 1.5}, {0, 0, 0}, Eigen::Vector3d::UnitX());
  EXPECT_THROW(walkingCameraPath(down, 10, 1), SceneError);
}

// Three planes; in `merged` plane 3's pixels carry 2 (touching and coplanar in that view).
RenderedFrame handMadeFrame(bool merged) {
  RenderedFrame frame;
  for (std::uint32_t id = 1; id <= 3; ++id) {
    GroundTruthPlane plane;
    plane.id = id;
    plane.pixel_count = 2;
    frame.planes.push_back(plane);
  }
  frame.labels = {1, 1, 2, 2, 3, 3, 0};
  if (merged) {
    frame.planes[2].merged_into = 2;
    frame.planes[1].pixel_count = 4;
    frame.planes[2].pixel_count = 0;
    frame.labels = {1, 1, 2, 2, 2, 2, 0};
  }
  return frame;
}

TEST(SequenceSurfaces, AFaceMergedInAnyFrameCarriesItsGroupsIdInEvery) {
  SequenceSurfaces surfaces;
  RenderedFrame apart = handMadeFrame(false);
  surfaces.add(apart);
  EXPECT_FALSE(surfaces.changes(apart));
  const RenderedFrame merged = handMadeFrame(true);
  surfaces.add(merged);
  EXPECT_FALSE(surfaces.changes(merged));
  EXPECT_TRUE(surfaces.changes(apart));
  surfaces.relabel(apart);
  EXPECT_EQ(apart.labels, merged.labels);
  EXPECT_EQ(apart.planes[2].merged_into, 2U);
  EXPECT_EQ(apart.planes[1].pixel_count, 4U);
  EXPECT_EQ(apart.planes[2].pixel_count, 0U);
  EXPECT_FALSE(surfaces.changes(apart));
  RenderedFrame other_scene;
  other_scene.planes.resize(5);
  EXPECT_THROW(surfaces.relabel(other_scene), std::invalid_argument);
}

// Whether a pixel of the 3 x 3 around (u, v) has another label than (u, v): a point near an
// edge between planes may land a pixel off.
bool atEdge(const RenderedFrame& frame, long u, long v) {
  const long width = frame.intrinsics.width;
  const long height = frame.intrinsics.height;
  const std::uint32_t label = frame.labels[static_cast<std::size_t>(v * width + u)];
  for (long y = std::max(0L, v - 1); y <= std::min(height - 1, v + 1); ++y) {
    for (long x = std::max(0L, u - 1); x <= std::min(width - 1, u + 1); ++x) {
      if (frame.labels[static_cast<std::size_t>(y * width + x)] != label) return true;
    }
  }
  return false;
}

// Every labelled point of frame k, carried into frame k + 1 by the two poses, lands on a pixel
// of the same label wherever frame k + 1 sees that same point (its depth there agrees within
// 2 mm) away from the edges between planes.
TEST(SequenceSurfaces, TheSameSurfaceKeepsItsIdAlongAWalk) {
  Scene scene = generateRoomScene(11);
  scene.intrinsics = scene.intrinsics.scaledTo(160, 120);
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 60, 11);
  std::vector<RenderedFrame> frames;
  SequenceSurfaces surfaces;
  for (const Eigen::Isometry3d& pose : poses) {
    Scene view = scene;
    view.world_from_camera = pose;
    frames.push_back(renderScene(view, RenderSettings{}));
    surfaces.add(frames.back());
  }
  for (RenderedFrame& frame : frames) surfaces.relabel(frame);
  const CameraIntrinsics& camera = scene.intrinsics;
  std::size_t compared = 0;
  std::size_t same = 0;
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    const Eigen::Isometry3d next_from_this = poses[k + 1].inverse() * poses[k];
    for (std::size_t i = 0; i < frames[k].labels.size(); ++i) {
      if (frames[k].labels[i] == 0) continue;
      const Eigen::Vector3d point = next_from_this * Eigen::Vector3d(frames[k].points[i].cast<double>());
      if (point.z() <= 0.0) continue;
      const long u = std::lround(camera.fx * point.x() / point.z() + camera.cx);
      const long v = std::lround(camera.fy * point.y() / point.z() + camera.cy);
      if (u < 0 || v < 0 || u >= camera.width || v >= camera.height) continue;
      const auto j = static_cast<std::size_t>(v * camera.width + u);
      if (frames[k + 1].labels[j] == 0 || std::abs(frames[k + 1].points[j].z() - point.z()) > 0.002) continue;
      if (atEdge(frames[k + 1], u, v)) continue;
      ++compared;
      same += frames[k + 1].labels[j] == frames[k].labels[i] ? 1 : 0;
    }
  }
  ASSERT_GT(compared, 59U * 3000U);  // of 19200 pixels a frame
  EXPECT_GE(static_cast<double>(same), 0.999 * static_cast<double>(compared)) << same << " of " << compared;
}

}  // namespace
