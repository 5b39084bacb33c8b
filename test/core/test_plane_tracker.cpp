// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PlaneTracker: track ids over a stream of segmentations, built by hand on small grids.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "floodplane/plane_tracker.h"

namespace floodplane {
namespace {

constexpr int kWidth = 20, kHeight = 20;

// A plane n . P + d = 0 on the pixels [x0, x1) x [y0, y1) of the grid.
struct Surface {
  Eigen::Vector3d normal;
  double offset;
  int x0, y0, x1, y1;
  Eigen::Vector3d centroid = Eigen::Vector3d::Constant(NAN);  ///< NaN: the plane's point nearest the sensor
};

// A segmentation of the surfaces, labelled in the order given (surfaces[k] is label k + 1, a
// later one painted over an earlier one where they overlap); the centroid is the plane's point
// nearest the sensor unless the surface gives one.
Segmentation segmentationOf(const std::vector<Surface>& surfaces, int width = kWidth, int height = kHeight) {
  Segmentation segmentation;
  segmentation.width = width;
  segmentation.height = height;
  segmentation.labels.assign(static_cast<std::size_t>(width) * height, 0);
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const Surface& s = surfaces[k];
    SegmentedPlane plane;
    plane.fit.normal = s.normal.normalized();
    plane.fit.offset = s.offset;
    plane.fit.centroid = s.centroid.allFinite() ? s.centroid : Eigen::Vector3d(-s.offset * plane.fit.normal);
    plane.fit.valid = true;
    for (int y = s.y0; y < s.y1; ++y)
      for (int x = s.x0; x < s.x1; ++x)
        segmentation.labels[static_cast<std::size_t>(y) * width + x] = static_cast<std::uint32_t>(k + 1);
    plane.inlier_count = static_cast<std::uint32_t>((s.x1 - s.x0) * (s.y1 - s.y0));
    segmentation.planes.push_back(plane);
  }
  return segmentation;
}

// A room seen from inside: the far wall, the floor and a side wall, each on its own block.
const Eigen::Vector3d kTowardsCamera(0.0, 0.0, -1.0), kUp(0.0, -1.0, 0.0), kLeftwards(-1.0, 0.0, 0.0);
Surface wall(int x0 = 0, int y0 = 0, int x1 = 12, int y1 = 12) { return {kTowardsCamera, 3.0, x0, y0, x1, y1}; }
Surface floorOf(int x0 = 0, int y0 = 12, int x1 = 20, int y1 = 20) { return {kUp, 1.2, x0, y0, x1, y1}; }
Surface sideWall(int x0 = 12, int y0 = 0, int x1 = 20, int y1 = 12) { return {kLeftwards, 2.0, x0, y0, x1, y1}; }

// --- ids over frames --------------------------------------------------------------------------

TEST(PlaneTracker, GivesTheFirstFramesPlanesIdsFromOne) {
  PlaneTracker tracker;
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({wall(), floorOf(), sideWall()}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2, 3}));
  ASSERT_EQ(tracker.tracks().size(), 3u);
  EXPECT_EQ(tracker.frameCount(), 1u);
  EXPECT_EQ(tracker.track(2)->plane, 1);
  EXPECT_EQ(tracker.track(0), nullptr);
}

TEST(PlaneTracker, KeepsIdsWhenTheLabelsArePermutedFromFrameToFrame) {
  PlaneTracker tracker;
  const std::vector<std::uint32_t> first = tracker.update(segmentationOf({wall(), floorOf(), sideWall()}));
  // The segmenter numbers by size: as the camera moves the order changes, and the blocks grow
  // and shrink a little.
  std::vector<std::uint32_t> ids = tracker.update(segmentationOf({sideWall(11), wall(0, 0, 11), floorOf()}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{first[2], first[0], first[1]}));
  ids = tracker.update(segmentationOf({floorOf(0, 13), sideWall(10, 0, 20, 13), wall(0, 0, 10, 13)}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{first[1], first[2], first[0]}));
  EXPECT_EQ(tracker.tracks().size(), 3u);
  const PlaneTrack* floor_track = tracker.track(first[1]);
  ASSERT_NE(floor_track, nullptr);
  EXPECT_EQ(floor_track->first_frame, 0u);
  EXPECT_EQ(floor_track->last_frame, 2u);
  EXPECT_EQ(floor_track->frames_seen, 3u);
  EXPECT_EQ(floor_track->plane, 0);
}

