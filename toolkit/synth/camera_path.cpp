// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/camera_path.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "synth/random_source.h"
#include "synth/surface_distance.h"

namespace floodplane::synth {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint64_t kPathStream = 3;  // the room and blocks scenes of a seed draw from 1 and 2
constexpr double kReachStep = 0.1;        // metres between the points tried along the way ahead
constexpr double kWanderTime = 1.5;       // seconds over which the wandering yaw rate reverts
constexpr double kWanderRate = 12.0;      // degrees a second: the wandering rate's spread
// The glances' own stream: drawing them leaves the walk's draws, and so the walk, as they were.
constexpr std::uint64_t kLookAwayStream = 4;

double radians(double degrees) { return degrees * kPi / 180.0; }

// `value` moved towards `target` by at most `most`.
double approach(double value, double target, double most) { return value + std::clamp(target - value, -most, most); }

void checkSettings(int frames, const WalkSettings& settings) {
  const auto positive = [](double value) { return value > 0.0 && std::isfinite(value); };
  if (frames < 1) throw std::invalid_argument("walkingCameraPath: frames must be at least 1");
  if (!positive(settings.frame_rate) || !positive(settings.min_speed) || !(settings.max_speed >= settings.min_speed) ||
      !positive(settings.max_speed) || !positive(settings.acceleration) || !positive(settings.max_yaw_rate) ||
      !positive(settings.max_yaw_acceleration) || !(settings.pitch_amplitude >= 0.0) ||
      !positive(settings.min_clearance) || !positive(settings.look_ahead) ||
      !(settings.max_distance_from_start > 0.0) || !(settings.max_turn > 0.0) || !(settings.up.norm() > 0.0)) {
    throw std::invalid_argument(
        "walkingCameraPath: rates, speeds, clearance, look-ahead, leash and turn must be positive, max_speed at "
        "least min_speed, pitch_amplitude not negative, up not zero");
  }
  const LookAwaySettings& look_away = settings.look_away;
  if (look_away.enabled &&
      !(positive(look_away.min_angle) && look_away.max_angle >= look_away.min_angle && look_away.max_angle < 180.0 &&
        positive(look_away.turn_rate) && look_away.min_hold >= 0.0 && look_away.max_hold >= look_away.min_hold &&
        std::isfinite(look_away.max_hold) && positive(look_away.min_interval) &&
        look_away.max_interval >= look_away.min_interval && std::isfinite(look_away.max_interval))) {
    throw std::invalid_argument(
        "walkingCameraPath: look-away angles must be above 0 and below 180 degrees, its turn rate and intervals "
        "positive, its holds not negative, each maximum at least its minimum");
  }
}

// Per frame, the yaw (radians about up) by which the camera looks away from its walking
// direction: glances as LookAwaySettings describes, 0 between them and at frame 0. Empty when
// looking away is off.
std::vector<double> lookAwayYaws(int frames, std::uint64_t seed, const WalkSettings& settings) {
  const LookAwaySettings& look_away = settings.look_away;
  if (!look_away.enabled) return {};
  std::vector<double> yaws(static_cast<std::size_t>(frames), 0.0);
  const auto set = [&](int frame, double yaw) {
    if (frame < frames) yaws[static_cast<std::size_t>(frame)] = yaw;
  };
  // Frame counts past the sequence's end are cut there (and so cannot overflow).
  const auto frameCount = [&](double count) { return static_cast<int>(std::round(std::min(count, frames + 1.0))); };
  RandomSource random(seed, kLookAwayStream);
  const double step = radians(look_away.turn_rate) / settings.frame_rate;  // a frame's turn
  // The last frame looking ahead.
  int frame = 0;
  while (frame < frames) {
    frame +=
        std::max(1, frameCount(random.uniform(look_away.min_interval, look_away.max_interval) * settings.frame_rate));
    const double angle = radians(random.uniform(look_away.min_angle, look_away.max_angle));
    const double side = random.chance(0.5) ? 1.0 : -1.0;
    const int hold = frameCount(random.uniform(look_away.min_hold, look_away.max_hold) * settings.frame_rate);
    const int turning = frameCount(std::ceil(angle / step));
    // Away: the last step stops at the angle; held; back: ends with the frame looking ahead.
    for (int k = 1; k <= turning; ++k) set(frame + k, side * std::min(angle, k * step));
    for (int k = 1; k <= hold; ++k) set(frame + turning + k, side * angle);
    frame = std::min(frame + turning + hold, frames);
    for (double yaw = angle - step; yaw > 0.0 && frame < frames; yaw -= step) set(++frame, side * yaw);
    ++frame;
  }
  return yaws;
}

class Walker {
 public:
  Walker(const Scene& scene, const WalkSettings& settings)
      : scene_(scene), settings_(settings), up_(settings.up.normalized()), start_(scene.world_from_camera) {
    const Eigen::Vector3d forward = start_.linear().col(2);
    forward_ = forward - forward.dot(up_) * up_;
    if (forward_.norm() < 1e-6) {
      throw SceneError(scene.source + ": the camera looks along the vertical, so it has no heading to walk in");
    }
    forward_.normalize();
    if (!canBeAt(start_.translation())) {
      throw SceneError(scene.source + ": the camera is inside a solid or nearer than " +
                       std::to_string(settings.min_clearance) + " m to a surface, so it cannot walk");
    }
  }

