// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment in a pipeline: what a batch leaves behind when it is interrupted (SIGINT,
// SIGTERM), when an input's second output cannot be written, when the disk is full, and what
// it says of a directory's entries it cannot read. A later step that skips the inputs whose
// outputs exist must never take an interrupted or failed input for done.

#include <gtest/gtest.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <sys/mount.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pcd_segment_test.h"
#include "support/app_process.h"
#include "support/app_run.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// A width x height pinhole view (a Kinect's f = 525 at 640 columns) of a wall at z = 2 m and a
// floor at y = 0.5 m: two planes.
Cloud wallAndFloor(int width, int height) {
  const double focal = 525.0 * width / 640.0;
  Cloud cloud(width, height);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      const double rx = (u - (width - 1) / 2.0) / focal;
      const double ry = (v - (height - 1) / 2.0) / focal;
      double t = 2.0;
      if (ry > 0.0) t = std::min(t, 0.5 / ry);
      pcl::PointXYZ& p = cloud.at(u, v);
      p.x = static_cast<float>(t * rx);
      p.y = static_cast<float>(t * ry);
      p.z = static_cast<float>(t);
    }
  }
  return cloud;
}

// The entries of `directory` whose names mark them as temporaries (".NAME.tmp.PID.N").
std::vector<std::string> temporariesIn(const fs::path& directory) {
  std::vector<std::string> found;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.find(".tmp.") != std::string::npos) found.push_back(name);
  }
  return found;
}

class PcdSegmentBatch : public PcdSegmentTest {
 protected:
  std::string writeScene(const std::string& name, const Cloud& cloud = wallAndFloor(160, 120)) const {
    const std::string file = path(name).string();
    EXPECT_EQ(pcl::io::savePCDFileBinary(file, cloud), 0);
    return file;
  }

  // Every input named <stem>.pcd in `in` has all of `suffixes` in `out` or none of them, and
  // each labelled cloud there reads back whole. Returns the number of inputs with outputs.
  std::size_t expectAllOrNone(const fs::path& in, const fs::path& out, const std::vector<std::string>& suffixes) const {
    std::size_t complete = 0;
    for (const auto& entry : fs::directory_iterator(in)) {
      const std::string stem = entry.path().stem().string();
      std::size_t present = 0;
      for (const std::string& suffix : suffixes) present += fs::exists(out / (stem + suffix)) ? 1 : 0;
      EXPECT_TRUE(present == 0 || present == suffixes.size()) << stem << ": " << present << " of its outputs";
      if (present == 0) continue;
      ++complete;
      pcl::PointCloud<pcl::PointXYZL> labelled;
      EXPECT_EQ(pcl::io::loadPCDFile((out / (stem + ".labels.pcd")).string(), labelled), 0) << stem;
    }
    return complete;
  }
};

// ---- interrupted --------------------------------------------------------------------------