TEST(PlaneTracker, GivesANewPlaneANewIdAndKeepsTheOthers) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(), floorOf(), sideWall()}));
  // A box face appears on the floor, facing the camera 1.5 m away: nothing matches it.
  const Surface box{kTowardsCamera, 1.5, 4, 14, 8, 18};
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), wall(), sideWall(), box}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{2, 1, 3, 4}));
  EXPECT_EQ(tracker.track(4)->first_frame, 1u);
  EXPECT_EQ(tracker.track(4)->frames_seen, 1u);
}

TEST(PlaneTracker, GivesTwoCoplanarPlanesOfOneFrameDifferentIds) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(0, 0, 20, 12), floorOf()}));
  // A pillar splits the wall: both halves fit the wall's track, only one may have it.
  const std::vector<std::uint32_t> ids =
      tracker.update(segmentationOf({wall(0, 0, 12, 12), floorOf(), wall(14, 0, 20, 12)}));
  EXPECT_EQ(ids[0], 1u);  // the half that overlaps the old wall most
  EXPECT_EQ(ids[1], 2u);
  EXPECT_EQ(ids[2], 3u);
}

// --- lost and returning -----------------------------------------------------------------------

TEST(PlaneTracker, GivesAPlaneItsIdBackWhenItReturnsWithinMaxLostFrames) {
  PlaneTracker tracker;  // max_lost_frames 30
  tracker.update(segmentationOf({floorOf(), sideWall()}));
  for (int frame = 1; frame <= 30; ++frame) {
    tracker.update(segmentationOf({floorOf()}));
    const PlaneTrack* lost = tracker.track(2);
    ASSERT_NE(lost, nullptr) << "frame " << frame;
    EXPECT_EQ(lost->plane, -1);
  }
  // Back after 30 frames away, elsewhere in the image (no overlap): its parameters find it.
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), sideWall(0, 0, 6, 10)}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2}));
  const PlaneTrack* back = tracker.track(2);
  EXPECT_EQ(back->first_frame, 0u);
  EXPECT_EQ(back->last_frame, 31u);
  EXPECT_EQ(back->frames_seen, 2u);
}

// A plane fitted to a sliver at the image's edge, its normal tilted by `angle` about the
// vertical through `centroid`, a point of the true plane.
Surface tiltedThrough(const Surface& truth, double angle, const Eigen::Vector3d& centroid, int x0, int y0, int x1,
                      int y1) {
  const Eigen::Vector3d normal = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()) * truth.normal.normalized();
  return {normal, -normal.dot(centroid), x0, y0, x1, y1, centroid};
}

TEST(PlaneTracker, ComparesOffsetsWhereThePlanesWereSeen) {
  // A wall 5 m ahead, last seen as a sliver 3 m to the right whose normal is 0.04 rad off:
  // that plane's offset d is 12 cm from the wall's, more than max_offset_difference (8 cm),
  // but at the sliver it is on the wall, and the wall coming back is on it there.
  const Surface far_wall{kTowardsCamera, 5.0, 0, 0, 10, 10, Eigen::Vector3d(-2.0, 0.0, 5.0)};
  const Surface sliver = tiltedThrough(far_wall, 0.04, Eigen::Vector3d(3.0, 0.0, 5.0), 18, 0, 20, 10);
  ASSERT_GT(std::abs(sliver.offset - far_wall.offset), PlaneTracker::Options().max_offset_difference);
  PlaneTracker tracker;
  tracker.update(segmentationOf({floorOf(), sliver}));
  tracker.update(segmentationOf({floorOf()}));  // out of view
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), far_wall}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2}));
}