  // Whether the camera centre may be at `point`.
  bool canBeAt(const Eigen::Vector3d& point) const {
    return (point - start_.translation()).norm() <= settings_.max_distance_from_start &&
           !insideAnySolid(scene_, point) && nearestSurfaceDistance(scene_, point) >= settings_.min_clearance;
  }

  // The horizontal walking direction at heading `yaw` (radians about up from the start's).
  Eigen::Vector3d heading(double yaw) const { return Eigen::AngleAxisd(yaw, up_) * forward_; }

  // The free way from `position` at heading `yaw`, up to look_ahead, in kReachStep steps.
  double reach(const Eigen::Vector3d& position, double yaw) const {
    const Eigen::Vector3d direction = heading(yaw);
    const int steps = static_cast<int>(std::floor(settings_.look_ahead / kReachStep));
    for (int step = 1; step <= steps; ++step) {
      if (!canBeAt(position + step * kReachStep * direction)) return (step - 1) * kReachStep;
    }
    return steps * kReachStep;
  }

  Eigen::Isometry3d pose(const Eigen::Vector3d& position, double yaw, double pitch) const {
    Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
    world_from_camera.linear() = Eigen::AngleAxisd(yaw, up_).toRotationMatrix() * start_.linear() *
                                 Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitX()).toRotationMatrix();
    world_from_camera.translation() = position;
    return world_from_camera;
  }

 private:
  const Scene& scene_;
  const WalkSettings& settings_;
  Eigen::Vector3d up_;
  Eigen::Isometry3d start_;
  Eigen::Vector3d forward_;
};

}  // namespace