// Ctrl-C (SIGINT) or SIGTERM while -j 2 workers write: sent as soon as a temporary and a
// finished output are both in the output directory (the batch has started writing and has
// writes under way), so every round interrupts the batch mid-write. Afterwards: no temporary
// left, each input's outputs all there or none, the one-line message, and the end by the
// signal (status 130 or 143). Rounds for both signals, since whether a worker is mid-write at
// that instant varies from round to round.
TEST_F(PcdSegmentBatch, InterruptRemovesTheTemporariesAndEndsByTheSignal) {
  // One large frame under many names (links): a long batch without writing much.
  fs::create_directory(path("in"));
  const std::string frame = writeScene("frame.pcd", wallAndFloor(640, 480));
  constexpr int kInputs = 80;
  for (int i = 0; i < kInputs; ++i) {
    fs::create_symlink(frame, path("in/f" + std::string(i < 10 ? "0" : "") + std::to_string(i) + ".pcd"));
  }
  int round = 0;
  for (const int signal_number : {SIGINT, SIGTERM, SIGINT, SIGTERM, SIGINT, SIGTERM}) {
    const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
    SCOPED_TRACE(name + ", round " + std::to_string(++round));
    const fs::path out = path("out" + std::to_string(round));
    AppProcess app(PCD_SEGMENT_BINARY, {path("in").string(), "-o", out.string(), "--png", "-j", "2", "--quiet"},
                   path("stdout"), path("stderr"));
    ASSERT_TRUE(app.running());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    bool writing = false;
    while (!writing && app.running() && std::chrono::steady_clock::now() < deadline) {
      writing = !temporariesIn(out).empty() && fs::exists(out / "f00.labels.pcd");
      if (!writing) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    ASSERT_TRUE(writing) << "the batch ended or did not start writing: " << readFile(path("stderr"));
    app.signal(signal_number);
    const std::optional<int> exit_code = app.waitFor(std::chrono::seconds(30));
    ASSERT_TRUE(exit_code.has_value()) << "still running 30 s after " << name;
    EXPECT_EQ(*exit_code, 128 + signal_number);
    EXPECT_TRUE(app.endedBySignal()) << "exit(" << *exit_code << ") instead of dying of " << name;
    const std::string err = readFile(path("stderr"));
    EXPECT_EQ(err, "pcd_segment: interrupted by " + name + ": unfinished outputs removed\n");
    EXPECT_EQ(temporariesIn(out), std::vector<std::string>{});
    const std::size_t complete = expectAllOrNone(path("in"), out, {".labels.pcd", ".labels.png"});
    EXPECT_GE(complete, 1u);
    EXPECT_LT(complete, static_cast<std::size_t>(kInputs)) << "the signal came after the batch was done";
  }
}

// ---- an output that cannot be written -----------------------------------------------------

// The second output (the PNG) of an input cannot be put in place, a directory being in the way:
// the input's first output (its labelled cloud) must not be left either, or a step that skips
// inputs with a .labels.pcd would take it for done. The other inputs are written, and the batch
// reports the input and ends with status 1, as for any bad input.
TEST_F(PcdSegmentBatch, AnInputWhoseSecondOutputFailsLeavesNoOutputAtAll) {
  fs::create_directory(path("in"));
  for (const char* name : {"a.pcd", "b.pcd", "c.pcd"}) writeScene(std::string("in/") + name);
  fs::create_directories(path("out/b.labels.png"));
  const Result result = run({path("in").string(), "-o", path("out").string(), "--png", "--json"});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(contains(result.err, "pcd_segment: error: " + path("in/b.pcd").string() + ": cannot write '" +
                                       path("out/b.labels.png").string() + "': Is a directory\n"))
      << result.err;
  EXPECT_TRUE(contains(result.err, "1 of 3 inputs failed")) << result.err;
  EXPECT_EQ(lineCount(result.err), 2u) << result.err;
  EXPECT_FALSE(fs::exists(path("out/b.labels.pcd")));
  EXPECT_FALSE(fs::exists(path("out/b.planes.json")));
  EXPECT_TRUE(fs::is_directory(path("out/b.labels.png"))) << "what was in the way stays";
  EXPECT_EQ(temporariesIn(path("out")), std::vector<std::string>{});
  EXPECT_EQ(lineCount(result.out), 2u) << result.out;
  for (const char* stem : {"a", "c"}) {
    for (const char* suffix : {".labels.pcd", ".labels.png", ".planes.json"}) {
      EXPECT_TRUE(fs::is_regular_file(path(std::string("out/") + stem + suffix))) << stem << suffix;
    }
  }
}

// ---- a full disk --------------------------------------------------------------------------

// A tmpfs small enough to fill part-way through the batch (needs root to mount): sized, from
// a first run on the ordinary disk, to hold two inputs' outputs and the third's labelled cloud
// but not its PNG, so the disk fills up on an input's second output. Each input that does not
// fit is reported with the system's reason, leaves none of its outputs and no temporary; those
// that fit are whole.
TEST_F(PcdSegmentBatch, AFullDiskIsReportedWithTheSystemsReasonAndLeavesNoPartialInput) {
  fs::create_directory(path("in"));
  for (int i = 0; i < 4; ++i) writeScene("in/f" + std::to_string(i) + ".pcd", wallAndFloor(320, 240));
  const std::vector<std::string> arguments = {path("in").string(), "--png", "-j", "1"};
  std::vector<std::string> measured = arguments;
  measured.insert(measured.end(), {"-o", path("measured").string()});
  ASSERT_EQ(run(measured).exit_code, 0);
  const auto pages = [](const fs::path& file) { return (fs::file_size(file) + 4095) / 4096; };
  const std::uintmax_t cloud_pages = pages(path("measured/f0.labels.pcd"));
  const std::uintmax_t image_pages = pages(path("measured/f0.labels.png"));
  const std::string size = "size=" + std::to_string((2 * (cloud_pages + image_pages) + cloud_pages) * 4096);

  const fs::path disk = path("disk");
  fs::create_directory(disk);
  if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, size.c_str()) != 0) {
    GTEST_SKIP() << "cannot mount a small tmpfs here (" << std::strerror(errno) << "): needs root";
  }
  struct Unmount {
    fs::path at;
    ~Unmount() { ::umount2(at.c_str(), MNT_DETACH); }
  } unmount{disk};
  const fs::path out = disk / "out";
  std::vector<std::string> full = arguments;
  full.insert(full.end(), {"-o", out.string()});
  const Result result = run(full);
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(expectAllOrNone(path("in"), out, {".labels.pcd", ".labels.png"}), 2u) << result.err;
  for (const char* stem : {"f2", "f3"}) {
    EXPECT_TRUE(contains(result.err, "pcd_segment: error: " + path("in").string() + "/" + stem +
                                         ".pcd: cannot write '" + out.string() + "/" + stem +
                                         ".labels.png': No space left on device\n"))
        << result.err;
  }
  EXPECT_TRUE(contains(result.err, "2 of 4 inputs failed")) << result.err;
  EXPECT_EQ(lineCount(result.err), 3u) << result.err;
  EXPECT_EQ(temporariesIn(out), std::vector<std::string>{});
}