TEST(PlaneTracker, KeepsAFarPlaneThroughACameraTurnItWasNotToldOf) {
  // The camera turns 0.1 rad about its vertical axis between two frames, no motion given: the
  // wall's normal and centroid turn with it (the centroid by 50 cm, far off the turned plane),
  // its offset d stays.
  const Surface far_wall{kTowardsCamera, 5.0, 0, 0, 10, 10, Eigen::Vector3d(0.0, 0.0, 5.0)};
  const Eigen::AngleAxisd turn(0.1, Eigen::Vector3d::UnitY());
  const Surface turned{turn * far_wall.normal, 5.0, 2, 0, 12, 10, turn * far_wall.centroid};
  PlaneTracker tracker;
  tracker.update(segmentationOf({floorOf(), far_wall}));
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), turned}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2}));
}

TEST(PlaneTracker, TakesALostTrackBackByItsBestMeasuredPlaneWhenTheMotionsAreKnown) {
  // The side wall is seen whole, then shrinks to a sliver at the image's edge whose fitted
  // normal drifts 0.14 rad a frame (each step within max_normal_angle, so the track follows
  // it) to 0.42 rad off, then leaves the view. It comes back whole and as it is: 0.42 rad from
  // the track's newest measurement, beyond even twice max_normal_angle, and on the plane the
  // track measured with the most inliers. The camera stands still, and says so.
  const Surface side = sideWall();
  const Eigen::Vector3d on_side(2.0, 0.0, 3.0);
  for (const bool motions_known : {true, false}) {
    SCOPED_TRACE(motions_known ? "motions given" : "no motions");
    PlaneTracker tracker;
    const auto update = [&](const Segmentation& segmentation) {
      return motions_known ? tracker.update(segmentation, Eigen::Isometry3d::Identity()) : tracker.update(segmentation);
    };
    update(segmentationOf({floorOf(), side}));
    for (const double drift : {0.14, 0.28, 0.42})
      ASSERT_EQ(update(segmentationOf({floorOf(), tiltedThrough(side, drift, on_side, 18, 0, 20, 12)})),
                (std::vector<std::uint32_t>{1, 2}));
    update(segmentationOf({floorOf()}));
    const std::vector<std::uint32_t> ids = update(segmentationOf({floorOf(), side}));
    if (motions_known) {
      EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2}));
      EXPECT_EQ(tracker.track(2)->best_inlier_count, 96u);  // the whole wall, 8 x 12 pixels
    } else {
      // Without motions a view from frames ago is in a camera frame moved by an unknown amount:
      // only the newest measurement counts, and the wall is a new surface.
      EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3}));
    }
  }
}

TEST(PlaneTracker, TakesALostTrackBackWithTwiceTheNormalAngleOnlyWhenNothingElseMatches) {
  const Surface side = sideWall();
  const Eigen::Vector3d on_side(2.0, 0.0, 3.0);  // a point of the side wall, x = 2
  // Back from out of view as a sliver 0.2 rad off (max_normal_angle 0.15): its id back.
  {
    PlaneTracker tracker;
    tracker.update(segmentationOf({floorOf(), side}));
    tracker.update(segmentationOf({floorOf()}));
    const std::vector<std::uint32_t> ids =
        tracker.update(segmentationOf({floorOf(), tiltedThrough(side, 0.2, on_side, 18, 0, 20, 12)}));
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2}));
  }
  // Seen a frame ago, the same plane 0.2 rad off is another surface: a new id.
  {
    PlaneTracker tracker;
    tracker.update(segmentationOf({floorOf(), side}));
    const std::vector<std::uint32_t> ids =
        tracker.update(segmentationOf({floorOf(), tiltedThrough(side, 0.2, on_side, 12, 0, 20, 12)}));
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3}));
  }
  // Beyond twice the angle: a new id even for a lost track.
  {
    PlaneTracker tracker;
    tracker.update(segmentationOf({floorOf(), side}));
    tracker.update(segmentationOf({floorOf()}));
    const std::vector<std::uint32_t> ids =
        tracker.update(segmentationOf({floorOf(), tiltedThrough(side, 0.35, on_side, 18, 0, 20, 12)}));
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3}));
  }
  // A lost track and a track seen a frame ago both within the wider angle of a plane: the
  // first round gives it to the one within max_normal_angle, the lost one stays lost.
  {
    PlaneTracker tracker;
    const Surface tilted = tiltedThrough(side, 0.1, on_side, 12, 0, 20, 12);
    tracker.update(segmentationOf({floorOf(), side, tilted}));  // ids 1, 2, 3
    tracker.update(segmentationOf({floorOf(), tilted}));        // 2 lost, 3 seen
    const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), tilted}));
    EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3}));
  }
}

