// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/plane_tracker.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace floodplane {

namespace {

std::string problem(const PlaneTracker::Options& options) {
  const auto number = [](double value) { return std::to_string(value); };
  if (!(std::isfinite(options.max_normal_angle) && options.max_normal_angle > 0.0 && options.max_normal_angle <= M_PI))
    return "max_normal_angle must be in (0, pi] radians, got " + number(options.max_normal_angle);
  if (!(std::isfinite(options.max_offset_difference) && options.max_offset_difference > 0.0))
    return "max_offset_difference must be a finite number of metres > 0, got " + number(options.max_offset_difference);
  if (options.max_lost_frames < 0)
    return "max_lost_frames must be >= 0, got " + std::to_string(options.max_lost_frames);
  if (!(options.smoothing > 0.0 && options.smoothing <= 1.0))
    return "smoothing must be in (0, 1], got " + number(options.smoothing);
  if (!(std::isfinite(options.overlap_max_rotation) && options.overlap_max_rotation >= 0.0))
    return "overlap_max_rotation must be a finite number of radians >= 0, got " + number(options.overlap_max_rotation);
  if (!(std::isfinite(options.overlap_max_translation) && options.overlap_max_translation >= 0.0))
    return "overlap_max_translation must be a finite number of metres >= 0, got " +
           number(options.overlap_max_translation);
  return {};
}

bool isRigid(const Eigen::Matrix4d& motion) {
  if (!motion.allFinite() || motion.row(3) != Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0)) return false;
  const Eigen::Matrix3d rotation = motion.topLeftCorner<3, 3>();
  return (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
         rotation.determinant() > 0.0;
}

// A plane n . P + d = 0 in the previous camera's frame, where P_previous = R P_current + t, is
// n . (R P_current + t) + d = 0, i.e. (R^T n) . P_current + (n . t + d) = 0 in the current one.
void moveIntoCurrentFrame(PlaneTrack& track, const Eigen::Isometry3d& motion) {
  const Eigen::Matrix3d rotation = motion.linear();
  const Eigen::Vector3d translation = motion.translation();
  track.offset += track.normal.dot(translation);
  track.normal = rotation.transpose() * track.normal;
  track.smoothed_offset += track.smoothed_normal.dot(translation);
  track.smoothed_normal = rotation.transpose() * track.smoothed_normal;
  track.centroid = motion.inverse() * track.centroid;
  track.best_offset += track.best_normal.dot(translation);
  track.best_normal = rotation.transpose() * track.best_normal;
  track.best_centroid = motion.inverse() * track.best_centroid;
}

void forgetBest(PlaneTrack& track) {
  track.best_inlier_count = track.inlier_count;
  track.best_normal = track.normal;
  track.best_offset = track.offset;
  track.best_centroid = track.centroid;
}

// Takes a frame's plane as the track's newest measurement, and as its best when it has the
// most inliers so far.
void measure(PlaneTrack& track, const SegmentedPlane& plane, double alpha) {
  track.inlier_count = plane.inlier_count;
  track.normal = plane.fit.normal;
  track.offset = plane.fit.offset;
  track.centroid = plane.fit.centroid;
  track.smoothed_normal = ((1.0 - alpha) * track.smoothed_normal + alpha * plane.fit.normal).normalized();
  track.smoothed_offset = (1.0 - alpha) * track.smoothed_offset + alpha * plane.fit.offset;
  if (plane.inlier_count >= track.best_inlier_count) {
    track.best_inlier_count = plane.inlier_count;
    track.best_normal = plane.fit.normal;
    track.best_offset = plane.fit.offset;
    track.best_centroid = plane.fit.centroid;
  }
}

// Pixel counts of two label images of one size: per label of each, and per pair of plane
// labels that share pixels. One pass, by runs of equal pairs: along a row a plane's label
// rarely changes, so a frame has a few thousand runs for 300 000 pixels.
struct LabelOverlap {
  std::vector<std::uint32_t> previous_pixels;  // [previous label]
  std::vector<std::uint32_t> current_pixels;   // [current label]
  struct Pair {
    std::uint64_t labels;  // previous label << 32 | current label
    std::uint32_t pixels;
  };
  std::vector<Pair> pairs;  // by labels, each pair once
};

// Throws on a current label above current_planes; previous labels were checked a frame ago.
LabelOverlap countOverlap(const std::vector<std::uint32_t>& previous, std::size_t previous_planes,
                          const std::vector<std::uint32_t>& current, std::size_t current_planes) {
  LabelOverlap overlap;
  overlap.previous_pixels.assign(previous_planes + 1, 0);
  overlap.current_pixels.assign(current_planes + 1, 0);
  const std::size_t size = current.size();
  for (std::size_t start = 0; start < size;) {
    const std::uint32_t a = previous[start], b = current[start];
    std::size_t end = start + 1;
    while (end < size && previous[end] == a && current[end] == b) ++end;
    if (b > current_planes)
      throw std::invalid_argument("floodplane::PlaneTracker::update: label " + std::to_string(b) + " but only " +
                                  std::to_string(current_planes) + " planes");
    const auto pixels = static_cast<std::uint32_t>(end - start);
    overlap.previous_pixels[a] += pixels;
    overlap.current_pixels[b] += pixels;
    if (a != 0 && b != 0) overlap.pairs.push_back({static_cast<std::uint64_t>(a) << 32 | b, pixels});
    start = end;
  }
  std::sort(overlap.pairs.begin(), overlap.pairs.end(),
            [](const LabelOverlap::Pair& x, const LabelOverlap::Pair& y) { return x.labels < y.labels; });
  std::size_t kept = 0;
  for (const LabelOverlap::Pair& pair : overlap.pairs) {
    if (kept > 0 && overlap.pairs[kept - 1].labels == pair.labels)
      overlap.pairs[kept - 1].pixels += pair.pixels;
    else
      overlap.pairs[kept++] = pair;
  }
  overlap.pairs.resize(kept);
  return overlap;
}

void checkLabels(const std::vector<std::uint32_t>& labels, std::size_t planes, const char* method) {
  const auto highest = std::max_element(labels.begin(), labels.end());
  if (highest != labels.end() && *highest > planes)
    throw std::invalid_argument(std::string("floodplane::PlaneTracker::") + method + ": label " +
                                std::to_string(*highest) + " but only " + std::to_string(planes) + " planes");
}

// One of a track's two measurements a plane is compared with, by reference into the track.
struct Measurement {
  const Eigen::Vector3d& normal;
  double offset;
  const Eigen::Vector3d& centroid;
};

// How far apart a track's plane and a frame's plane are: the smallest of the difference of
// their offsets d and the distances from each one's centroid to the other's plane. The offsets
// compare the planes at the foot of the perpendicular from the camera, often metres from any
// pixel of either: there a plane fitted to a sliver at the image's edge, its normal a few
// degrees off, lies tens of centimetres from where the surface is, while near its own pixels
// it is within millimetres of it (a wall 5 m away, last seen as a 20-pixel-wide strip 0.04 rad
// off, came back 12 cm away in d and 5 mm away at its centroid). The centroids, in turn, move
// with a camera turn the tracker was not told of (0.1 rad moves a centroid 5 m away by 50 cm
// off the turned plane), which leaves d as it was. Two parallel surfaces stay their distance
// apart by all three.
double separation(const Measurement& track, const PlaneFit& fit) {
  const double offsets = std::abs(track.offset - fit.offset);
  const double plane_at_track = std::abs(fit.normal.dot(track.centroid) + fit.offset);
  const double track_at_plane = std::abs(track.normal.dot(fit.centroid) + track.offset);
  return std::min({offsets, plane_at_track, track_at_plane});
}

struct Candidate {
  double score;
  std::size_t track;  // index into the tracks
  std::size_t plane;  // index into the frame's planes
};

// How alike a track and a frame's plane are, in [0, 1], or -1 where they are outside the gate
// (`max_angle`, `max_apart`): against the track's newest measurement and against its best one,
// the closer counts.
double similarity(const PlaneTrack& track, const PlaneFit& fit, double max_angle, double max_apart) {
  double similarity = -1.0;
  for (const Measurement& measured : {Measurement{track.normal, track.offset, track.centroid},
                                      Measurement{track.best_normal, track.best_offset, track.best_centroid}}) {
    const double angle = std::acos(std::clamp(measured.normal.dot(fit.normal), -1.0, 1.0));
    const double apart = separation(measured, fit);
    if (angle <= max_angle && apart <= max_apart)
      similarity = std::max(similarity, 1.0 - 0.5 * (angle / max_angle + apart / max_apart));
  }
  return similarity;
}

// The pixel overlap as intersection over union per (track, plane) pair: [track * planes + plane],
// 0 for a pair that shares no pixel. `previous_ids` are the previous frame's planes' track ids.
std::vector<double> intersectionOverUnion(const LabelOverlap& counts, const std::vector<PlaneTrack>& tracks,
                                          const std::vector<std::uint32_t>& previous_ids, std::size_t planes) {
  std::vector<double> overlap(tracks.size() * planes, 0.0);
  for (const LabelOverlap::Pair& pair : counts.pairs) {
    const auto previous = static_cast<std::uint32_t>(pair.labels >> 32);
    const auto current = static_cast<std::uint32_t>(pair.labels & 0xffffffffu);
    // The previous frame's tracks were all seen in it, so none has been dropped.
    const std::uint32_t id = previous_ids[previous - 1];
    const auto track = std::lower_bound(tracks.begin(), tracks.end(), id,
                                        [](const PlaneTrack& t, std::uint32_t i) { return t.id < i; });
    const double union_pixels =
        static_cast<double>(counts.previous_pixels[previous]) + counts.current_pixels[current] - pair.pixels;
    overlap[static_cast<std::size_t>(track - tracks.begin()) * planes + current - 1] = pair.pixels / union_pixels;
  }
  return overlap;
}

// The (track, plane) pairs of one round within the gate of `max_angle` (and the options' offset
// difference), of the tracks and planes not matched yet (plane_ids[p] == 0), scored by overlap
// plus similarity, best first. Ties go to the older track (tracks are by id), then to the larger
// plane (planes are by size).
void scoreCandidates(const std::vector<PlaneTrack>& tracks, const std::vector<SegmentedPlane>& planes,
                     const std::vector<std::uint32_t>& plane_ids, const std::vector<double>& overlap, bool lost_only,
                     std::size_t frame, double max_angle, double max_apart, std::vector<Candidate>& candidates) {
  candidates.clear();
  for (std::size_t t = 0; t < tracks.size(); ++t) {
    if (tracks[t].plane >= 0) continue;
    if (lost_only && tracks[t].last_frame + 1 >= frame) continue;
    for (std::size_t p = 0; p < planes.size(); ++p) {
      if (plane_ids[p] != 0) continue;
      const double alike = similarity(tracks[t], planes[p].fit, max_angle, max_apart);
      if (alike < 0.0) continue;
      candidates.push_back({overlap[t * planes.size() + p] + alike, t, p});
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.score != b.score) return a.score > b.score;
    if (a.track != b.track) return a.track < b.track;
    return a.plane < b.plane;
  });
}

