// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "floodplane/segmenter.h"

/// \file
/// floodplane::PlaneTracker: plane ids that persist over the frames of a stream.

namespace floodplane {

/// One surface followed over frames. Its parameters are in the camera frame of the last frame
/// given to PlaneTracker::update: as measured when the surface is in that frame, and, when it
/// is not, as last measured, moved by the camera motions given since (or left as they were when
/// no motion was given).
struct PlaneTrack {
  std::uint32_t id = 0;            ///< 1, 2, ... in order of appearance; never reused before reset()
  std::size_t first_frame = 0;     ///< index of the frame it was first seen in (0 = the first update)
  std::size_t last_frame = 0;      ///< index of the frame it was last seen in
  std::size_t frames_seen = 0;     ///< frames it was seen in (not necessarily consecutive)
  int plane = -1;                  ///< its index in the last frame's planes; -1 when not seen in it
  std::uint32_t inlier_count = 0;  ///< pixels when last seen
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();           ///< n of n . P + d = 0, unit
  double offset = 0.0;                                         ///< d [m]
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();          ///< of its inliers when last seen [m]
  Eigen::Vector3d smoothed_normal = Eigen::Vector3d::UnitZ();  ///< exponentially smoothed n, unit
  double smoothed_offset = 0.0;                                ///< exponentially smoothed d [m]
  /// The plane as measured in the frame where the track had the most inliers (moved like the
  /// others), since the last frame given without a motion (which makes it the newest
  /// measurement): a reference a plane is also compared with, since a surface last seen as a
  /// sliver at the image's edge or at range may have been measured far off.
  std::uint32_t best_inlier_count = 0;
  Eigen::Vector3d best_normal = Eigen::Vector3d::UnitZ();   ///< n there, unit
  double best_offset = 0.0;                                 ///< d there [m]
  Eigen::Vector3d best_centroid = Eigen::Vector3d::Zero();  ///< centroid there [m]
};

/// Gives the planes of a stream of segmentations ids that persist over frames (PCL-free).
///
/// Feed it each frame's Segmentation in order, with the camera's motion since the previous
/// frame when it is known. Each plane of the frame is matched one-to-one to a track, by three
/// cues:
///  - the angle between the normals and how far apart the two planes are (the smallest of the
///    difference of their offsets and the distances from each one's centroid to the other's
///    plane: a sliver's normal a few degrees off moves its offset, a camera turn its centroid),
///    which must both be within Options' limits (a gate, not a preference). A track's plane
///    here is two measurements, its newest and its best (the frame where it had the most
///    inliers), and the closer of the two counts: a surface that shrank to a sliver at the
///    image's edge or receded to where Kinect noise is centimetres, and was fitted ever
///    further off as it went, comes back as its best view saw it. Only while the motions are
///    given: a frame without one makes the newest measurement the best;
///  - the pixel overlap of the plane with the track's pixels in the previous frame, as
///    intersection over union of the two label images, counted in one pass over them.
/// A pair's score is its overlap (0 when the track was not in the previous frame, or when the
/// overlap is not used, below) plus its parameter similarity
///   1 - (angle / max_normal_angle + separation / max_offset_difference) / 2
/// (with the second round's wider angle there),
/// both in [0, 1]; the pairs are taken greedily by falling score. Overlap weighs as much as the
/// whole parameter range because without a motion the camera's own movement shifts every
/// plane's offset (by up to the distance moved), and two parallel planes a few centimetres
/// apart then swap their offsets, not their pixels. Greedy rather than an optimal assignment:
/// after the gate almost every plane has one candidate; where it has more, the pair with the
/// most evidence is the one to trust, whereas maximising the sum of scores may give it up for
/// two doubtful pairs; and it is deterministic (ties go to the older track, then the larger
/// plane) and costs O(n^2 log n) for n planes.
///
/// With a motion, the tracks' parameters are first moved into the current camera frame, so the
/// gate and the parameter similarity compare like with like however far the camera moved. The
/// previous label image cannot be moved without depths and the camera's intrinsics, so it is
/// compared as it is when the motion is small (rotation at most overlap_max_rotation and
/// translation at most overlap_max_translation) and not at all when it is larger, or when the
/// image size changed: the match then rests on the parameters alone.
///
/// Planes that match no track start new tracks. A track not matched stays (lost) for up to
/// max_lost_frames frames and can be matched again, by its parameters only, in any of them: a
/// surface that leaves the view and returns within that many frames gets its id back. A
/// returning surface shows first as a sliver at the image's edge whose fitted normal can be
/// 0.1-0.2 rad off, so a second round gives the planes still unmatched to tracks lost before
/// the previous frame within twice max_normal_angle. Since
/// a track is matched by its plane's parameters, a surface coplanar with a lost one (within the
/// gate) may take its id; two planes of one frame never share one.
///
/// The planes' centroids (PlaneFit::centroid) must lie on them, as every fit's does: the
/// planes' distance is measured there too.
///
/// Cost per frame: a copy of the label image and one pass over it and the previous one
/// (counting runs of equal label pairs, not pixels one by one), plus O(tracks x planes).
/// Not thread-safe; one tracker per stream.
class PlaneTracker {
 public:
  /// The tracker's matching limits and smoothing; setOptions() validates them.
  struct Options {
    /// Largest angle between a track's normal and a plane's normal for them to match [rad].
    /// Covers the fit's noise and, without motions, the camera's turn between two frames.
    /// A track lost before the previous frame may take a plane no other track matched within
    /// twice this angle (a returning surface's first sliver).
    double max_normal_angle = 0.15;
    /// Largest distance between a track's plane and a frame's plane for them to match [m]:
    /// the smallest of the difference of their offsets and the distances from each one's
    /// centroid to the other's plane. Covers the fit's noise and, without motions, the camera's movement between two
    /// frames (walking speed at 30 Hz is 5 cm).
    double max_offset_difference = 0.08;
    /// How many consecutive frames a track may go unseen and still be matched again (K).
    int max_lost_frames = 30;
    /// Weight of the newest measurement in the smoothed parameters, in (0, 1]; 1 is no
    /// smoothing. The smoothed normal is renormalised after each step.
    double smoothing = 0.3;
    /// Largest rotation [rad] of a given motion for which the previous label image is still
    /// compared with the current one pixel by pixel.
    double overlap_max_rotation = 0.05;
    /// Largest translation [m] of a given motion for the same.
    double overlap_max_translation = 0.1;
  };