TEST(PlaneTracker, GivesAPlaneANewIdWhenItWasGoneLongerThanMaxLostFrames) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({floorOf(), sideWall()}));
  for (int frame = 1; frame <= 31; ++frame) tracker.update(segmentationOf({floorOf()}));
  EXPECT_EQ(tracker.track(2), nullptr);  // dropped
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({floorOf(), sideWall()}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 3}));
}

TEST(PlaneTracker, CountsLostFramesWithTheMaxLostFramesOption) {
  PlaneTracker::Options options;
  options.max_lost_frames = 3;
  PlaneTracker tracker(options);
  tracker.update(segmentationOf({floorOf(), sideWall()}));
  for (int frame = 1; frame <= 3; ++frame) tracker.update(segmentationOf({floorOf()}));
  EXPECT_EQ(tracker.update(segmentationOf({floorOf(), sideWall()}))[1], 2u);  // 3 frames away
  for (int frame = 1; frame <= 4; ++frame) tracker.update(segmentationOf({floorOf()}));
  EXPECT_EQ(tracker.update(segmentationOf({floorOf(), sideWall()}))[1], 3u);  // 4 frames away
}

// --- parallel planes --------------------------------------------------------------------------

// A floor and a 2 cm step on it (two parallel planes 2 cm apart), each on its own rows.
Surface lowerFloor(int y0, int y1) { return {kUp, 1.20, 0, y0, 20, y1}; }
Surface step(int y0, int y1) { return {kUp, 1.18, 0, y0, 20, y1}; }

TEST(PlaneTracker, DoesNotSwapTwoParallelPlanesTwoCentimetresApartByTheirOffsets) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({lowerFloor(0, 5), step(5, 10)}));
  // Both move to rows they did not cover (no overlap to go by) and the step is now labelled
  // first: the offsets alone tell them apart.
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({step(15, 20), lowerFloor(10, 15)}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{2, 1}));
}

TEST(PlaneTracker, DoesNotSwapTwoParallelPlanesTwoCentimetresApartWhenTheCameraMovesUnknown) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({lowerFloor(10, 20), step(0, 10)}));
  // The camera sinks 3 cm, and no motion is given: the floor's offset (1.17) is now nearer the
  // step's old one (1.18) than its own (1.20). Their pixels barely moved: the overlap decides.
  const Surface lower{kUp, 1.17, 0, 11, 20, 20}, upper{kUp, 1.15, 0, 0, 20, 11};
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({upper, lower}));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{2, 1}));
}

// --- camera motion ----------------------------------------------------------------------------

// The plane through three points, its normal towards the origin.
Surface planeThrough(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int x0, int y0,
                     int x1, int y1) {
  Eigen::Vector3d normal = (b - a).cross(c - a).normalized();
  double offset = -normal.dot(a);
  if (offset < 0.0) normal = -normal, offset = -offset;
  return {normal, offset, x0, y0, x1, y1};
}

// A surface of the first camera's frame seen from a camera at pose `motion` (in that frame):
// three of its points moved into the new camera's frame, P_new = motion^-1 P_old.
Surface seenFrom(const Eigen::Isometry3d& motion, const Surface& s, int x0, int y0, int x1, int y1) {
  const Eigen::Vector3d point = -s.offset * s.normal;
  const Eigen::Vector3d u = s.normal.unitOrthogonal(), v = s.normal.cross(u);
  const Eigen::Isometry3d to_new = motion.inverse();
  return planeThrough(to_new * point, to_new * (point + u), to_new * (point + v), x0, y0, x1, y1);
}

