// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Runs the pcd_synth binary with --random and checks what it writes and says: the outputs of
// every seed and sensor, scenes made again one at a time byte for byte, saved scene files that
// render the same frames, sequences of a walking camera (--sequence: every frame's files, the
// poses a walking step apart, frame 0 the single render, determinism, saved rooms walked as
// scene files, --look-away turning the camera away and back on the same walk), the boards
// family (--family boards: its own names and files, none and kinect only), the quirks of real
// sensors (only their own sensors' frames change, the ground truth lists them), the label PNG,
// and a clear error and exit code 2 for every bad combination of arguments.

#include <gtest/gtest.h>

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "floodplane/io/label_palette.h"
#include "support/app_process.h"
#include "support/app_run.h"
#include "support/png_images.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

class PcdSynth : public AppTest {
 protected:
  Result run(const std::vector<std::string>& arguments) const {
    return runShell("exec " + commandLine(PCD_SYNTH_BINARY, arguments));
  }

  // Checks the one-line usage error naming `reason` (as every floodplane app prints it), exit
  // code 2, and that nothing was written.
  void expectRejected(const std::vector<std::string>& arguments, const std::string& reason) const {
    std::vector<std::string> all = arguments;
    all.insert(all.end(), {"-o", path("rejected").string()});
    SCOPED_TRACE(reason);
    expectUsageError(run(all), "pcd_synth", reason);
    EXPECT_FALSE(fs::exists(path("rejected")));
  }
};