// Step 5: the candidates taken best first, one-to-one: a track and a plane once each. The
// track takes the plane as its measurement in `frame` (smoothed with weight `alpha`).
void takeGreedily(const std::vector<Candidate>& candidates, const std::vector<SegmentedPlane>& planes,
                  std::size_t frame, double alpha, std::vector<PlaneTrack>& tracks,
                  std::vector<std::uint32_t>& plane_ids) {
  for (const Candidate& candidate : candidates) {
    PlaneTrack& track = tracks[candidate.track];
    if (track.plane >= 0 || plane_ids[candidate.plane] != 0) continue;
    const SegmentedPlane& plane = planes[candidate.plane];
    track.plane = static_cast<int>(candidate.plane);
    track.last_frame = frame;
    ++track.frames_seen;
    measure(track, plane, alpha);
    plane_ids[candidate.plane] = track.id;
  }
}

// The planes no track took (plane_ids[p] == 0) start new tracks, numbered from `next_id` on.
void startTracks(const std::vector<SegmentedPlane>& planes, std::size_t frame, std::uint32_t& next_id,
                 std::vector<PlaneTrack>& tracks, std::vector<std::uint32_t>& plane_ids) {
  for (std::size_t p = 0; p < planes.size(); ++p) {
    if (plane_ids[p] != 0) continue;
    PlaneTrack track;
    track.id = next_id++;
    track.first_frame = track.last_frame = frame;
    track.frames_seen = 1;
    track.plane = static_cast<int>(p);
    measure(track, planes[p], 1.0);  // weight 1: the first measurement is the smoothed one too
    tracks.push_back(track);         // ids grow, so the tracks stay by id
    plane_ids[p] = track.id;
  }
}