Eigen::Isometry3d turnAndStep(double yaw, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  motion.translation() = translation;
  return motion;
}

TEST(PlaneTracker, MatchesPlanesThroughAGivenMotionWhereOverlapAloneFails) {
  const Eigen::Isometry3d motion = turnAndStep(0.6, {0.5, 0.0, 0.4});
  // The camera turns 34 degrees towards the side wall: in the image the far wall and the side
  // wall trade places, and their normals turn by as much.
  const Segmentation before = segmentationOf({wall(), floorOf(), sideWall()});
  const Segmentation after =
      segmentationOf({seenFrom(motion, sideWall(), 0, 0, 12, 12), seenFrom(motion, floorOf(), 0, 12, 20, 20),
                      seenFrom(motion, wall(), 12, 0, 20, 12)});
  PlaneTracker with_motion;
  with_motion.update(before);
  EXPECT_EQ(with_motion.update(after, motion), (std::vector<std::uint32_t>{3, 2, 1}));
  // The same as a 4 x 4 matrix.
  PlaneTracker with_matrix;
  with_matrix.update(before);
  EXPECT_EQ(with_matrix.update(after, motion.matrix()), (std::vector<std::uint32_t>{3, 2, 1}));
  // Without the motion only the floor (whose plane a turn about the vertical keeps) matches.
  PlaneTracker without_motion;
  without_motion.update(before);
  EXPECT_EQ(without_motion.update(after), (std::vector<std::uint32_t>{4, 2, 5}));
}

TEST(PlaneTracker, KeepsLostTracksInTheCurrentCameraFrame) {
  const Eigen::Isometry3d motion = turnAndStep(-0.3, {-0.2, 0.0, 0.3});
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(), floorOf(), sideWall()}));
  // The side wall leaves the view while the camera turns away from it, twice.
  Eigen::Isometry3d pose = motion;  // of the current camera in the first one's frame
  tracker.update(segmentationOf({seenFrom(pose, wall(), 4, 0, 20, 12), seenFrom(pose, floorOf(), 0, 12, 20, 20)}),
                 motion);
  pose = pose * motion;
  tracker.update(segmentationOf({seenFrom(pose, wall(), 8, 0, 20, 12), seenFrom(pose, floorOf(), 0, 12, 20, 20)}),
                 motion);
  const PlaneTrack* lost = tracker.track(3);
  ASSERT_NE(lost, nullptr);
  const Surface expected = seenFrom(pose, sideWall(), 0, 0, 1, 1);
  EXPECT_LT((lost->normal - expected.normal).norm(), 1e-9);
  EXPECT_NEAR(lost->offset, expected.offset, 1e-9);
  EXPECT_LT((lost->smoothed_normal - expected.normal).norm(), 1e-9);
  EXPECT_NEAR(lost->smoothed_offset, expected.offset, 1e-9);
  EXPECT_LT((lost->centroid - pose.inverse() * (-2.0 * kLeftwards)).norm(), 1e-9);
  // Back the way it came, in one step: the side wall returns with its id.
  const Eigen::Isometry3d back = pose.inverse();
  const std::vector<std::uint32_t> ids = tracker.update(segmentationOf({wall(), floorOf(), sideWall()}), back);
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{1, 2, 3}));
}

// --- parameters -------------------------------------------------------------------------------

