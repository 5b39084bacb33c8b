// Runs the pcd_synth binary with --random and checks what it writes and says: the outputs of
// every seed and sensor, scenes made again one at a time byte for byte, saved scene files that
// render the same frames, and a clear error and exit code 2 for every bad combination of
// arguments.

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "support/app_run.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

class PcdSynth : public AppTest {
 protected:
  Result run(const std::vector<std::string>& arguments) const {
    return runShell("exec " + commandLine(PCD_SYNTH_BINARY, arguments));
  }

  // Checks the error naming `reason` in its first line, the usage after it (as every
  // floodplane app prints), exit code 2, and that nothing was written.
  void expectRejected(const std::vector<std::string>& arguments, const std::string& reason) const {
    std::vector<std::string> all = arguments;
    all.insert(all.end(), {"-o", path("rejected").string()});
    const Result result = run(all);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_TRUE(contains(result.err, "Usage: pcd_synth")) << result.err;
    const std::string first_line = result.err.substr(0, result.err.find('\n'));
    EXPECT_TRUE(contains(first_line, reason)) << "expected '" << reason << "' in: " << result.err;
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

TEST_F(PcdSynth, BadArgumentsAreRejectedWithAClearMessage) {
  expectRejected({"--random", "0"}, "--random");
  expectRejected({"--random", "2", "scene.json"}, "not both");
  expectRejected({}, "nothing to render");
  expectRejected({"scene.json", "--write-scene"}, "--write-scene");
  expectRejected({"--random", "2", "--seed", "18446744073709551615"}, "runs past the largest seed");
  expectRejected({"--random", "1", "--width", "320", "--height", "240"}, "--width and --height apply to scene files");
  expectRejected({"--random", "1", "--sensor", "lidar"}, "--sensor");
}

}  // namespace
}  // namespace floodplane::test