// The tracks into the current camera frame, moved by `motion` (the camera's since the last
// frame). Without a motion the best measurement is in a camera frame that has since moved by an
// unknown amount, and the newest takes its place: a stale view of one surface would match
// whatever the camera now sees where that surface was (measured: bench/HISTORY.md,
// "Tracking without a camera motion"). No track has a plane of this frame yet.
void bringIntoCurrentFrame(const Eigen::Isometry3d* motion, std::vector<PlaneTrack>& tracks) {
  if (motion)
    for (PlaneTrack& track : tracks) moveIntoCurrentFrame(track, *motion);
  else
    for (PlaneTrack& track : tracks) forgetBest(track);
  for (PlaneTrack& track : tracks) track.plane = -1;
}

}  // namespace

PlaneTracker::PlaneTracker() = default;

PlaneTracker::PlaneTracker(const Options& options) { setOptions(options); }

void PlaneTracker::setOptions(const Options& options) {
  const std::string what = problem(options);
  if (!what.empty()) throw std::invalid_argument("floodplane::PlaneTracker::Options: " + what);
  options_ = options;
}

const std::vector<std::uint32_t>& PlaneTracker::update(const Segmentation& segmentation) {
  return associate(segmentation, nullptr);
}

const std::vector<std::uint32_t>& PlaneTracker::update(const Segmentation& segmentation,
                                                       const Eigen::Isometry3d& motion) {
  return update(segmentation, motion.matrix());
}

