// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment --track: its inputs as one sequence, track ids in the label field and the JSON,
// tracks.json, a bad frame skipped, and -j refused; --poses, the camera motions from a poses
// file, and its errors.

#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "pcd_segment_test.h"
#include "support/app_run.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::string kRenderedScene = std::string(FLOODPLANE_RENDERED_DIR) + "/boxes_on_floor.kinect.pcd";

std::vector<std::uint32_t> labelField(const fs::path& file) {
  pcl::PointCloud<pcl::PointXYZL> cloud;
  EXPECT_EQ(pcl::io::loadPCDFile(file.string(), cloud), 0) << file;
  std::vector<std::uint32_t> labels;
  for (const auto& p : cloud) labels.push_back(p.label);
  return labels;
}

Json readJson(const fs::path& file) { return Json::parse(readFile(file)); }

using Rows = std::vector<std::vector<double>>;
const Rows kIdentity = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
// A turn of 120 degrees about (1, 1, 1) (x to y, y to z, z to x) and a step: no plane of a scene
// keeps its normal and offset under it.
const Rows kTurned = {{0, 0, 1, 0.5}, {1, 0, 0, 0.2}, {0, 1, 0, -0.3}, {0, 0, 0, 1}};

// A poses file as pcd_synth --sequence writes it: "poses", one entry per frame.
std::string posesJson(const std::vector<Rows>& poses) {
  Json entries = Json::array();
  for (std::size_t k = 0; k < poses.size(); ++k)
    entries.push_back({{"frame", k}, {"time", static_cast<double>(k) / 30.0}, {"world_from_camera", poses[k]}});
  return Json{{"scene", "test"}, {"poses", entries}}.dump(2) + "\n";
}

std::set<std::uint32_t> trackIdsOf(const fs::path& planes_json) {
  const Json report = readJson(planes_json);  // not in the loop's head: a temporary's member would dangle
  std::set<std::uint32_t> ids;
  for (const Json& plane : report["planes"]) ids.insert(plane["track"].get<std::uint32_t>());
  return ids;
}

class PcdSegmentTrack : public PcdSegmentTest {
 protected:
  // The rendered scene copied to in/<name> for each name.
  void copyScene(const std::vector<std::string>& names) const {
    fs::create_directories(path("in"));
    for (const std::string& name : names) fs::copy_file(kRenderedScene, path("in/" + name));
  }
};