// ---- an output that is an input ----------------------------------------------------------

// What `directory` holds, file by file: name and bytes.
std::map<std::string, std::string> filesIn(const fs::path& directory) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(directory)) {
    files[entry.path().filename().string()] = entry.is_regular_file() ? readFile(entry.path()) : "(not a file)";
  }
  return files;
}

// The refusal of an output that is an input: the usage error naming both files, and nothing
// written or changed in `directory`, whose files were `before`.
void expectOutputRefused(const Result& result, const std::string& output, const std::string& input,
                         const fs::path& directory, const std::map<std::string, std::string>& before) {
  expectUsageError(result, "pcd_segment", "the output " + output + " would overwrite the input " + input);
  EXPECT_TRUE(result.out.empty()) << result.out;
  const std::map<std::string, std::string> after = filesIn(directory);
  EXPECT_TRUE(after == before) << "an input changed or an output was written: " << after.size() << " files, "
                               << before.size() << " before";
}

// An input named as another input's output would be (frame.labels.pcd, the name pcd_compare
// --labels expects beside frame.pcd): the whole run is refused before any write, whether the
// inputs are given one by one or as their directory, and whether -o names that directory or
// a link to it (the same file found by device and inode, not by name).
TEST_F(PcdSegmentBatch, RefusesToWriteAnOutputOverAnotherInput) {
  fs::create_directory(path("col"));
  const std::string frame = writeScene("col/frame.pcd");
  const std::string labels = writeScene("col/frame.labels.pcd", wallAndFloor(80, 60));
  fs::create_directory_symlink(path("col"), path("alias"));
  const std::map<std::string, std::string> before = filesIn(path("col"));
  ASSERT_EQ(before.size(), 2u);
  expectOutputRefused(run({frame, labels, "-o", path("col").string()}), labels, labels, path("col"), before);
  expectOutputRefused(run({path("col").string(), "-o", path("col").string(), "--png", "--json"}), labels, labels,
                      path("col"), before);
  expectOutputRefused(run({frame, labels, "-o", path("alias").string()}), path("alias/frame.labels.pcd").string(),
                      labels, path("col"), before);
  // A side output too: --json's report over an input of that name (a PCD file named so).
  const std::string report = writeScene("col/frame.planes.json", wallAndFloor(80, 60));
  const std::map<std::string, std::string> with_report = filesIn(path("col"));
  expectOutputRefused(run({frame, report, "-o", path("col").string(), "--json"}), report, report, path("col"),
                      with_report);
  // And --objects' labels over an input of that name.
  const std::string objects = writeScene("col/frame.objects.pcd", wallAndFloor(80, 60));
  const std::map<std::string, std::string> with_objects = filesIn(path("col"));
  expectOutputRefused(run({frame, objects, "-o", path("col").string(), "--objects"}), objects, objects, path("col"),
                      with_objects);
  fs::remove(objects);
  // Without --json the report is no output, and a file that is not an input of the run is
  // an earlier output, replaced as usual.
  const Result replaced = run({frame, report, "-o", path("col").string()});
  EXPECT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_TRUE(readFile(report) == with_report.at("frame.planes.json")) << "an input changed";
  EXPECT_FALSE(readFile(labels) == with_report.at("frame.labels.pcd")) << "the earlier output was not replaced";
}