const std::vector<std::uint32_t>& PlaneTracker::update(const Segmentation& segmentation,
                                                       const Eigen::Matrix4d& motion) {
  if (!isRigid(motion))
    throw std::invalid_argument(
        "floodplane::PlaneTracker::update: the motion must be a finite rigid transform (orthonormal rotation, last "
        "row 0 0 0 1)");
  const Eigen::Isometry3d isometry(motion);
  return associate(segmentation, &isometry);
}

const std::vector<std::uint32_t>& PlaneTracker::associate(const Segmentation& segmentation,
                                                          const Eigen::Isometry3d* motion) {
  if (segmentation.width < 0 || segmentation.height < 0 ||
      segmentation.labels.size() !=
          static_cast<std::size_t>(segmentation.width) * static_cast<std::size_t>(segmentation.height))
    throw std::invalid_argument("floodplane::PlaneTracker::update: the labels do not fill width x height");
  const std::size_t frame = frame_count_;
  const std::vector<SegmentedPlane>& planes = segmentation.planes;

  // 1. Pixel overlap with the previous frame (this also checks the labels, before anything changes).
  const bool same_grid = frame > 0 && segmentation.width == previous_width_ && segmentation.height == previous_height_;
  const bool small_motion = !motion || (Eigen::AngleAxisd(motion->linear()).angle() <= options_.overlap_max_rotation &&
                                        motion->translation().norm() <= options_.overlap_max_translation);
  const bool use_overlap = same_grid && small_motion;
  LabelOverlap counts;
  if (use_overlap)
    counts = countOverlap(previous_labels_, plane_track_ids_.size(), segmentation.labels, planes.size());
  else
    checkLabels(segmentation.labels, planes.size(), "update");

  // 2. The tracks into the current camera frame.
  bringIntoCurrentFrame(motion && frame > 0 ? motion : nullptr, tracks_);

  // 3. The overlap as intersection over union per (track, plane).
  const std::vector<double> overlap = intersectionOverUnion(counts, tracks_, plane_track_ids_, planes.size());

  // 4. Candidate pairs within the gate, scored by overlap plus parameter similarity, taken
  // greedily one-to-one (5). Two rounds: every track within the gate, then the tracks lost
  // before the previous frame, within twice the angle, for the planes still unmatched. A
  // surface coming back into view shows first as a sliver at the image's edge whose normal
  // can be off by 0.1-0.2 rad; the wider gate takes it back then rather than giving it a new
  // id, which would stay with it. Only in the second round, so that it never takes a plane
  // that a track seen a frame ago matches, and only for lost tracks, whose pixels nothing
  // else in the frame claims.
  plane_track_ids_.assign(planes.size(), 0);
  const double alpha = options_.smoothing;
  std::vector<Candidate> candidates;
  for (const bool lost_only : {false, true}) {
    const double max_angle = lost_only ? 2.0 * options_.max_normal_angle : options_.max_normal_angle;
    scoreCandidates(tracks_, planes, plane_track_ids_, overlap, lost_only, frame, max_angle,
                    options_.max_offset_difference, candidates);
    takeGreedily(candidates, planes, frame, alpha, tracks_, plane_track_ids_);
  }
  // The planes left over start new tracks.
  startTracks(planes, frame, next_id_, tracks_, plane_track_ids_);

  // 6. The tracks that have now been lost for more than max_lost_frames frames go.
  const auto max_lost = static_cast<std::size_t>(options_.max_lost_frames);
  tracks_.erase(std::remove_if(tracks_.begin(), tracks_.end(),
                               [&](const PlaneTrack& track) { return frame - track.last_frame > max_lost; }),
                tracks_.end());

  previous_width_ = segmentation.width;
  previous_height_ = segmentation.height;
  previous_labels_ = segmentation.labels;
  ++frame_count_;
  return plane_track_ids_;
}

void PlaneTracker::relabel(const std::vector<std::uint32_t>& labels, std::vector<std::uint32_t>& track_labels) const {
  checkLabels(labels, plane_track_ids_.size(), "relabel");
  std::vector<std::uint32_t> id_of_label(plane_track_ids_.size() + 1, 0);  // [label]; 0 stays 0
  std::copy(plane_track_ids_.begin(), plane_track_ids_.end(), id_of_label.begin() + 1);
  track_labels.resize(labels.size());
  std::transform(labels.begin(), labels.end(), track_labels.begin(),
                 [&](std::uint32_t label) { return id_of_label[label]; });
}

const PlaneTrack* PlaneTracker::track(std::uint32_t id) const {
  const auto found = std::lower_bound(tracks_.begin(), tracks_.end(), id,
                                      [](const PlaneTrack& t, std::uint32_t i) { return t.id < i; });
  return found != tracks_.end() && found->id == id ? &*found : nullptr;
}

void PlaneTracker::reset() {
  tracks_.clear();
  plane_track_ids_.clear();
  frame_count_ = 0;
  next_id_ = 1;
  previous_width_ = previous_height_ = 0;
  previous_labels_.clear();
}

}  // namespace floodplane
