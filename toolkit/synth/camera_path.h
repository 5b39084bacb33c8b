// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A camera carried through a scene: the poses of a hand-held depth camera walking at a
// person's pace, turning smoothly, nodding a little, never nearer than a clearance to any
// surface. Ground truth for plane tracking (pcd_synth --sequence).
//
// Motion: the camera walks along its own viewing direction projected onto the horizontal
// (the plane normal to `up`), at a cruise speed drawn per path, and turns about `up`. Its yaw
// rate wanders smoothly (a mean-reverting random process, limited to max_yaw_rate and changing
// by at most max_yaw_acceleration); when the way ahead is blocked within look_ahead, it turns at
// the full rate towards the freer side and slows down so that it could stop in the free way
// left, down to turning in place. A step that would bring a surface nearer than min_clearance
// (or leave the leash) is not taken. As every position keeps min_clearance and steps are far
// shorter, the camera never passes through a surface: it stays in the room it starts in. It
// pitches about its own x axis by up to pitch_amplitude (a slow sine), and keeps its roll.
//
// Looking away (LookAwaySettings, off by default): like a head on a walking body, the camera
// now and then turns about `up` away from the way it walks, holds, and turns back, so that
// surfaces leave the view for a moment and come back: the re-entries of plane tracking. Only the
// camera's orientation changes; the positions are those of the same walk without it.

#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "synth/scene.h"

namespace floodplane::synth {

/// Glances away from the walking direction. Each glance, after looking ahead for an interval,
/// turns by an angle to a random side at turn_rate, holds, and turns back at the same rate;
/// interval, angle, side and hold are drawn per glance. At the defaults and 30 Hz a glance turns
/// 60-90 degrees and is over in 22-38 frames, so a small surface in the middle of a Kinect's
/// 63-degree wide view is out of it for about 13-29 frames: within plane tracking's 30-frame
/// memory. The draws have a random stream of their own: the walk is the same with
/// and without glances.
struct LookAwaySettings {
  bool enabled = false;
  double min_angle = 60.0;    ///< degrees a glance turns away, drawn from [min_angle, max_angle]
  double max_angle = 90.0;    ///< below 180
  double turn_rate = 180.0;   ///< degrees a second, away and back: a brisk head turn
  double min_hold = 0.1;      ///< seconds held turned away, drawn from [min_hold, max_hold]
  double max_hold = 0.3;      ///<
  double min_interval = 1.0;  ///< seconds looking ahead before each glance, from [min_interval, max_interval]
  double max_interval = 2.5;  ///<
};

struct WalkSettings {
  double frame_rate = 30.0;            ///< poses a second (Hz)
  double min_speed = 1.0;              ///< the cruise speed is drawn from [min_speed, max_speed] (m/s)
  double max_speed = 1.4;              ///<
  double acceleration = 1.0;           ///< the most the speed changes, m/s^2
  double max_yaw_rate = 30.0;          ///< degrees a second, about `up`
  double max_yaw_acceleration = 90.0;  ///< degrees a second squared
  double pitch_amplitude = 4.0;        ///< degrees up and down about the starting pitch
  double min_clearance = 0.5;          ///< no surface nearer to the camera centre (metres)
  double look_ahead = 2.0;             ///< metres of free way wanted ahead; less makes it turn
  /// The camera stays within this distance of its start (metres): a leash for scenes without
  /// walls. Infinity: no leash.
  double max_distance_from_start = std::numeric_limits<double>::infinity();
  /// The heading stays within about this many degrees of the starting one (turning back
  /// towards it beyond): for scenes that are only seen from one side. Infinity: free turning.
  double max_turn = std::numeric_limits<double>::infinity();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  ///< the world's vertical
  LookAwaySettings look_away;                     ///< off by default
};

/// `frames` camera poses (world from camera, the convention of Scene::world_from_camera), one
/// every 1 / frame_rate seconds; pose 0 is scene.world_from_camera. The same scene, seed and
/// settings give the same poses. Throws std::invalid_argument for frames < 1 or settings out of
/// range, SceneError when the starting pose is inside a solid, nearer than min_clearance to a
/// surface or looks along `up`.
std::vector<Eigen::Isometry3d> walkingCameraPath(const Scene& scene, int frames, std::uint64_t seed,
                                                 const WalkSettings& settings = WalkSettings());

/// The poses as JSON for the files of a sequence: the scene, frame rate, the look-away settings
/// when enabled, the convention and per frame its index, time (s) and world_from_camera as 4
/// rows of 4 numbers.
std::string cameraPathJson(const std::string& scene_name, const std::vector<Eigen::Isometry3d>& poses,
                           double frame_rate, const LookAwaySettings& look_away = LookAwaySettings());

}  // namespace floodplane::synth