// ---- what a directory holds ---------------------------------------------------------------

// Entries of an input directory named like inputs that are not files: a directory "x.pcd", a
// symbolic link to nothing, a named pipe (which would block a reader). Each is reported in its
// sorted place as a bad input is, counted in the summary, and the batch ends with status 1; the
// real files are segmented.
TEST_F(PcdSegmentBatch, ReportsEveryEntryOfADirectoryThatIsNotAFile) {
  fs::create_directory(path("in"));
  writeScene("in/a.pcd");
  fs::create_directory(path("in/b.pcd"));
  fs::create_symlink(path("nowhere.pcd"), path("in/c.pcd"));
  ASSERT_EQ(::mkfifo(path("in/d.pcd").c_str(), 0644), 0);
  writeScene("in/e.pcd");
  const Result result = run({path("in").string(), "-o", path("out").string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  const std::string prefix = "pcd_segment: error: " + path("in").string();
  EXPECT_EQ(result.err, prefix + "/b.pcd: is a directory, not a file\n" + prefix +
                            "/c.pcd: is a symbolic link to nothing\n" + prefix +
                            "/d.pcd: is a named pipe, not a file\npcd_segment: 3 of 5 inputs failed\n");
  EXPECT_EQ(lineCount(result.out), 2u) << result.out;
  EXPECT_TRUE(fs::exists(path("out/a.labels.pcd")));
  EXPECT_TRUE(fs::exists(path("out/e.labels.pcd")));
  for (const char* stem : {"b", "c", "d"}) EXPECT_FALSE(fs::exists(path(std::string("out/") + stem + ".labels.pcd")));
}

// A directory holding nothing but such an entry: said of both.
TEST_F(PcdSegmentBatch, ADirectoryWhoseOnlyInputIsADirectoryIsReported) {
  fs::create_directories(path("in/x.pcd"));
  const Result result = run({path("in").string(), "-o", path("out").string()});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_TRUE(contains(result.err, path("in").string() + ": directory contains no .pcd files\n")) << result.err;
  EXPECT_TRUE(contains(result.err, path("in/x.pcd").string() + ": is a directory, not a file\n")) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
}

}  // namespace
}  // namespace floodplane::test