TEST_F(PcdSegmentTrack, KeepsEveryIdOfASceneGivenThreeTimes) {
  copyScene({"a.pcd", "b.pcd", "c.pcd"});
  const Result result = run({path("in").string(), "-o", path("out").string(), "--track", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  EXPECT_TRUE(contains(result.out, "tracks over 3 frames -> " + path("out/tracks.json").string())) << result.out;

  const std::vector<std::uint32_t> first = labelField(path("out/a.labels.pcd"));
  EXPECT_EQ(labelField(path("out/b.labels.pcd")), first);
  EXPECT_EQ(labelField(path("out/c.labels.pcd")), first);
  const Json planes = readJson(path("out/c.planes.json"))["planes"];
  ASSERT_GE(planes.size(), 5u);  // the floor, the boxes' faces
  std::set<std::uint32_t> ids;
  for (const Json& plane : planes) {
    // The first frame's ids are its size ranks; the same cloud again keeps them.
    EXPECT_EQ(plane["track"], plane["id"]);
    ids.insert(plane["track"].get<std::uint32_t>());
    std::size_t pixels = 0;
    for (const std::uint32_t label : first) pixels += label == plane["track"].get<std::uint32_t>();
    EXPECT_EQ(pixels, plane["inliers"].get<std::size_t>());
  }

  const Json tracks = readJson(path("out/tracks.json"));
  EXPECT_EQ(tracks["frame_count"], 3);
  EXPECT_EQ(tracks["frames"],
            Json::array({path("in/a.pcd").string(), path("in/b.pcd").string(), path("in/c.pcd").string()}));
  ASSERT_EQ(tracks["track_count"], planes.size());
  ASSERT_EQ(tracks["tracks"].size(), planes.size());
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const Json& track = tracks["tracks"][k];
    const Json& plane = planes[k];
    EXPECT_EQ(track["id"], plane["track"]);
    EXPECT_EQ(track["first_frame"], path("in/a.pcd").string());
    EXPECT_EQ(track["last_frame"], path("in/c.pcd").string());
    EXPECT_EQ(track["frames_seen"], 3);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(track["smoothed_normal"][i].get<double>(), plane["normal"][i].get<double>(), 1e-6);
    EXPECT_NEAR(track["smoothed_offset"].get<double>(), plane["d"].get<double>(), 1e-5);
  }
}

TEST_F(PcdSegmentTrack, ReportsABadFrameSkipsItAndGoesOn) {
  copyScene({"a.pcd", "c.pcd"});
  writeFile(path("in/b.pcd"), "not a point cloud\n");
  const Result result = run({path("in").string(), "-o", path("out").string(), "--track", "--json", "-j", "1"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.err, "pcd_segment: error: " + path("in/b.pcd").string())) << result.err;
  EXPECT_TRUE(contains(result.err, "1 of 3 inputs failed")) << result.err;
  EXPECT_FALSE(fs::exists(path("out/b.labels.pcd")));
  EXPECT_EQ(labelField(path("out/c.labels.pcd")), labelField(path("out/a.labels.pcd")));
  const Json tracks = readJson(path("out/tracks.json"));
  EXPECT_EQ(tracks["frames"], Json::array({path("in/a.pcd").string(), path("in/c.pcd").string()}));
  for (const Json& track : tracks["tracks"]) EXPECT_EQ(track["frames_seen"], 2) << track;
}

TEST_F(PcdSegmentTrack, TakesTheInputsInTheOrderGiven) {
  copyScene({"a.pcd", "c.pcd"});
  fs::copy_file(std::string(FLOODPLANE_RENDERED_DIR) + "/staircase.kinect.pcd", path("in/b.pcd"));
  // c first, another scene, then a (c's cloud again): a's planes get c's ids back.
  const Result result = run({path("in/c.pcd").string(), path("in/b.pcd").string(), path("in/a.pcd").string(), "-o",
                             path("out").string(), "--track", "--json", "-q"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
  const Json tracks = readJson(path("out/tracks.json"));
  EXPECT_EQ(tracks["frames"],
            Json::array({path("in/c.pcd").string(), path("in/b.pcd").string(), path("in/a.pcd").string()}));
  EXPECT_EQ(labelField(path("out/a.labels.pcd")), labelField(path("out/c.labels.pcd")));
}

TEST_F(PcdSegmentTrack, WritesNoTrackKeysOrSummaryWithoutTrack) {
  copyScene({"a.pcd", "b.pcd"});
  ASSERT_EQ(run({path("in").string(), "-o", path("out").string(), "--json"}).exit_code, 0);
  for (const Json& plane : readJson(path("out/b.planes.json"))["planes"]) EXPECT_FALSE(plane.contains("track"));
  EXPECT_FALSE(fs::exists(path("out/tracks.json")));
  // --track without --json: track ids in the labels, no summary.
  ASSERT_EQ(run({path("in").string(), "-o", path("tracked").string(), "--track"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(path("tracked/tracks.json")));
  EXPECT_EQ(labelField(path("tracked/b.labels.pcd")), labelField(path("out/b.labels.pcd")));
}

TEST_F(PcdSegmentTrack, RefusesSeveralJobsAndSaysWhyInTheHelp) {
  copyScene({"a.pcd", "b.pcd"});
  const Result refused = run({path("in").string(), "-o", path("out").string(), "--track", "-j", "2"});
  expectUsageError(refused, "pcd_segment", "--track segments the frames in order on one thread");
  EXPECT_FALSE(fs::exists(path("out")));
  const Result help = run({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_TRUE(contains(help.out, "--track")) << help.out;
  EXPECT_TRUE(contains(help.out, "in order on one thread")) << help.out;
}

TEST_F(PcdSegmentTrack, TakesTheCameraMotionsOfPosesAndGivesIdsBackAfterATurnAwayAndBack) {
  copyScene({"a.pcd", "b.pcd", "c.pcd"});
  // The same cloud three times, but the poses say the camera turned between a and b and back
  // for c: the tracker moves a's tracks by the turn, so no plane of b matches one (new ids), and
  // back again, so that c's planes get a's ids back.
  writeFile(path("turn.json"), posesJson({kIdentity, kTurned, kIdentity}));
  const Result result = run({path("in").string(), "-o", path("out").string(), "--track", "--json", "-q", "--poses",
                             path("turn.json").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  const std::set<std::uint32_t> first = trackIdsOf(path("out/a.planes.json"));
  const std::set<std::uint32_t> turned = trackIdsOf(path("out/b.planes.json"));
  ASSERT_GE(first.size(), 5u);
  ASSERT_EQ(turned.size(), first.size());
  EXPECT_GT(*turned.begin(), *first.rbegin()) << "a plane of the turned frame kept an id of the first";
  EXPECT_EQ(labelField(path("out/c.labels.pcd")), labelField(path("out/a.labels.pcd")));
  const Json tracks = readJson(path("out/tracks.json"));
  EXPECT_EQ(tracks["frame_count"], 3);
  EXPECT_EQ(tracks["track_count"], 2 * first.size());

  // Poses that do not move the camera: the ids of no poses at all.
  writeFile(path("still.json"), posesJson({kIdentity, kIdentity, kIdentity}));
  ASSERT_EQ(
      run({path("in").string(), "-o", path("still").string(), "--track", "-q", "--poses", path("still.json").string()})
          .exit_code,
      0);
  for (const std::string name : {"a", "b", "c"})
    EXPECT_EQ(labelField(path("still/" + name + ".labels.pcd")), labelField(path("out/a.labels.pcd"))) << name;
}

TEST_F(PcdSegmentTrack, TakesTheMotionFromTheLastFrameSegmentedWhenOneFails) {
  copyScene({"a.pcd", "c.pcd"});
  writeFile(path("in/b.pcd"), "not a point cloud\n");
  // b fails; c's motion is then from a's pose (the same), not from b's (turned).
  writeFile(path("poses.json"), posesJson({kIdentity, kTurned, kIdentity}));
  const Result result =
      run({path("in").string(), "-o", path("out").string(), "--track", "-q", "--poses", path("poses.json").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(contains(result.err, "pcd_segment: error: " + path("in/b.pcd").string())) << result.err;
  EXPECT_EQ(labelField(path("out/c.labels.pcd")), labelField(path("out/a.labels.pcd")));
}

TEST_F(PcdSegmentTrack, RefusesBadPosesInOneLineBeforeAnyWork) {
  copyScene({"a.pcd", "b.pcd"});
  // The first of two poses is `matrix`.
  const auto rows = [](const Rows& matrix) {
    Json poses = Json::array();
    poses.push_back(Json::object({{"world_from_camera", matrix}}));
    poses.push_back(Json::object({{"world_from_camera", kIdentity}}));
    return Json::object({{"poses", poses}}).dump();
  };
  Rows scaled = kIdentity;
  scaled[0][0] = 2.0;
  Rows bottom = kIdentity;
  bottom[3][0] = 0.1;
  Rows three_columns = kIdentity;
  for (auto& row : three_columns) row.pop_back();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "cannot be parsed as JSON: parse error at line 1, column"},
      {"{\"poses\": [", "cannot be parsed as JSON: parse error at line 1, column"},
      {"[]", "has no \"poses\" array"},
      {"{\"poses\": {}}", "has no \"poses\" array"},
      {posesJson({kIdentity}), "1 pose for 2 inputs"},
      {posesJson({kIdentity, kIdentity, kIdentity}), "3 poses for 2 inputs"},
      {"{\"poses\": [{\"frame\": 0}, {}]}", "poses[0] has no \"world_from_camera\""},
      {rows(three_columns), "poses[0].world_from_camera is not 4 rows of 4 numbers"},
      {rows({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}), "poses[0].world_from_camera is not 4 rows of 4 numbers"},
      {R"({"poses": [{"world_from_camera": [[1, 0, 0, "0"], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}, {}]})",
       "poses[0].world_from_camera is not 4 rows of 4 numbers"},
      {R"({"poses": [{"world_from_camera": [[1, 0, 0, 1e999], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]}, {}]})",
       "cannot be parsed as JSON: number overflow parsing '1e999'"},
      {rows(scaled), "poses[0].world_from_camera is not a finite rigid transform"},
      {rows(bottom), "poses[0].world_from_camera is not a finite rigid transform"},
  };
  for (const auto& [text, message] : cases) {
    writeFile(path("poses.json"), text);
    const Result result =
        run({path("in").string(), "-o", path("out").string(), "--track", "--poses", path("poses.json").string()});
    EXPECT_EQ(result.exit_code, 1) << text;
    EXPECT_EQ(lineCount(result.err), 1u) << result.err;
    EXPECT_TRUE(contains(result.err, "pcd_segment: error: --poses " + path("poses.json").string() + ": " + message))
        << text << "\n"
        << result.err;
    EXPECT_TRUE(result.out.empty()) << result.out;
    EXPECT_FALSE(fs::exists(path("out"))) << text;
  }
  const Result missing =
      run({path("in").string(), "-o", path("out").string(), "--track", "--poses", path("missing.json").string()});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(lineCount(missing.err), 1u) << missing.err;
  EXPECT_TRUE(contains(missing.err, path("missing.json").string() + ": cannot read the file: No such file"))
      << missing.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(PcdSegmentTrack, RefusesPosesWithoutTrackAndDescribesThemInTheHelp) {
  copyScene({"a.pcd", "b.pcd"});
  writeFile(path("poses.json"), posesJson({kIdentity, kIdentity}));
  const Result refused = run({path("in").string(), "-o", path("out").string(), "--poses", path("poses.json").string()});
  expectUsageError(refused, "pcd_segment", "--poses gives the camera motion to the tracker: it needs --track");
  EXPECT_FALSE(fs::exists(path("out")));
  const Result help = run({"--help"});
  EXPECT_TRUE(contains(help.out, "--poses FILE")) << help.out;
  EXPECT_TRUE(contains(help.out, "world_from_camera")) << help.out;
}

// The issue's target on real data, the three consecutive Kinect frames: every plane of at least
// 2 % of a frame that covers the same pixels as a plane of the frame before (intersection over
// union at least 0.5) carries that plane's track id. Prints how many of the tracks with such a
// plane are seen in all three frames.
TEST_F(PcdSegmentTrack, KeepsTheIdOfEveryLargePlaneThroughThreeRealKinectFrames) {
  const fs::path folder(FLOODPLANE_REAL_DATA_DIR);
  std::vector<std::string> frames;
  if (fs::is_directory(folder)) {
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().filename().string().rfind("frame_20121214T14225", 0) == 0)
        frames.push_back(entry.path().string());
  }
  if (frames.size() != 3) {
    GTEST_SKIP() << "needs the three consecutive Kinect frames frame_20121214T14225*.pcd in " << folder;
  }
  std::sort(frames.begin(), frames.end());
  fs::create_directories(path("in"));
  for (const std::string& frame : frames) fs::copy_file(frame, path("in") / fs::path(frame).filename());
  const Result result = run({path("in").string(), "-o", path("out").string(), "--track", "--json", "-q"});
  ASSERT_EQ(result.exit_code, 0) << result.err;

  std::vector<std::vector<std::uint32_t>> labels;
  for (const std::string& frame : frames) {
    const std::string stem = fs::path(frame).stem().string();
    labels.push_back(labelField(path("out/" + stem + ".labels.pcd")));
  }
  const auto pixelsOf = [](const std::vector<std::uint32_t>& image) {
    std::map<std::uint32_t, std::size_t> pixels;
    for (const std::uint32_t label : image) ++pixels[label];
    return pixels;
  };
  std::set<std::uint32_t> large;
  std::size_t compared = 0;
  for (std::size_t t = 0; t < labels.size(); ++t) {
    const std::vector<std::uint32_t>& current = labels[t];
    const std::map<std::uint32_t, std::size_t> current_pixels = pixelsOf(current);
    for (const auto& [id, pixels] : current_pixels)
      if (id != 0 && pixels * 50 >= current.size()) large.insert(id);
    if (t == 0) continue;
    const std::vector<std::uint32_t>& previous = labels[t - 1];
    const std::map<std::uint32_t, std::size_t> previous_pixels = pixelsOf(previous);
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> shared;  // (current, previous) id
    for (std::size_t i = 0; i < current.size(); ++i)
      if (current[i] != 0 && previous[i] != 0) ++shared[{current[i], previous[i]}];
    for (const auto& [id, pixels] : current_pixels) {
      if (id == 0 || pixels * 50 < current.size()) continue;
      double best = 0.0;
      std::uint32_t best_id = 0;
      for (const auto& [pair, count] : shared) {
        if (pair.first != id) continue;
        const double iou =
            static_cast<double>(count) / static_cast<double>(pixels + previous_pixels.at(pair.second) - count);
        if (iou > best) {
          best = iou;
          best_id = pair.second;
        }
      }
      if (best < 0.5) continue;
      EXPECT_EQ(id, best_id) << "frame " << t << ": the plane on track " << best_id << "'s pixels has id " << id;
      ++compared;
    }
  }
  EXPECT_GE(compared, 6u);  // not vacuous: most large planes have one in the frame before

  const Json tracks = readJson(path("out/tracks.json"));
  std::size_t through_all = 0;
  for (const Json& track : tracks["tracks"])
    if (large.count(track["id"].get<std::uint32_t>()) && track["frames_seen"] == 3) ++through_all;
  std::cout << "tracks with a plane of at least 2 % of a frame: " << large.size()
            << ", seen in all three frames: " << through_all
            << "; large planes compared with the frame before: " << compared << std::endl;
  RecordProperty("large_plane_tracks", static_cast<int>(large.size()));
  RecordProperty("seen_in_all_three_frames", static_cast<int>(through_all));
}

}  // namespace
}  // namespace floodplane::test