TEST(PlaneTracker, SmoothedParametersFollowAStepAndConverge) {
  PlaneTracker tracker;  // smoothing 0.3
  tracker.update(segmentationOf({{kUp, 1.20, 0, 0, 20, 20}}));
  // The floor's fit jumps by 4 cm and 0.1 rad and stays there.
  const Eigen::Vector3d tilted = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * kUp;
  tracker.update(segmentationOf({{tilted, 1.24, 0, 0, 20, 20}}));
  const PlaneTrack* floor_track = tracker.track(1);
  EXPECT_DOUBLE_EQ(floor_track->offset, 1.24);  // the current parameters are the newest
  EXPECT_NEAR(floor_track->smoothed_offset, 0.7 * 1.20 + 0.3 * 1.24, 1e-12);
  const double first_angle = std::acos(std::min(1.0, floor_track->smoothed_normal.dot(tilted)));
  EXPECT_GT(first_angle, 0.05);  // it lags
  EXPECT_LT(first_angle, 0.09);
  for (int frame = 0; frame < 30; ++frame) tracker.update(segmentationOf({{tilted, 1.24, 0, 0, 20, 20}}));
  EXPECT_NEAR(floor_track->smoothed_offset, 1.24, 1e-4);
  EXPECT_NEAR(floor_track->smoothed_normal.norm(), 1.0, 1e-12);
  EXPECT_LT(std::acos(std::min(1.0, floor_track->smoothed_normal.dot(tilted))), 1e-3);
}

// --- relabelling ------------------------------------------------------------------------------

TEST(PlaneTracker, RelabelsTheLabelImageWithTrackIds) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(0, 0, 12, 10), floorOf(), sideWall(12, 0, 20, 10)}));
  const Segmentation frame = segmentationOf({sideWall(12, 0, 20, 10), floorOf(), wall(0, 0, 12, 10)});
  tracker.update(frame);
  std::vector<std::uint32_t> track_labels;
  tracker.relabel(frame.labels, track_labels);
  ASSERT_EQ(track_labels.size(), frame.labels.size());
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::uint32_t expected = y >= 12 ? 2 : y >= 10 ? 0 : x < 12 ? 1 : 3;  // rows 10, 11: no plane
      EXPECT_EQ(track_labels[static_cast<std::size_t>(y) * kWidth + x], expected) << x << ", " << y;
    }
  std::vector<std::uint32_t> in_place = frame.labels;
  tracker.relabel(in_place, in_place);
  EXPECT_EQ(in_place, track_labels);
  std::vector<std::uint32_t> bad = frame.labels;
  bad[7] = 4;  // the frame has 3 planes
  EXPECT_THROW(tracker.relabel(bad, track_labels), std::invalid_argument);
}

// --- errors and reset -------------------------------------------------------------------------

void expectRejected(void (*spoil)(PlaneTracker::Options&), const std::string& name) {
  PlaneTracker::Options options;
  spoil(options);
  try {
    PlaneTracker tracker(options);
    ADD_FAILURE() << name << " accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
  }
}

TEST(PlaneTracker, RejectsBadOptionsNamingTheOption) {
  expectRejected([](PlaneTracker::Options& o) { o.max_normal_angle = 0.0; }, "max_normal_angle");
  expectRejected([](PlaneTracker::Options& o) { o.max_normal_angle = 4.0; }, "max_normal_angle");
  expectRejected([](PlaneTracker::Options& o) { o.max_normal_angle = NAN; }, "max_normal_angle");
  expectRejected([](PlaneTracker::Options& o) { o.max_offset_difference = -0.1; }, "max_offset_difference");
  expectRejected([](PlaneTracker::Options& o) { o.max_offset_difference = INFINITY; }, "max_offset_difference");
  expectRejected([](PlaneTracker::Options& o) { o.max_lost_frames = -1; }, "max_lost_frames");
  expectRejected([](PlaneTracker::Options& o) { o.smoothing = 0.0; }, "smoothing");
  expectRejected([](PlaneTracker::Options& o) { o.smoothing = 1.5; }, "smoothing");
  expectRejected([](PlaneTracker::Options& o) { o.smoothing = NAN; }, "smoothing");
  expectRejected([](PlaneTracker::Options& o) { o.overlap_max_rotation = -0.01; }, "overlap_max_rotation");
  expectRejected([](PlaneTracker::Options& o) { o.overlap_max_translation = NAN; }, "overlap_max_translation");
  // setOptions keeps the old options when it rejects the new ones.
  PlaneTracker tracker;
  PlaneTracker::Options bad;
  bad.smoothing = 2.0;
  EXPECT_THROW(tracker.setOptions(bad), std::invalid_argument);
  EXPECT_EQ(tracker.options().smoothing, PlaneTracker::Options().smoothing);
  PlaneTracker::Options edge;  // the limits themselves are valid
  edge.max_normal_angle = M_PI;
  edge.max_lost_frames = 0;
  edge.smoothing = 1.0;
  edge.overlap_max_rotation = edge.overlap_max_translation = 0.0;
  EXPECT_NO_THROW(tracker.setOptions(edge));
}