TEST_F(PcdSynth, RandomWritesEveryOutputOfEverySeedAndSensorWithAProgressLineEach) {
  const Result result = run({"--random", "2", "--seed", "41", "--png", "--write-scene", "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  EXPECT_EQ(lineCount(result.out), 2U) << result.out;
  EXPECT_TRUE(contains(result.out, "random_0041 (1 of 2)")) << result.out;
  EXPECT_TRUE(contains(result.out, "scanner 512x512")) << result.out;
  for (const std::string scene : {"random_0041", "random_0042"}) {
    for (const std::string sensor : {"none", "kinect", "scanner"}) {
      for (const std::string suffix : {".pcd", ".planes.json", ".labels.png"}) {
        const fs::path file = path("out") / (scene + "." + sensor + suffix);
        EXPECT_TRUE(fs::exists(file)) << file;
      }
    }
    EXPECT_TRUE(fs::exists(path("out") / (scene + ".room.json")));
    EXPECT_TRUE(fs::exists(path("out") / (scene + ".blocks.json")));
  }
  // Nothing else: no temporaries left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(path("out")), fs::directory_iterator()), 2 * 11);
}

TEST_F(PcdSynth, EachRandomSceneCanBeMadeAgainOnItsOwn) {
  ASSERT_EQ(run({"--random", "3", "--seed", "7", "--quiet", "-o", path("batch").string()}).exit_code, 0);
  const Result single = run({"--random", "1", "--seed", "8", "--sensor", "all", "-o", path("single").string()});
  ASSERT_EQ(single.exit_code, 0) << single.err;
  for (const std::string sensor : {"none", "kinect", "scanner"}) {
    for (const std::string suffix : {".pcd", ".planes.json"}) {
      const std::string name = "random_0008." + sensor + suffix;
      const std::string batch = readFile(path("batch") / name);
      EXPECT_FALSE(batch.empty()) << name;
      EXPECT_TRUE(batch == readFile(path("single") / name)) << name;
    }
  }
  // Another seed, another scene.
  EXPECT_FALSE(readFile(path("batch") / "random_0007.kinect.pcd") ==
               readFile(path("batch") / "random_0008.kinect.pcd"));
}

TEST_F(PcdSynth, SavedScenesRenderTheSameFramesFromTheirFiles) {
  ASSERT_EQ(run({"--random", "1", "--seed", "12", "--write-scene", "-q", "-o", path("random").string()}).exit_code, 0);
  const Result room = run({path("random/random_0012.room.json").string(), "--sensor", "kinect", "--seed", "12", "-q",
                           "-o", path("files").string()});
  ASSERT_EQ(room.exit_code, 0) << room.err;
  const Result blocks = run({path("random/random_0012.blocks.json").string(), "--sensor", "scanner", "--seed", "12",
                             "-q", "-o", path("files").string()});
  ASSERT_EQ(blocks.exit_code, 0) << blocks.err;
  EXPECT_TRUE(readFile(path("random/random_0012.kinect.pcd")) == readFile(path("files/random_0012.room.kinect.pcd")));
  EXPECT_TRUE(readFile(path("random/random_0012.scanner.pcd")) ==
              readFile(path("files/random_0012.blocks.scanner.pcd")));
}

TEST_F(PcdSynth, OneSensorWritesOnlyItsOwnFrames) {
  const Result result = run({"--random", "1", "--seed", "3", "--sensor", "scanner", "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::exists(path("out/random_0003.scanner.pcd")));
  EXPECT_FALSE(fs::exists(path("out/random_0003.none.pcd")));
  EXPECT_FALSE(fs::exists(path("out/random_0003.kinect.pcd")));
  EXPECT_TRUE(contains(result.out, "% no return")) << result.out;
}

TEST_F(PcdSynth, TheBoardsFamilyWritesBoardsScenesForNoneAndKinectNamedApartFromTheRooms) {
  const Result boards =
      run({"--random", "2", "--seed", "5", "--family", "boards", "--write-scene", "-o", path("out").string()});
  ASSERT_EQ(boards.exit_code, 0) << boards.err;
  EXPECT_EQ(lineCount(boards.out), 2U) << boards.out;
  EXPECT_TRUE(contains(boards.out, "boards_0005 (1 of 2)")) << boards.out;
  EXPECT_TRUE(contains(boards.out, " board edge")) << boards.out;
  for (const std::string scene : {"boards_0005", "boards_0006"}) {
    for (const std::string sensor : {"none", "kinect"}) {
      EXPECT_TRUE(fs::exists(path("out") / (scene + "." + sensor + ".pcd"))) << scene << " " << sensor;
      EXPECT_TRUE(fs::exists(path("out") / (scene + "." + sensor + ".planes.json"))) << scene << " " << sensor;
    }
    EXPECT_FALSE(fs::exists(path("out") / (scene + ".scanner.pcd"))) << scene;
    EXPECT_TRUE(fs::exists(path("out") / (scene + ".boards.json"))) << scene;
  }
  // The ground truth lists each board's six faces under its name.
  const auto listing = nlohmann::json::parse(readFile(path("out/boards_0005.none.planes.json")));
  int board_faces = 0;
  for (const auto& plane : listing.at("planes")) {
    board_faces += contains(plane.at("primitive").get<std::string>(), " board ") ? 1 : 0;
  }
  EXPECT_GE(board_faces, 2 * 6);
  EXPECT_EQ(board_faces % 6, 0);
  // The rooms of the same seeds go into the same directory without touching the boards.
  const std::string kinect = readFile(path("out/boards_0005.kinect.pcd"));
  ASSERT_EQ(run({"--random", "1", "--seed", "5", "--sensor", "kinect", "-q", "-o", path("out").string()}).exit_code, 0);
  EXPECT_TRUE(fs::exists(path("out/random_0005.kinect.pcd")));
  EXPECT_TRUE(readFile(path("out/boards_0005.kinect.pcd")) == kinect);
  EXPECT_FALSE(readFile(path("out/random_0005.kinect.pcd")) == kinect);
  // --family room is the default family, byte for byte.
  ASSERT_EQ(
      run({"--random", "1", "--seed", "5", "--sensor", "kinect", "--family", "room", "-q", "-o", path("room").string()})
          .exit_code,
      0);
  EXPECT_TRUE(readFile(path("room/random_0005.kinect.pcd")) == readFile(path("out/random_0005.kinect.pcd")));
  // A saved boards scene renders the same frame from its file.
  const Result file = run({path("out/boards_0005.boards.json").string(), "--sensor", "kinect", "--seed", "5", "-q",
                           "-o", path("files").string()});
  ASSERT_EQ(file.exit_code, 0) << file.err;
  EXPECT_TRUE(readFile(path("files/boards_0005.boards.kinect.pcd")) == kinect);
}

// "random_0009_f0002.kinect.pcd".
std::string frameFile(const std::string& scene, int frame, const std::string& sensor, const std::string& suffix) {
  char digits[16];
  std::snprintf(digits, sizeof digits, "_f%04d.", frame);
  return scene + digits + sensor + suffix;
}

// The x y z of every point of a text PCD of x y z label, without the labels.
std::string pointsOf(const std::string& pcd) {
  std::istringstream lines(pcd);
  std::string line;
  while (std::getline(lines, line) && line.rfind("DATA", 0) != 0) {
  }
  std::string points;
  while (std::getline(lines, line)) points += line.substr(0, line.rfind(' ')) + "\n";
  return points;
}

std::vector<Eigen::Matrix4d> posesOf(const std::string& json) {
  std::vector<Eigen::Matrix4d> poses;
  const nlohmann::json document = nlohmann::json::parse(json);
  for (const auto& pose : document.at("poses")) {
    Eigen::Matrix4d matrix;
    for (int row = 0; row < 4; ++row) {
      for (int column = 0; column < 4; ++column)
        matrix(row, column) = pose.at("world_from_camera").at(row).at(column).get<double>();
    }
    poses.push_back(matrix);
  }
  return poses;
}

TEST_F(PcdSynth, ASequenceWritesEveryFrameOfBothSensorsAndThePosesAWalkingStepApart) {
  const Result result = run({"--random", "1", "--seed", "9", "--sequence", "6", "--ascii", "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(lineCount(result.out), 1U) << result.out;
  EXPECT_TRUE(contains(result.out, "random_0009 (1 of 1); 6 frames none kinect, walked")) << result.out;
  for (int frame = 0; frame < 6; ++frame) {
    for (const std::string sensor : {"none", "kinect"}) {
      for (const std::string suffix : {".pcd", ".planes.json"}) {
        EXPECT_TRUE(fs::exists(path("out") / frameFile("random_0009", frame, sensor, suffix))) << frame << sensor;
      }
    }
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(path("out")), fs::directory_iterator()), 6 * 4 + 1);
  const std::vector<Eigen::Matrix4d> poses = posesOf(readFile(path("out/random_0009.poses.json")));
  ASSERT_EQ(poses.size(), 6U);
  for (std::size_t k = 1; k < poses.size(); ++k) {
    const Eigen::Vector3d step = poses[k].block<3, 1>(0, 3) - poses[k - 1].block<3, 1>(0, 3);
    EXPECT_LE(step.norm(), 1.4 / 30 + 1e-9) << "frame " << k;
    const Eigen::Matrix3d turn = poses[k - 1].block<3, 3>(0, 0).transpose() * poses[k].block<3, 3>(0, 0);
    EXPECT_LE(Eigen::AngleAxisd(turn).angle(), 1.2 * 3.14159265358979323846 / 180) << "frame " << k;
  }
  EXPECT_FALSE(poses.front().isApprox(poses.back(), 1e-9));
  // Frame 0 is the scene's own view with its own noise: the points a single render writes (its
  // labels may differ where faces that first touch in later frames are one surface).
  ASSERT_EQ(run({"--random", "1", "--seed", "9", "--sensor", "kinect", "--ascii", "-q", "-o", path("single").string()})
                .exit_code,
            0);
  const std::string single = pointsOf(readFile(path("single/random_0009.kinect.pcd")));
  EXPECT_GT(single.size(), 640U * 480U * 4U);
  EXPECT_TRUE(single == pointsOf(readFile(path("out") / frameFile("random_0009", 0, "kinect", ".pcd"))));
  // Every frame its own noise.
  EXPECT_FALSE(readFile(path("out") / frameFile("random_0009", 1, "kinect", ".pcd")) ==
               readFile(path("out") / frameFile("random_0009", 2, "kinect", ".pcd")));
}

TEST_F(PcdSynth, ASequenceIsTheSameEveryTimeAndASavedRoomCanBeWalkedAsASceneFile) {
  const std::vector<std::string> arguments = {"--random", "1",      "--seed",        "4",  "--sequence", "3",
                                              "--sensor", "kinect", "--write-scene", "-q", "-o"};
  std::vector<std::string> first = arguments;
  first.push_back(path("first").string());
  std::vector<std::string> second = arguments;
  second.push_back(path("second").string());
  ASSERT_EQ(run(first).exit_code, 0);
  ASSERT_EQ(run(second).exit_code, 0);
  for (const auto& entry : fs::directory_iterator(path("first"))) {
    const fs::path name = entry.path().filename();
    EXPECT_TRUE(readFile(entry.path()) == readFile(path("second") / name)) << name;
  }
  const Result scene_file = run({path("first/random_0004.room.json").string(), "--sequence", "3", "--sensor", "none",
                                 "-o", path("file").string()});
  ASSERT_EQ(scene_file.exit_code, 0) << scene_file.err;
  EXPECT_TRUE(contains(scene_file.out, "random_0004.room; 3 frames none")) << scene_file.out;
  EXPECT_TRUE(fs::exists(path("file/random_0004.room_f0002.none.pcd")));
  EXPECT_TRUE(fs::exists(path("file/random_0004.room.poses.json")));
}

// --look-away: the same walk (the same positions), the camera turned away by 60-90 degrees in
// some frames, the glances listed in the poses file; a small scene file, to be quick.
TEST_F(PcdSynth, LookingAwayTurnsTheCameraOfTheSameWalkAndThePosesFileSaysSo) {
  ASSERT_EQ(run({"--random", "1", "--seed", "4", "--sequence", "1", "--sensor", "none", "--write-scene", "-q", "-o",
                 path("room").string()})
                .exit_code,
            0);
  const auto walk = [&](const std::string& directory, bool look_away) {
    std::vector<std::string> arguments = {path("room/random_0004.room.json").string(),
                                          "--sequence",
                                          "90",
                                          "--sensor",
                                          "none",
                                          "--width",
                                          "64",
                                          "--height",
                                          "48",
                                          "-q",
                                          "-o",
                                          path(directory).string()};
    if (look_away) arguments.push_back("--look-away");
    const Result result = run(arguments);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return readFile(path(directory) / "random_0004.room.poses.json");
  };
  const std::string plain = walk("plain", false);
  const std::string glancing = walk("glancing", true);
  EXPECT_FALSE(contains(plain, "look_away"));
  const nlohmann::json listed = nlohmann::json::parse(glancing).at("look_away");
  EXPECT_EQ(listed.at("angle_degrees"), nlohmann::json({60.0, 90.0}));
  const std::vector<Eigen::Matrix4d> walked = posesOf(plain);
  const std::vector<Eigen::Matrix4d> turned = posesOf(glancing);
  ASSERT_EQ(walked.size(), 90U);
  ASSERT_EQ(turned.size(), 90U);
  double widest = 0.0;
  for (std::size_t k = 0; k < walked.size(); ++k) {
    const Eigen::Vector3d walked_position = walked[k].col(3).head<3>();
    const Eigen::Vector3d turned_position = turned[k].col(3).head<3>();
    EXPECT_TRUE(walked_position == turned_position) << "frame " << k;
    const Eigen::Matrix3d away = walked[k].block<3, 3>(0, 0).transpose() * turned[k].block<3, 3>(0, 0);
    widest = std::max(widest, Eigen::AngleAxisd(away).angle() * 180.0 / 3.14159265358979323846);
  }
  EXPECT_GE(widest, 60.0 - 1e-6);
  EXPECT_LE(widest, 90.0 + 1e-6);
  EXPECT_TRUE(fs::exists(path("glancing/random_0004.room_f0089.none.pcd")));
}

// The quirks of real sensors: each changes only the frames of the sensor models it belongs to
// (the exact frames stay as they were) and is listed in those frames' ground truth; a sequence
// keeps one warp (the scene's seed) through its frames.
TEST_F(PcdSynth, QuirksChangeOnlyTheirSensorsFramesAndTheGroundTruthListsThem) {
  ASSERT_EQ(run({"--random", "1", "--seed", "6", "-q", "-o", path("plain").string()}).exit_code, 0);
  const Result quirky = run({"--random", "1", "--seed", "6", "--quantize-bits", "8", "--warp", "2", "--speckle",
                             "--bend", "0.02", "-q", "-o", path("quirky").string()});
  ASSERT_EQ(quirky.exit_code, 0) << quirky.err;
  EXPECT_TRUE(readFile(path("plain/random_0006.none.pcd")) == readFile(path("quirky/random_0006.none.pcd")));
  EXPECT_TRUE(readFile(path("plain/random_0006.none.planes.json")) ==
              readFile(path("quirky/random_0006.none.planes.json")));
  for (const std::string sensor : {"kinect", "scanner"}) {
    EXPECT_FALSE(readFile(path("plain") / ("random_0006." + sensor + ".pcd")) ==
                 readFile(path("quirky") / ("random_0006." + sensor + ".pcd")))
        << sensor;
    EXPECT_EQ(nlohmann::json::parse(readFile(path("plain") / ("random_0006." + sensor + ".planes.json")))
                  .count("sensor_quirks"),
              0U);
  }
  const nlohmann::json scanner =
      nlohmann::json::parse(readFile(path("quirky/random_0006.scanner.planes.json"))).at("sensor_quirks");
  EXPECT_EQ(scanner.at("quantize_bits").get<int>(), 8);
  EXPECT_DOUBLE_EQ(scanner.at("warp_mm").get<double>(), 2.0);
  EXPECT_EQ(scanner.at("warp_seed").get<int>(), 6);
  EXPECT_TRUE(scanner.at("speckle").get<bool>());
  EXPECT_EQ(scanner.count("bend_per_m"), 0U);
  const nlohmann::json kinect =
      nlohmann::json::parse(readFile(path("quirky/random_0006.kinect.planes.json"))).at("sensor_quirks");
  EXPECT_DOUBLE_EQ(kinect.at("bend_per_m").get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(kinect.at("warp_mm").get<double>(), 2.0);
  EXPECT_EQ(kinect.count("quantize_bits"), 0U);

  const Result sequence = run({"--random", "1", "--seed", "6", "--sequence", "2", "--sensor", "kinect", "--warp", "2",
                               "--bend", "0.02", "-q", "-o", path("sequence").string()});
  ASSERT_EQ(sequence.exit_code, 0) << sequence.err;
  for (int frame = 0; frame < 2; ++frame) {
    const nlohmann::json listed =
        nlohmann::json::parse(readFile(path("sequence") / frameFile("random_0006", frame, "kinect", ".planes.json")));
    EXPECT_EQ(listed.at("sensor_quirks").at("warp_seed").get<int>(), 6) << "frame " << frame;
  }
}

// --png draws the ground truth as pcd_segment --png draws labels: a plane's colour where a
// point is on it, near-black on no plane, white where the sensor saw nothing.
// The camera's up (the world's z in the camera frame) in planes.json and, as the camera's
// orientation in the world, in the PCD's VIEWPOINT: the floor's ground-truth normal (towards the
// camera above it) is that up, and the VIEWPOINT's rotation turns it back onto the world's z.
TEST_F(PcdSynth, WritesTheCamerasUpInThePlanesJsonAndThePcdsViewpoint) {
  const std::string scene = std::string(FLOODPLANE_SOURCE_DIR) + "/data/scenes/tabletop.json";
  ASSERT_EQ(run({scene, "--sensor", "none", "--quiet", "-o", path("out").string()}).exit_code, 0);
  const nlohmann::json listing = nlohmann::json::parse(readFile(path("out/tabletop.none.planes.json")));
  const Eigen::Vector3d up(listing.at("up")[0].get<double>(), listing.at("up")[1].get<double>(),
                           listing.at("up")[2].get<double>());
  EXPECT_NEAR(up.norm(), 1.0, 1e-12);
  bool floor = false;
  for (const nlohmann::json& plane : listing.at("planes")) {
    if (plane.at("primitive") != "floor" || plane.at("pixels").get<int>() == 0) continue;
    floor = true;
    const Eigen::Vector3d normal(plane["normal"][0].get<double>(), plane["normal"][1].get<double>(),
                                 plane["normal"][2].get<double>());
    EXPECT_GT(normal.dot(up), 1.0 - 1e-9) << listing.dump();
  }
  EXPECT_TRUE(floor) << "the floor is in view";
  EXPECT_LT(up.y(), -0.5) << "the camera looks down at the table: up is mostly -y, tilted";
  EXPECT_GT(std::abs(up.z()), 0.2);
  pcl::PointCloud<pcl::PointXYZL> cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/tabletop.none.pcd").string(), cloud), 0);
  EXPECT_TRUE(cloud.sensor_origin_.isZero()) << "the points stay in the camera's frame";
  const Eigen::Vector3d world_up = cloud.sensor_orientation_.cast<double>() * up;
  EXPECT_NEAR(world_up.z(), 1.0, 1e-6) << world_up.transpose();
}

// Ctrl-C (SIGINT) or SIGTERM while frames are written: no temporary left, each frame's files
// all there or none, the one-line message, and the end by the signal (status 130 or 143).
TEST_F(PcdSynth, InterruptRemovesTheTemporariesAndEndsByTheSignal) {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
    SCOPED_TRACE(name);
    const fs::path out = path("out_" + name);
    AppProcess app(PCD_SYNTH_BINARY, {"--random", "500", "--sensor", "kinect", "--png", "--quiet", "-o", out.string()},
                   path("stdout"), path("stderr"));
    ASSERT_TRUE(app.running());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (app.running() && !fs::exists(out / "random_0002.kinect.pcd") &&
           std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    app.signal(signal_number);
    const std::optional<int> exit_code = app.waitFor(std::chrono::seconds(30));
    ASSERT_TRUE(exit_code.has_value()) << "still running 30 s after " << name;
    EXPECT_EQ(*exit_code, 128 + signal_number);
    EXPECT_TRUE(app.endedBySignal());
    EXPECT_EQ(readFile(path("stderr")), "pcd_synth: interrupted by " + name + ": unfinished outputs removed\n");
    std::size_t frames = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
      const std::string file = entry.path().filename().string();
      EXPECT_EQ(file.find(".tmp."), std::string::npos) << "a temporary left: " << file;
      const std::string suffix = ".kinect.pcd";
      if (file.size() < suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      ++frames;
      const std::string stem = file.substr(0, file.size() - 4);
      EXPECT_TRUE(fs::exists(out / (stem + ".planes.json"))) << stem;
      EXPECT_TRUE(fs::exists(out / (stem + ".labels.png"))) << stem;
    }
    EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), static_cast<long>(3 * frames))
        << "a file without the rest of its frame";
    EXPECT_GE(frames, 2u);
    EXPECT_LT(frames, 500u) << "the signal came after the run was done";
  }
}

TEST_F(PcdSynth, LabelPngShowsTheGroundTruthWithHolesWhite) {
  const Result result = run({std::string(FLOODPLANE_SOURCE_DIR) + "/data/scenes/tabletop.json", "--sensor", "kinect",
                             "--width", "160", "--height", "120", "--png", "-q", "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/tabletop.kinect.pcd").string(), cloud), 0);
  const floodplane::io::RgbImage image = readPng(path("out/tabletop.kinect.labels.png"));
  ASSERT_EQ(image.width, cloud.width);
  ASSERT_EQ(image.height, cloud.height);
  std::size_t holes = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const bool finite = std::isfinite(cloud[i].z);
    const std::array<std::uint8_t, 3> expected =
        finite ? floodplane::io::labelColor(cloud[i].label) : floodplane::io::kHoleColor;
    const std::array<std::uint8_t, 3> pixel{image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]};
    ASSERT_EQ(pixel, expected) << "pixel " << i;
    holes += finite ? 0 : 1;
  }
  EXPECT_GT(holes, 0u) << "the Kinect model loses returns";
}

TEST_F(PcdSynth, BadArgumentsAreRejectedWithAClearMessage) {
  expectRejected({"--random", "0"}, "--random");
  expectRejected({"--random", "2", "scene.json"}, "not both");
  expectRejected({}, "nothing to render");
  expectRejected({"scene.json", "--write-scene"}, "--write-scene");
  expectRejected({"--random", "2", "--seed", "18446744073709551615"}, "runs past the largest seed");
  expectRejected({"--random", "1", "--width", "320", "--height", "240"}, "--width and --height apply to scene files");
  expectRejected({"--random", "1", "--sensor", "lidar"}, "--sensor");
  expectRejected({"--random", "1", "--sequence", "0"}, "--sequence");
  expectRejected({"--random", "1", "--sequence", "x"}, "--sequence");
  expectRejected({"--random", "1", "--sequence", "3", "--sensor", "scanner"}, "--sequence walks through rooms");
  expectRejected({"--random", "1", "--sequence", "3", "--sensor", "all"}, "--sequence walks through rooms");
  expectRejected({"--random", "1", "--quantize-bits", "0"}, "--quantize-bits");
  expectRejected({"--random", "1", "--quantize-bits", "17"}, "--quantize-bits");
  expectRejected({"--random", "1", "--warp", "0"}, "--warp: the peak warp must be");
  expectRejected({"--random", "1", "--warp", "-2"}, "--warp: the peak warp must be");
  expectRejected({"--random", "1", "--warp", "nan"}, "--warp: the peak warp must be");
  expectRejected({"--random", "1", "--warp", "51"}, "--warp: the peak warp must be");
  expectRejected({"--random", "1", "--bend", "1.5"}, "--bend: the curvature must be");
  expectRejected({"--random", "1", "--bend", "inf"}, "--bend: the curvature must be");
  expectRejected({"--random", "1", "--bend", "0"}, "--bend: the curvature must be");
  expectRejected({"--random", "1", "--sensor", "kinect", "--quantize-bits", "8"},
                 "--quantize-bits applies to the scanner model");
  expectRejected({"--random", "1", "--sensor", "kinect", "--speckle"}, "--speckle applies to the scanner model");
  expectRejected({"--random", "1", "--sensor", "scanner", "--bend", "0.02"}, "--bend applies to the kinect model");
  expectRejected({"--random", "1", "--sensor", "none", "--warp", "2"}, "--warp applies to the scanner and kinect");
  expectRejected({"--random", "1", "--sequence", "3", "--speckle"}, "--speckle applies to the scanner model");
  expectRejected({"--random", "1", "--look-away"}, "--look-away turns the walking camera of --sequence");
  expectRejected({"--random", "1", "--family", "planks"}, "--family");
  expectRejected({"scene.json", "--family", "boards"}, "--family chooses the family of the generated scenes");
  expectRejected({"--random", "1", "--family", "boards", "--sensor", "scanner"}, "--family boards has no scanner");
  expectRejected({"--random", "1", "--family", "boards", "--sensor", "all"}, "--family boards has no scanner");
  expectRejected({"--random", "1", "--family", "boards", "--sequence", "3"}, "--family boards renders single frames");
  // -o names a directory: a file's name is refused, not made a directory.
  for (const std::string file : {"scenes.pcd", "scenes.txt"}) {
    SCOPED_TRACE(file);
    expectUsageError(run({"--random", "1", "-o", path(file).string()}), "pcd_synth",
                     "-o " + path(file).string() + " looks like a");
    EXPECT_FALSE(fs::exists(path(file)));
  }
}

TEST_F(PcdSynth, HelpListsEveryOptionAndDrawsLabelsAsEveryApp) {
  const Result help = run({"--help"});
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (const std::string option : {"--output-dir", "--random", "--family", "--sequence", "--look-away", "--sensor",
                                   "--seed", "--width", "--height", "--ascii", "--png", "--write-scene", "--quiet",
                                   "--quantize-bits", "--warp", "--speckle", "--bend", "--version"}) {
    EXPECT_TRUE(contains(help.out, option)) << option;
  }
  // The words of every app (cli/cli.h).
  EXPECT_TRUE(contains(help.out, "Write the PCDs as text (default: binary compressed)")) << help.out;
  EXPECT_TRUE(contains(help.out, "near-black where a point is on no plane, white where there is no point (no depth)"))
      << help.out;
}

}  // namespace
}  // namespace floodplane::test
