// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The walking camera of pcd_synth --sequence: one pose per frame starting at the scene's own,
// steps of a walking pace and turns of a walking person's rate, clearance from every surface
// kept in random rooms, the leash and turn limit of scene files, determinism, the errors; the
// glances of looking away (away by the angle and back in time, the walk unchanged, nothing
// changed while off, surfaces leaving the view and returning); and one ground-truth id per
// surface over a sequence (SequenceSurfaces), checked by following the pixels of each frame
// into the next.

#include "synth/camera_path.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "synth/renderer.h"
#include "synth/room_walk.h"
#include "synth/scene_generator.h"
#include "synth/sequence_labels.h"
#include "synth/surface_distance.h"

namespace {

using namespace floodplane::synth;

// The frames of `scene` seen from each of `poses`, exact sensor, each added to `surfaces`.
std::vector<RenderedFrame> renderAlong(const Scene& scene, const std::vector<Eigen::Isometry3d>& poses,
                                       SequenceSurfaces& surfaces) {
  std::vector<RenderedFrame> frames;
  for (const Eigen::Isometry3d& pose : poses) {
    Scene view = scene;
    view.world_from_camera = pose;
    frames.push_back(renderScene(view, RenderSettings{}));
    surfaces.add(frames.back());
  }
  return frames;
}

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

WalkSettings lookingAway() {
  WalkSettings settings;
  settings.look_away.enabled = true;
  return settings;
}

// The yaw (degrees, in (-180, 180]) by which `pose` looks away from `walking`, the same frame's
// pose of the walk without glances.
double lookAwayYaw(const Eigen::Isometry3d& pose, const Eigen::Isometry3d& walking) {
  double yaw = headingOf(pose) - headingOf(walking);
  if (yaw > 180.0) yaw -= 360.0;
  if (yaw <= -180.0) yaw += 360.0;
  return yaw;
}

TEST(CameraPath, LookingAwayTurnsByTheAngleAndBackInTimeAndWalksTheSameWalk) {
  const WalkSettings settings = lookingAway();
  const LookAwaySettings& look_away = settings.look_away;
  const Scene scene = openFloor();
  const std::vector<Eigen::Isometry3d> walking = walkingCameraPath(scene, 600, 7);
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 600, 7, settings);
  ASSERT_EQ(poses.size(), walking.size());
  EXPECT_TRUE(poses[0].isApprox(scene.world_from_camera, 1e-12));
  // At 180 deg/s and 30 Hz, 6 degrees a frame: out and back, each at most ceil(90 / 6) frames,
  // and a hold of at most 0.3 s.
  const double step = look_away.turn_rate / settings.frame_rate;
  const auto longest_glance =
      static_cast<int>(2 * std::ceil(look_away.max_angle / step) + std::ceil(look_away.max_hold * settings.frame_rate));
  int glances = 0;
  int glance_frames = 0;  // of the glance under way
  double widest = 0.0;    // its widest yaw, degrees
  double previous = 0.0;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    EXPECT_TRUE(poses[k].translation() == walking[k].translation()) << "frame " << k;
    const double yaw = lookAwayYaw(poses[k], walking[k]);
    EXPECT_LE(std::abs(yaw - previous), step + 1e-9) << "frame " << k;
    EXPECT_LE(std::abs(yaw), look_away.max_angle + 1e-9) << "frame " << k;
    previous = yaw;
    if (std::abs(yaw) > 1e-9) {
      ++glance_frames;
      widest = std::max(widest, std::abs(yaw));
      continue;
    }
    if (glance_frames == 0) continue;
    // A glance just ended: it reached its angle and came back in time.
    ++glances;
    EXPECT_GE(widest, look_away.min_angle - 1e-9) << "glance ending at frame " << k;
    EXPECT_LE(glance_frames, longest_glance) << "glance ending at frame " << k;
    glance_frames = 0;
    widest = 0.0;
  }
  // A glance at most every 2.5 s + 39 frames: at least 4 in 20 s.
  EXPECT_GE(glances, 4);
}