std::vector<Eigen::Isometry3d> walkingCameraPath(const Scene& scene, int frames, std::uint64_t seed,
                                                 const WalkSettings& settings) {
  checkSettings(frames, settings);
  const Walker walker(scene, settings);
  RandomSource random(seed, kPathStream);
  const double dt = 1.0 / settings.frame_rate;
  const double cruise = random.uniform(settings.min_speed, settings.max_speed);
  const double pitch_period = random.uniform(4.0, 8.0);  // seconds
  const double pitch_sign = random.chance(0.5) ? 1.0 : -1.0;
  const double max_rate = radians(settings.max_yaw_rate);
  const double max_turn = radians(settings.max_turn);
  const double pitch_amplitude = radians(settings.pitch_amplitude);
  const std::vector<double> look_away_yaws = lookAwayYaws(frames, seed, settings);
  // A sine from 0, so pose 0 is the scene's own.
  const auto pitch = [&](int frame) {
    return pitch_sign * pitch_amplitude * std::sin(2.0 * kPi * frame * dt / pitch_period);
  };

  Eigen::Vector3d position = scene.world_from_camera.translation();
  double yaw = 0.0;
  double yaw_rate = 0.0;
  double wander_rate = 0.0;
  double speed = 0.0;
  int turn_side = 0;  // +1 turning about +up, -1 about -up, while the way ahead is blocked
  std::vector<Eigen::Isometry3d> poses{scene.world_from_camera};
  for (int frame = 1; frame < frames; ++frame) {
    // The wandering rate: an Ornstein-Uhlenbeck process with spread kWanderRate.
    wander_rate +=
        -wander_rate * dt / kWanderTime + radians(kWanderRate) * std::sqrt(2.0 * dt / kWanderTime) * random.gaussian();
    wander_rate = std::clamp(wander_rate, -max_rate, max_rate);
    const double ahead = walker.reach(position, yaw);
    double target_rate = wander_rate;
    if (ahead < settings.look_ahead) {
      if (turn_side == 0) {
        turn_side = walker.reach(position, yaw + kPi / 4) >= walker.reach(position, yaw - kPi / 4) ? 1 : -1;
        if (std::abs(yaw) > max_turn / 2) turn_side = yaw > 0 ? -1 : 1;
      }
      if (std::abs(yaw) > max_turn) turn_side = yaw > 0 ? -1 : 1;
      target_rate = turn_side * max_rate;
    } else {
      turn_side = 0;
      if (std::abs(yaw) > max_turn) target_rate = yaw > 0 ? -max_rate / 2 : max_rate / 2;
    }
    // Slow enough to stop within the free way (at 80 % of the braking the walker has).
    const double target_speed =
        std::min(cruise, std::sqrt(2.0 * 0.8 * settings.acceleration * std::max(0.0, ahead - kReachStep)));
    yaw_rate = approach(yaw_rate, target_rate, radians(settings.max_yaw_acceleration) * dt);
    speed = approach(speed, target_speed, settings.acceleration * dt);
    yaw += yaw_rate * dt;
    const Eigen::Vector3d next = position + speed * dt * walker.heading(yaw);
    if (walker.canBeAt(next)) {
      position = next;
    } else {
      speed = 0.0;
    }
    // Without glances the yaw as it is (not + 0.0, which would turn a -0.0 into +0.0 in the poses).
    const double view_yaw = look_away_yaws.empty() ? yaw : yaw + look_away_yaws[static_cast<std::size_t>(frame)];
    poses.push_back(walker.pose(position, view_yaw, pitch(frame)));
  }
  return poses;
}

std::string cameraPathJson(const std::string& scene_name, const std::vector<Eigen::Isometry3d>& poses,
                           double frame_rate, const LookAwaySettings& look_away) {
  using nlohmann::ordered_json;  // keeps keys in the order written, for human readers
  ordered_json document;
  document["scene"] = scene_name;
  document["frames"] = poses.size();
  document["frame_rate"] = frame_rate;
  if (look_away.enabled) {  // absent when off, so that the files of a plain walk stay as they were
    document["look_away"] = {{"angle_degrees", {look_away.min_angle, look_away.max_angle}},
                             {"turn_rate_degrees_per_second", look_away.turn_rate},
                             {"hold_seconds", {look_away.min_hold, look_away.max_hold}},
                             {"interval_seconds", {look_away.min_interval, look_away.max_interval}}};
  }
  document["convention"] =
      "world_from_camera maps a point from frame k's camera frame (its PCD's: x right, y down, z forward, "
      "metres) to the world frame of the scene (z up): p_world = R p_camera + t, the matrix [R t; 0 0 0 1] given "
      "row by row. The motion from frame k-1 to frame k, in frame k-1's camera frame, is "
      "inverse(world_from_camera[k-1]) * world_from_camera[k].";
  ordered_json frames = ordered_json::array();
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Matrix4d matrix = poses[k].matrix();
    ordered_json rows = ordered_json::array();
    for (int row = 0; row < 4; ++row) {
      rows.push_back({matrix(row, 0), matrix(row, 1), matrix(row, 2), matrix(row, 3)});
    }
    frames.push_back({{"frame", k}, {"time", static_cast<double>(k) / frame_rate}, {"world_from_camera", rows}});
  }
  document["poses"] = std::move(frames);
  // A scene named after a file whose name is not UTF-8: replaced as floodplane/io/json_text.h says.
  return document.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace floodplane::synth