  /// A tracker with the default Options.
  PlaneTracker();
  /// A tracker with these options; throws std::invalid_argument naming a bad one.
  /// \param options the matching limits and smoothing
  explicit PlaneTracker(const Options& options);

  /// Validates and sets the options; throws std::invalid_argument naming the option. Takes
  /// effect from the next update; the tracks are kept.
  /// \param options the matching limits and smoothing
  void setOptions(const Options& options);
  /// \return the options in use (setOptions())
  const Options& options() const { return options_; }

  /// Takes the next frame. Returns the track id of each of its planes (planes[k] has ids[k];
  /// ids are >= 1), valid until the next call. Throws std::invalid_argument when the labels do
  /// not fill width x height or name a plane the segmentation does not have.
  /// \param segmentation the next frame's result (Segmenter::segment)
  /// \return the track id of each plane, in the order of Segmentation::planes
  const std::vector<std::uint32_t>& update(const Segmentation& segmentation);
  /// The same, with the camera's motion since the previous frame: the pose of the current
  /// camera in the previous camera's frame (T_previous_current, as odometry gives it), so that
  /// a point P in the current camera's frame is motion * P in the previous one. Ignored for
  /// the first frame. Throws std::invalid_argument when the motion is not finite and rigid.
  /// \param segmentation the next frame's result (Segmenter::segment)
  /// \param motion       T_previous_current, rigid [m]
  /// \return the track id of each plane, in the order of Segmentation::planes
  const std::vector<std::uint32_t>& update(const Segmentation& segmentation, const Eigen::Isometry3d& motion);
  /// The same, with the motion as a 4 x 4 homogeneous matrix (last row 0 0 0 1).
  /// \param segmentation the next frame's result (Segmenter::segment)
  /// \param motion       T_previous_current, 4 x 4 rigid [m]
  /// \return the track id of each plane, in the order of Segmentation::planes
  const std::vector<std::uint32_t>& update(const Segmentation& segmentation, const Eigen::Matrix4d& motion);

  /// Track ids of the last frame's planes, as update returned them.
  /// \return the track id of each plane of the last frame
  const std::vector<std::uint32_t>& trackIds() const { return plane_track_ids_; }
  /// Writes the last frame's label image with track ids in place of plane labels (0 stays
  /// 0). `labels` is that frame's Segmentation::labels; `track_labels` may be the same vector.
  /// Throws std::invalid_argument on a label above the last frame's plane count.
  /// \param labels            the last frame's label image (Segmentation::labels)
  /// \param[out] track_labels the same image with track ids
  void relabel(const std::vector<std::uint32_t>& labels, std::vector<std::uint32_t>& track_labels) const;

  /// The tracks seen in the last frame and the lost ones still kept, by increasing id.
  /// \return every track kept
  const std::vector<PlaneTrack>& tracks() const { return tracks_; }
  /// The track with this id, or nullptr when there is none (never was, or dropped). Valid until
  /// the next update or reset.
  /// \param id a track id (PlaneTrack::id)
  /// \return the track, or nullptr
  const PlaneTrack* track(std::uint32_t id) const;
  /// Frames taken since construction or reset(); the last frame's index is frameCount() - 1.
  /// \return the number of update() calls since construction or reset()
  std::size_t frameCount() const { return frame_count_; }

  /// Forgets every track and the previous frame; ids start again at 1. Keeps the options.
  void reset();

 private:
  const std::vector<std::uint32_t>& associate(const Segmentation& segmentation, const Eigen::Isometry3d* motion);

  Options options_;
  std::vector<PlaneTrack> tracks_;
  std::vector<std::uint32_t> plane_track_ids_;
  std::size_t frame_count_ = 0;
  std::uint32_t next_id_ = 1;
  // The last frame's labels, compared with the next frame's (its track ids: plane_track_ids_).
  int previous_width_ = 0;
  int previous_height_ = 0;
  std::vector<std::uint32_t> previous_labels_;
};

}  // namespace floodplane