TEST(CameraPath, WhileOffLookingAwayChangesNothingAndWhenOnItsSettingsAreChecked) {
  const Scene scene = generateRoomScene(3);
  WalkSettings off;
  off.look_away.min_angle = 10.0;
  off.look_away.max_angle = 500.0;  // out of range, but off
  const std::vector<Eigen::Isometry3d> plain = walkingCameraPath(scene, 200, 3);
  const std::vector<Eigen::Isometry3d> still_plain = walkingCameraPath(scene, 200, 3, off);
  const std::vector<Eigen::Isometry3d> glancing = walkingCameraPath(scene, 200, 3, lookingAway());
  bool turned_away = false;
  for (std::size_t k = 0; k < plain.size(); ++k) {
    EXPECT_TRUE(plain[k].matrix() == still_plain[k].matrix()) << "frame " << k;
    // In a room too the walk is the same: clearance is the camera centre's.
    EXPECT_TRUE(plain[k].translation() == glancing[k].translation()) << "frame " << k;
    turned_away = turned_away || std::abs(lookAwayYaw(glancing[k], plain[k])) >= 60.0 - 1e-9;
  }
  EXPECT_TRUE(turned_away);
  // The poses file lists the glances only when they are on.
  EXPECT_EQ(cameraPathJson("room", plain, 30.0).find("look_away"), std::string::npos);
  EXPECT_NE(cameraPathJson("room", glancing, 30.0, lookingAway().look_away).find("\"look_away\""), std::string::npos);
  WalkSettings bad = lookingAway();
  bad.look_away.max_angle = 200.0;
  EXPECT_THROW(walkingCameraPath(scene, 10, 1, bad), std::invalid_argument);
  bad = lookingAway();
  bad.look_away.min_interval = 0.0;
  EXPECT_THROW(walkingCameraPath(scene, 10, 1, bad), std::invalid_argument);
}

// What looking away is for: planes in view leave it and come back within plane tracking's
// 30-frame memory. Counts, per ground-truth surface of at least 1 % of the frame, its returns
// after 1-29 absent frames over 5 s of a random room.
TEST(CameraPath, WhenLookingAwaySurfacesLeaveTheViewAndComeBackWithinThirtyFrames) {
  const auto re_entries = [](const WalkSettings& settings) {
    Scene scene = generateRoomScene(11);
    scene.intrinsics = scene.intrinsics.scaledTo(80, 60);
    const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 150, 11, settings);
    SequenceSurfaces surfaces;
    std::vector<RenderedFrame> frames = renderAlong(scene, poses, surfaces);
    std::map<std::uint32_t, int> absent;  // surface seen before -> frames absent since
    int returned = 0;
    for (RenderedFrame& frame : frames) {
      surfaces.relabel(frame);
      std::map<std::uint32_t, std::size_t> pixels;
      for (const std::uint32_t label : frame.labels) pixels[label] += label != 0 ? 1 : 0;
      for (auto& [surface, frames_absent] : absent) ++frames_absent;
      for (const auto& [surface, count] : pixels) {
        if (surface == 0 || count < frame.labels.size() / 100) continue;
        const auto seen = absent.find(surface);
        if (seen != absent.end() && seen->second >= 2 && seen->second <= 30) ++returned;
        absent[surface] = 0;
      }
    }
    return returned;
  };
  const int plain = re_entries(WalkSettings());
  const int glancing = re_entries(lookingAway());
  // 12 against 4 when written.
  EXPECT_GE(glancing, 6) << "plain walk: " << plain;
  EXPECT_GE(glancing, 2 * plain);
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
  SequenceSurfaces surfaces;
  std::vector<RenderedFrame> frames = renderAlong(scene, poses, surfaces);
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

// renderRoomWalk is pcd_synth --sequence's walk in memory: frame k is the room seen from the
// walk's pose k with noise seed sequenceFrameSeed(seed, k), frame 0 with the seed itself.
TEST(RoomWalk, RendersTheWalksPosesWithAnotherNoiseSeedEachFrame) {
  EXPECT_EQ(sequenceFrameSeed(7, 0), 7u);
  EXPECT_NE(sequenceFrameSeed(7, 1), sequenceFrameSeed(7, 2));
  const std::vector<RenderedFrame> walk = renderRoomWalk(5, 3, SensorModel::kinect);
  ASSERT_EQ(walk.size(), 3u);
  const Scene scene = generateRoomScene(5);
  const std::vector<Eigen::Isometry3d> poses = walkingCameraPath(scene, 3, 5);
  for (int k : {0, 2}) {
    Scene view = scene;
    view.world_from_camera = poses[static_cast<std::size_t>(k)];
    RenderSettings settings;
    settings.sensor = SensorModel::kinect;
    settings.seed = sequenceFrameSeed(5, k);
    const RenderedFrame expected = renderScene(view, settings);
    ASSERT_EQ(walk[static_cast<std::size_t>(k)].points.size(), expected.points.size());
    EXPECT_EQ(walk[static_cast<std::size_t>(k)].labels, expected.labels) << k;
    EXPECT_TRUE(std::equal(expected.points.begin(), expected.points.end(),
                           walk[static_cast<std::size_t>(k)].points.begin(),
                           [](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
                             return a.cwiseEqual(b).all() || (a.array().isNaN().all() && b.array().isNaN().all());
                           }))
        << k;
  }
  EXPECT_NE(walk[0].labels, walk[2].labels) << "the camera moved";
}

}  // namespace