TEST(PlaneTracker, RejectsBadFramesAndMotionsAndStaysAsItWas) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(), floorOf()}));
  Segmentation short_labels = segmentationOf({wall(), floorOf()});
  short_labels.labels.pop_back();
  EXPECT_THROW(tracker.update(short_labels), std::invalid_argument);
  Segmentation unknown_label = segmentationOf({wall(), floorOf()});
  unknown_label.labels[5] = 3;
  EXPECT_THROW(tracker.update(unknown_label), std::invalid_argument);  // with the overlap pass
  EXPECT_THROW(tracker.update(unknown_label, turnAndStep(1.0, {0, 0, 0})), std::invalid_argument);  // without
  Eigen::Matrix4d scaled = Eigen::Matrix4d::Identity();
  scaled(0, 0) = 1.1;
  EXPECT_THROW(tracker.update(segmentationOf({wall(), floorOf()}), scaled), std::invalid_argument);
  Eigen::Matrix4d projective = Eigen::Matrix4d::Identity();
  projective(3, 2) = 0.5;
  EXPECT_THROW(tracker.update(segmentationOf({wall(), floorOf()}), projective), std::invalid_argument);
  Eigen::Matrix4d mirror = Eigen::Matrix4d::Identity();
  mirror(2, 2) = -1.0;
  EXPECT_THROW(tracker.update(segmentationOf({wall(), floorOf()}), mirror), std::invalid_argument);
  Eigen::Matrix4d not_finite = Eigen::Matrix4d::Identity();
  not_finite(0, 3) = NAN;
  EXPECT_THROW(tracker.update(segmentationOf({wall(), floorOf()}), not_finite), std::invalid_argument);
  // Nothing of the rejected frames stuck.
  EXPECT_EQ(tracker.frameCount(), 1u);
  EXPECT_EQ(tracker.update(segmentationOf({floorOf(), wall()})), (std::vector<std::uint32_t>{2, 1}));
  EXPECT_EQ(tracker.track(1)->frames_seen, 2u);
}

TEST(PlaneTracker, MatchesByParametersWhenTheImageSizeChanges) {
  PlaneTracker tracker;
  tracker.update(segmentationOf({wall(), floorOf()}));
  const std::vector<std::uint32_t> ids =
      tracker.update(segmentationOf({floorOf(0, 6, 10, 10), wall(0, 0, 10, 6)}, 10, 10));
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{2, 1}));
}

TEST(PlaneTracker, ResetForgetsEverythingAndStartsIdsAtOne) {
  PlaneTracker::Options options;
  options.smoothing = 0.5;
  PlaneTracker tracker(options);
  tracker.update(segmentationOf({wall(), floorOf()}));
  tracker.update(segmentationOf({wall(), floorOf(), sideWall()}));
  EXPECT_EQ(tracker.trackIds()[2], 3u);
  tracker.reset();
  EXPECT_EQ(tracker.frameCount(), 0u);
  EXPECT_TRUE(tracker.tracks().empty());
  EXPECT_TRUE(tracker.trackIds().empty());
  EXPECT_EQ(tracker.options().smoothing, 0.5);
  // The side wall alone: a fresh track 1, first seen in frame 0, not the old track 3.
  EXPECT_EQ(tracker.update(segmentationOf({sideWall()})), (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(tracker.track(1)->first_frame, 0u);
  EXPECT_EQ(tracker.track(1)->frames_seen, 1u);
  EXPECT_EQ(tracker.track(1)->normal, kLeftwards);
}

}  // namespace
}  // namespace floodplane
