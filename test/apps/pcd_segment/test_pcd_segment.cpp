// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Runs the pcd_segment binary on clouds written at run time and checks what it writes and
// says: its labels against the library's on the same cloud, its JSON against its PCD, and
// one clear error line and exit code for every kind of bad input.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/fs.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "floodplane/io/label_palette.h"
#include "floodplane/params.h"
#include "floodplane/version.h"
#include "support/app_run.h"
#include "support/library_labels.h"
#include "support/png_images.h"

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;

// A 160x120 pinhole view (a Kinect's f = 525 scaled to the grid) of a wall at z = 2 m and a
// floor at y = 0.5 m that meet at row 92: two planes of known extent, a few NaN holes.
Cloud twoPlaneScene() {
  constexpr int kWidth = 160;
  constexpr int kHeight = 120;
  constexpr double kFocal = 525.0 / 4.0;
  Cloud cloud(kWidth, kHeight);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const double rx = (u - (kWidth - 1) / 2.0) / kFocal;
      const double ry = (v - (kHeight - 1) / 2.0) / kFocal;
      double t = 2.0;                           // the wall, z = 2
      if (ry > 0.0) t = std::min(t, 0.5 / ry);  // the floor, y = 0.5, when nearer
      pcl::PointXYZ& p = cloud.at(u, v);
      p.x = static_cast<float>(t * rx);
      p.y = static_cast<float>(t * ry);
      p.z = static_cast<float>(t);
    }
  }
  // Sensor-style holes: no return for a small block.
  for (int v = 10; v < 14; ++v)
    for (int u = 20; u < 24; ++u)
      cloud.at(u, v).x = cloud.at(u, v).y = cloud.at(u, v).z = std::numeric_limits<float>::quiet_NaN();
  cloud.is_dense = false;
  return cloud;
}

std::vector<std::uint32_t> labelsOf(const pcl::PointCloud<pcl::PointXYZL>& cloud) {
  std::vector<std::uint32_t> out;
  for (const auto& p : cloud) out.push_back(p.label);
  return out;
}

bool sameXyz(const pcl::PointXYZ& a, const pcl::PointXYZL& b) {
  if (!std::isfinite(a.x)) return !std::isfinite(b.x);
  return a.x == b.x && a.y == b.y && a.z == b.z;
}

class PcdSegment : public AppTest {
 protected:
  void SetUp() override {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    AppTest::SetUp();
  }

  // Runs pcd_segment with `arguments`; `prefix` is shell text put before the command
  // (resource limits).
  Result run(const std::vector<std::string>& arguments, const std::string& prefix = "") const {
    return runShell(prefix + "exec " + commandLine(PCD_SEGMENT_BINARY, arguments));
  }

  std::string writeScene(const std::string& name, const Cloud& cloud = twoPlaneScene()) const {
    const std::string file = path(name).string();
    EXPECT_EQ(pcl::io::savePCDFileBinary(file, cloud), 0);
    return file;
  }

  // Checks the one-line error and exit code of a bad input, and that nothing was written.
  void expectRejected(const std::string& input, const std::string& reason) const {
    const Result result = run({input, "-o", path("out").string(), "--png", "--json"});
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(lineCount(result.err), 1u) << result.err;
    EXPECT_TRUE(contains(result.err, input)) << result.err;
    EXPECT_TRUE(contains(result.err, reason)) << "expected '" << reason << "' in: " << result.err;
    EXPECT_TRUE(result.out.empty()) << result.out;
    EXPECT_TRUE(fs::is_empty(path("out"))) << "a rejected input must leave no output";
  }
};

// ---- the good path ------------------------------------------------------------------------

TEST_F(PcdSegment, WritesTheLibrarysLabelsInTheInputsGrid) {
  const Cloud scene = twoPlaneScene();
  const std::string input = writeScene("scene.pcd", scene);
  const Result result = run({input, "-o", path("result.pcd").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;

  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("result.pcd").string(), labelled), 0);
  ASSERT_EQ(labelled.width, scene.width);
  ASSERT_EQ(labelled.height, scene.height);
  for (std::size_t i = 0; i < scene.size(); ++i) ASSERT_TRUE(sameXyz(scene[i], labelled[i])) << "point " << i;
  const std::vector<std::uint32_t> expected = libraryLabels(scene);
  EXPECT_EQ(labelsOf(labelled), expected);
  // The scene has a wall and a floor; fewer would mean the comparison above proved little.
  const std::uint32_t planes = *std::max_element(expected.begin(), expected.end());
  EXPECT_EQ(planes, 2u);
  EXPECT_TRUE(contains(result.out, "scene.pcd: 160x120, 2 planes, ")) << result.out;
  EXPECT_EQ(lineCount(result.out), 1u);
  // Binary compressed unless --ascii is given.
  EXPECT_TRUE(contains(readFile(path("result.pcd")), "DATA binary_compressed\n"));
}

TEST_F(PcdSegment, KeepsTheSensorPoseAndSegmentsInIt) {
  Cloud scene = twoPlaneScene();
  scene.sensor_origin_ = Eigen::Vector4f(0.5f, -1.0f, 2.0f, 0.0f);
  scene.sensor_orientation_ = Eigen::Quaternionf(Eigen::AngleAxisf(0.3f, Eigen::Vector3f(0, 1, 0)));
  const std::string input = writeScene("posed.pcd", scene);
  ASSERT_EQ(run({input, "-o", path("out").string()}).exit_code, 0);

  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/posed.labels.pcd").string(), labelled), 0);
  EXPECT_TRUE(labelled.sensor_origin_.isApprox(scene.sensor_origin_));
  EXPECT_TRUE(labelled.sensor_orientation_.isApprox(scene.sensor_orientation_));
  EXPECT_EQ(labelsOf(labelled), libraryLabels(scene));
}

TEST_F(PcdSegment, PassesEveryParameterToTheLibrary) {
  const Cloud scene = twoPlaneScene();
  const std::string input = writeScene("scene.pcd", scene);
  floodplane::Params params;
  params.distance_threshold = 0.02;
  params.seed_size = 0.1;
  params.angular_threshold = 0.2;
  params.merge_distance = 0.05;
  params.min_inliers = 5000;  // drops the floor (about 4300 points): the labels must change
  params.subsampling = 2;
  params.depth_noise_coefficient = 0.0;
  const Result result = run({input, "-o", path("out").string(), "--json", "--distance-threshold", "0.02", "--seed-size",
                             "0.1", "--angular-threshold", "0.2", "--merge-distance", "0.05", "--min-inliers", "5000",
                             "--subsample", "2", "--depth-noise-coefficient", "0"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/scene.labels.pcd").string(), labelled), 0);
  const std::vector<std::uint32_t> expected = libraryLabels(scene, params);
  EXPECT_EQ(labelsOf(labelled), expected);
  EXPECT_NE(expected, libraryLabels(scene)) << "these parameters should change the result";

  const auto json = nlohmann::json::parse(readFile(path("out/scene.planes.json")));
  const auto& used = json.at("parameters");
  EXPECT_EQ(used.at("distance_threshold"), 0.02);
  EXPECT_EQ(used.at("seed_size"), 0.1);
  EXPECT_EQ(used.at("angular_threshold"), 0.2);
  EXPECT_EQ(used.at("merge_distance"), 0.05);
  EXPECT_EQ(used.at("min_inliers"), 5000);
  EXPECT_EQ(used.at("subsampling"), 2);
  EXPECT_EQ(used.at("depth_noise_coefficient"), 0.0);
}

// twoPlaneScene's wall with a box in front of it: a square of 20 x 20 pixels (27 cm, too small
// to be a support) 20 cm nearer.
Cloud boxScene() {
  Cloud cloud = twoPlaneScene();
  for (int v = 30; v < 50; ++v) {
    for (int u = 60; u < 80; ++u) {
      pcl::PointXYZ& p = cloud.at(u, v);
      const float scale = 1.8f / p.z;
      p.x *= scale;
      p.y *= scale;
      p.z = 1.8f;
    }
  }
  return cloud;
}

TEST_F(PcdSegment, ObjectsAreWrittenAsTheLibraryFindsThemWithTheirJson) {
  const Cloud cloud = boxScene();
  const std::string input = writeScene("scene.pcd", cloud);
  const Result result = run({input, "-o", path("out").string(), "--objects", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> objects;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/scene.objects.pcd").string(), objects), 0);
  ASSERT_EQ(objects.width, cloud.width);
  ASSERT_EQ(objects.height, cloud.height);
  for (std::size_t i = 0; i < cloud.size(); ++i) ASSERT_TRUE(sameXyz(cloud[i], objects[i])) << i;
  std::vector<pcl::PointIndices> indices;
  const std::vector<std::uint32_t> expected = libraryObjectLabels(cloud, &indices);
  EXPECT_EQ(labelsOf(objects), expected);
  // The box, and nothing of the wall or the floor.
  ASSERT_EQ(indices.size(), 1u);
  std::size_t on_box = 0;
  for (int v = 0; v < static_cast<int>(objects.height); ++v) {
    for (int u = 0; u < static_cast<int>(objects.width); ++u) {
      const bool box = u >= 60 && u < 80 && v >= 30 && v < 50;
      if (!box) {
        EXPECT_EQ(objects.at(u, v).label, 0u) << u << "," << v;
      }
      on_box += box && objects.at(u, v).label == 1;
    }
  }
  EXPECT_GT(on_box, 380u);
  EXPECT_EQ(indices[0].indices.size(), on_box);
  const auto json = nlohmann::json::parse(readFile(path("out/scene.planes.json")));
  ASSERT_EQ(json.at("object_count"), 1);
  const auto& box = json.at("objects").at(0);
  EXPECT_EQ(box.at("id"), 1);
  EXPECT_EQ(box.at("pixels"), on_box);
  EXPECT_EQ(box.at("support"), 1) << "it stands on the wall, the largest plane";
  EXPECT_NEAR(box.at("centroid")[2].get<double>(), 1.8, 1e-4);
  EXPECT_NEAR(box.at("min")[2].get<double>(), 1.8, 1e-4);
  EXPECT_GE(json.at("objects_ms").get<double>(), 0.0);
  // Without --objects, no objects file and no objects in the JSON.
  ASSERT_EQ(run({input, "-o", path("plain").string(), "--json"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(path("plain/scene.objects.pcd")));
  EXPECT_FALSE(nlohmann::json::parse(readFile(path("plain/scene.planes.json"))).contains("objects"));
}

// Sets or clears a file's immutable flag (chattr +i / -i); false where that cannot be done
// (not root, a file system without the flag).
bool setImmutable(const fs::path& file, bool immutable) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  int flags = 0;
  bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
  if (done) {
    flags = immutable ? (flags | FS_IMMUTABLE_FL) : (flags & ~FS_IMMUTABLE_FL);
    done = ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
  }
  ::close(fd);
  return done;
}

// A rerun over an earlier run's outputs whose commit fails on one of them (made immutable):
// the earlier run's outputs are all kept, whichever of them cannot be replaced.
TEST_F(PcdSegment, ARerunThatCannotReplaceOneOutputKeepsAllTheEarlierOnes) {
  const std::string input = writeScene("x.pcd", boxScene());
  const std::vector<std::string> outputs = {"x.labels.pcd", "x.objects.pcd", "x.planes.json"};
  for (const std::string stuck : {"x.objects.pcd", "x.planes.json", "x.labels.pcd"}) {
    SCOPED_TRACE(stuck);
    const fs::path out = path("out_" + stuck.substr(2, stuck.find('.', 2) - 2));  // no dot: a directory
    ASSERT_EQ(run({input, "-o", out.string(), "--objects", "--json"}).exit_code, 0);
    // The earlier run's files, told apart from the rerun's (which would write the same bytes).
    std::map<std::string, std::string> earlier;
    for (const std::string& name : outputs) {
      earlier[name] = readFile(out / name) + "\n";
      writeFile(out / name, earlier[name]);
    }
    if (!setImmutable(out / stuck, true)) GTEST_SKIP() << "cannot make a file immutable here";
    const Result rerun = run({input, "-o", out.string(), "--objects", "--json"});
    setImmutable(out / stuck, false);
    EXPECT_EQ(rerun.exit_code, 1) << rerun.err;
    EXPECT_TRUE(contains(rerun.err, stuck)) << rerun.err;
    for (const std::string& name : outputs) EXPECT_EQ(readFile(out / name), earlier[name]) << name;
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(out)) ++entries;
    EXPECT_EQ(entries, outputs.size()) << "no temporary nor kept copy left";
  }
}

// With --track the labels hold track ids, and each object's "support" names its plane the
// same way. The first frame sees more floor than wall, the second (a ball on the wall) more
// wall: the wall's size rank changes, its track id does not.
TEST_F(PcdSegment, AnObjectsSupportUnderTrackIsTheLabelOfItsPlane) {
  Cloud first = twoPlaneScene();
  for (int v = 0; v < 76; ++v)
    for (int u = 0; u < static_cast<int>(first.width); ++u)
      first.at(u, v).x = first.at(u, v).y = first.at(u, v).z = std::numeric_limits<float>::quiet_NaN();
  fs::create_directory(path("seq"));
  writeScene("seq/000.pcd", first);
  // A ball in front of the wall: an object, never a plane.
  Cloud second = twoPlaneScene();
  for (int v = 30; v < 50; ++v) {
    for (int u = 60; u < 80; ++u) {
      const double r2 = ((u - 69.5) * (u - 69.5) + (v - 39.5) * (v - 39.5)) / 100.0;
      if (r2 >= 1.0) continue;
      pcl::PointXYZ& p = second.at(u, v);
      const float scale = static_cast<float>(1.8 - 0.15 * std::sqrt(1.0 - r2)) / p.z;
      p.x *= scale;
      p.y *= scale;
      p.z *= scale;
    }
  }
  writeScene("seq/001.pcd", second);
  const Result result = run({path("seq").string(), "-o", path("out").string(), "--track", "--objects", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> labels;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/001.labels.pcd").string(), labels), 0);
  const std::uint32_t wall = labels.at(10, 10).label;
  const auto json = nlohmann::json::parse(readFile(path("out/001.planes.json")));
  ASSERT_EQ(json.at("object_count"), 1) << json.dump();
  EXPECT_NE(wall, 1u) << "the wall's track id is its rank: the scene tells nothing";
  EXPECT_EQ(json.at("objects").at(0).at("support"), wall) << "the ball stands on the wall";
}

TEST_F(PcdSegment, JsonAgreesWithThePcdAndPngSitsNextToIt) {
  const std::string input = writeScene("scene.pcd", twoPlaneScene());
  const Result result = run({input, "-o", path("res/labels.pcd").string(), "--png", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;

  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("res/labels.pcd").string(), labelled), 0);
  std::map<std::uint32_t, std::size_t> count;
  std::map<std::uint32_t, std::array<int, 4>> box;  // min column, max column, min row, max row
  for (int v = 0; v < static_cast<int>(labelled.height); ++v) {
    for (int u = 0; u < static_cast<int>(labelled.width); ++u) {
      const std::uint32_t label = labelled.at(u, v).label;
      if (label == 0) continue;
      auto [it, fresh] = box.try_emplace(label, std::array<int, 4>{u, u, v, v});
      auto& b = it->second;
      b = {std::min(b[0], u), std::max(b[1], u), std::min(b[2], v), std::max(b[3], v)};
      ++count[label];
      (void)fresh;
    }
  }

  // Single-file mode: <stem>.png and <stem>.json next to the PCD.
  const auto json = nlohmann::json::parse(readFile(path("res/labels.json")));
  ASSERT_EQ(json.at("planes").size(), count.size());
  ASSERT_EQ(count.size(), 2u);
  EXPECT_EQ(json.at("plane_count"), count.size());
  EXPECT_EQ(json.at("width"), 160);
  EXPECT_EQ(json.at("height"), 120);
  EXPECT_GT(json.at("segmentation_ms").get<double>(), 0.0) << "the time is measured, not left at 0";
  std::size_t previous_inliers = std::numeric_limits<std::size_t>::max();
  for (const auto& plane : json.at("planes")) {
    const std::uint32_t id = plane.at("id");
    ASSERT_EQ(count.count(id), 1u) << "plane " << id << " has no labelled points";
    EXPECT_EQ(plane.at("inliers").get<std::size_t>(), count[id]);
    EXPECT_LE(count[id], previous_inliers) << "labels are numbered by size, largest first";
    previous_inliers = count[id];
    const auto& n = plane.at("normal");
    EXPECT_NEAR(std::hypot(n[0].get<double>(), n[1].get<double>(), n[2].get<double>()), 1.0, 1e-5);
    // The centroid lies on the plane it describes.
    const auto& c = plane.at("centroid");
    EXPECT_NEAR(n[0].get<double>() * c[0].get<double>() + n[1].get<double>() * c[1].get<double>() +
                    n[2].get<double>() * c[2].get<double>() + plane.at("d").get<double>(),
                0.0, 1e-4);
    // Each plane here is one connected region, so its outer boundary spans all its pixels.
    const auto& b = plane.at("boundary_box");
    EXPECT_EQ(b.at("min_column"), box[id][0]);
    EXPECT_EQ(b.at("max_column"), box[id][1]);
    EXPECT_EQ(b.at("min_row"), box[id][2]);
    EXPECT_EQ(b.at("max_row"), box[id][3]);
  }
  // The wall (z = 2, normal towards the camera) is the larger plane.
  EXPECT_NEAR(json["planes"][0]["normal"][2].get<double>(), -1.0, 1e-3);
  EXPECT_NEAR(json["planes"][0]["d"].get<double>(), 2.0, 1e-3);

  const std::string png = readFile(path("res/labels.png"));
  ASSERT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  // IHDR: big-endian width and height at bytes 16 and 20.
  const auto be32 = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(png[at])) << 24) | (std::uint32_t(std::uint8_t(png[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(png[at + 2])) << 8) | std::uint32_t(std::uint8_t(png[at + 3]));
  };
  EXPECT_EQ(be32(16), 160u);
  EXPECT_EQ(be32(20), 120u);
}

// A file name that is not UTF-8 (Latin-1 bytes, a name cut in a multi-byte character): the
// report is valid JSON, each ill-formed part of the name written as U+FFFD, the rule of
// nlohmann's replace and of Python's bytes.decode("utf-8", "replace").
TEST_F(PcdSegment, JsonOfANameThatIsNotUtf8IsValidWithTheBadBytesReplaced) {
  fs::create_directory(path("in"));
  const std::string name = "caf\xe9_\xe2\x82.pcd";  // é in Latin-1; € cut after two of its three bytes
  const std::string input = writeScene("in/" + name);
  const Result result = run({path("in").string(), "-o", path("out").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string text = readFile(path("out/caf\xe9_\xe2\x82.planes.json"));
  ASSERT_FALSE(text.empty());
  nlohmann::json json;
  ASSERT_NO_THROW(json = nlohmann::json::parse(text));
  const std::string replaced = path("in").string() + "/caf\xef\xbf\xbd_\xef\xbf\xbd.pcd";
  EXPECT_EQ(json.at("input").get<std::string>(), replaced);
  EXPECT_EQ(json.at("plane_count"), 2);
}

TEST_F(PcdSegment, KeepsColourWhenTheInputHasIt) {
  const Cloud scene = twoPlaneScene();
  pcl::PointCloud<pcl::PointXYZRGB> coloured;
  pcl::copyPointCloud(scene, coloured);
  for (std::size_t i = 0; i < coloured.size(); ++i) {
    coloured[i].r = static_cast<std::uint8_t>(i);
    coloured[i].g = static_cast<std::uint8_t>(i / 7);
    coloured[i].b = static_cast<std::uint8_t>(255 - i % 200);
  }
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("rgb.pcd").string(), coloured), 0);
  const Result result = run({path("rgb.pcd").string(), "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;

  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/rgb.labels.pcd").string(), blob), 0);
  const bool has_colour = std::any_of(blob.fields.begin(), blob.fields.end(),
                                      [](const auto& f) { return f.name == "rgb" || f.name == "rgba"; });
  EXPECT_TRUE(has_colour);
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/rgb.labels.pcd").string(), labelled), 0);
  ASSERT_EQ(labelled.size(), coloured.size());
  std::vector<std::uint32_t> labels;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    ASSERT_EQ(labelled[i].r, coloured[i].r) << i;
    ASSERT_EQ(labelled[i].g, coloured[i].g) << i;
    ASSERT_EQ(labelled[i].b, coloured[i].b) << i;
    labels.push_back(labelled[i].label);
  }
  EXPECT_EQ(labels, libraryLabels(scene));
}

// The label PNG has a pixel per point: each plane in its palette colour, a finite point on no
// plane near-black, a pixel without a point (no depth) white.
TEST_F(PcdSegment, LabelPngPaintsPlanesNoPlaneAndHolesApart) {
  Cloud scene = twoPlaneScene();
  // Points scattered along their rays, on no surface: finite, and on no plane.
  for (int v = 30; v < 42; ++v) {
    for (int u = 100; u < 112; ++u) {
      const float scale = 0.5f + 0.07f * static_cast<float>((u * 7 + v * 13) % 10);
      pcl::PointXYZ& p = scene.at(u, v);
      p.x *= scale;
      p.y *= scale;
      p.z *= scale;
    }
  }
  const std::string input = writeScene("scene.pcd", scene);
  ASSERT_EQ(run({input, "-o", path("out").string(), "--png"}).exit_code, 0);
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/scene.labels.pcd").string(), labelled), 0);
  const floodplane::io::RgbImage image = readPng(path("out/scene.labels.png"));
  ASSERT_EQ(image.width, labelled.width);
  ASSERT_EQ(image.height, labelled.height);
  std::size_t holes = 0, no_plane = 0, planes = 0;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    const bool finite = std::isfinite(labelled[i].z);
    const std::array<std::uint8_t, 3> expected =
        finite ? floodplane::io::labelColor(labelled[i].label) : floodplane::io::kHoleColor;
    const std::array<std::uint8_t, 3> pixel{image.pixels[3 * i], image.pixels[3 * i + 1], image.pixels[3 * i + 2]};
    ASSERT_EQ(pixel, expected) << "pixel " << i << ", label " << labelled[i].label;
    holes += finite ? 0 : 1;
    no_plane += finite && labelled[i].label == 0 ? 1 : 0;
    planes += labelled[i].label != 0 ? 1 : 0;
  }
  EXPECT_EQ(holes, 16u) << "the scene's block without returns";
  EXPECT_GE(no_plane, 50u) << "the scattered points";
  EXPECT_GT(planes, labelled.size() / 2);
  EXPECT_NE(floodplane::io::kHoleColor, floodplane::io::kNoPlaneColor);
}

// --overlay: the input's own colours with each plane's colour blended half over it, holes white.
TEST_F(PcdSegment, OverlayBlendsThePlaneColoursOverTheInputsColours) {
  const Cloud scene = twoPlaneScene();
  pcl::PointCloud<pcl::PointXYZRGB> coloured;
  pcl::copyPointCloud(scene, coloured);
  for (std::size_t i = 0; i < coloured.size(); ++i) {
    coloured[i].r = static_cast<std::uint8_t>(i);
    coloured[i].g = static_cast<std::uint8_t>(i / 7);
    coloured[i].b = static_cast<std::uint8_t>(255 - i % 200);
  }
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("rgb.pcd").string(), coloured), 0);
  const Result result = run({path("rgb.pcd").string(), "-o", path("one/frame.pcd").string(), "--overlay"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("one/frame.pcd").string(), labelled), 0);
  const floodplane::io::RgbImage overlay = readPng(path("one/frame.overlay.png"));
  ASSERT_EQ(overlay.width, labelled.width);
  ASSERT_EQ(overlay.height, labelled.height);
  std::size_t blended = 0;
  for (std::size_t i = 0; i < labelled.size(); ++i) {
    const std::array<int, 3> own{coloured[i].r, coloured[i].g, coloured[i].b};
    const bool finite = std::isfinite(labelled[i].z);
    const bool on_plane = labelled[i].label != 0 && finite;
    const auto colour = floodplane::io::labelColor(labelled[i].label);
    for (std::size_t c = 0; c < 3; ++c) {
      const int expected = !finite ? floodplane::io::kHoleColor[c] : on_plane ? (own[c] + colour[c] + 1) / 2 : own[c];
      ASSERT_EQ(overlay.pixels[3 * i + c], expected) << "pixel " << i << ", channel " << c;
    }
    blended += on_plane ? 1 : 0;
  }
  EXPECT_GT(blended, labelled.size() / 2);
}

// An input without colour gets a note, not an overlay and not an error; the batch goes on.
TEST_F(PcdSegment, OverlayOfAnInputWithoutColourIsANote) {
  const std::string input = writeScene("plain.pcd");
  const Result result = run({input, "-o", path("out").string(), "--overlay"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_TRUE(contains(result.err, "pcd_segment: note: " + input + ": no colour")) << result.err;
  EXPECT_TRUE(fs::exists(path("out/plain.labels.pcd")));
  EXPECT_FALSE(fs::exists(path("out/plain.overlay.png")));
  const Result quiet = run({input, "-o", path("out").string(), "--overlay", "-q"});
  ASSERT_EQ(quiet.exit_code, 0);
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
}

TEST_F(PcdSegment, WritesNoColourFieldWhenTheInputHasNone) {
  const std::string input = writeScene("plain.pcd");
  ASSERT_EQ(run({input, "-o", path("out").string()}).exit_code, 0);
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/plain.labels.pcd").string(), blob), 0);
  std::string names;
  for (const auto& field : blob.fields) names += field.name + " ";
  EXPECT_EQ(names, "x y z label ");
}

TEST_F(PcdSegment, AcceptsCloudsWithOtherFields) {
  // Normals, curvature and intensity besides x y z: only x y z matter.
  const Cloud scene = twoPlaneScene();
  pcl::PointCloud<pcl::PointXYZINormal> rich;
  pcl::copyPointCloud(scene, rich);
  for (auto& p : rich) p.intensity = 7.0f;
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path("rich.pcd").string(), rich), 0);
  const Result result = run({path("rich.pcd").string(), "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/rich.labels.pcd").string(), labelled), 0);
  EXPECT_EQ(labelsOf(labelled), libraryLabels(scene));
}

TEST_F(PcdSegment, ReadsDoublePrecisionCoordinates) {
  // Hand-written: PCL's point types have float coordinates. 4x3 grid, too small for planes.
  std::string text =
      "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 3\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 12\nDATA ascii\n";
  for (int i = 0; i < 12; ++i) text += std::to_string(0.25 * i) + " 0.5 1.5\n";
  writeFile(path("double.pcd"), text);
  const Result result = run({path("double.pcd").string(), "-o", path("out.pcd").string(), "--ascii"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out.pcd").string(), labelled), 0);
  ASSERT_EQ(labelled.size(), 12u);
  EXPECT_FLOAT_EQ(labelled[5].x, 1.25f);
  EXPECT_FLOAT_EQ(labelled[5].z, 1.5f);
}

TEST_F(PcdSegment, AsciiOptionWritesTextThatReadsBackTheSame) {
  const Cloud scene = twoPlaneScene();
  const std::string input = writeScene("scene.pcd", scene);
  const Result result = run({input, "-o", path("out").string(), "--ascii"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string text = readFile(path("out/scene.labels.pcd"));
  EXPECT_TRUE(contains(text, "\nDATA ascii\n"));
  EXPECT_TRUE(std::all_of(text.begin(), text.end(), [](char c) { return c == '\n' || (c >= 32 && c < 127); }))
      << "ASCII output holds a non-printable byte";
  EXPECT_EQ(lineCount(text), 11u + scene.size()) << "11 header lines and one line per point";
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/scene.labels.pcd").string(), labelled), 0);
  EXPECT_EQ(labelled.width, scene.width);
  EXPECT_EQ(labelled.height, scene.height);
  for (std::size_t i = 0; i < scene.size(); ++i) ASSERT_TRUE(sameXyz(scene[i], labelled[i])) << "point " << i;
  EXPECT_EQ(labelsOf(labelled), libraryLabels(scene));
}

TEST_F(PcdSegment, ProcessesADirectorysPcdFilesInSortedOrder) {
  fs::create_directory(path("in"));
  for (const char* name : {"c.pcd", "a.pcd", "b.pcd"}) writeScene(std::string("in/") + name);
  writeFile(path("in/notes.txt"), "not a cloud");
  const Result result = run({path("in").string(), "-o", path("out").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::size_t a = result.out.find("a.pcd:");
  const std::size_t b = result.out.find("b.pcd:");
  const std::size_t c = result.out.find("c.pcd:");
  ASSERT_NE(a, std::string::npos);
  ASSERT_NE(b, std::string::npos);
  ASSERT_NE(c, std::string::npos);
  EXPECT_LT(a, b);
  EXPECT_LT(b, c);
  EXPECT_EQ(lineCount(result.out), 3u);
  for (const char* name : {"a", "b", "c"}) EXPECT_TRUE(fs::exists(path(std::string("out/") + name + ".labels.pcd")));
  EXPECT_FALSE(fs::exists(path("out/notes.labels.pcd")));
  // Four or more files would draw a progress bar on a terminal; stderr here is a file.
  EXPECT_TRUE(result.err.empty());
}

TEST_F(PcdSegment, DrawsNoProgressBarWhenStderrIsNotATerminal) {
  std::vector<std::string> arguments;
  for (int i = 0; i < 5; ++i) arguments.push_back(writeScene("f" + std::to_string(i) + ".pcd"));
  arguments.insert(arguments.end(), {"-o", path("out").string()});
  const Result result = run(arguments);
  ASSERT_EQ(result.exit_code, 0);
  EXPECT_EQ(lineCount(result.out), 5u);
  EXPECT_TRUE(result.err.empty()) << "progress output in a log: " << result.err;
}

TEST_F(PcdSegment, DrawsAProgressBarWhenStderrIsATerminal) {
  // util-linux script(1) gives the program a pseudo-terminal and copies what it shows.
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "script(1) not installed";
  std::string command = quote(PCD_SEGMENT_BINARY);
  for (int i = 0; i < 4; ++i) command += " " + quote(writeScene("f" + std::to_string(i) + ".pcd"));
  command += " -o " + quote(path("out").string());
  const fs::path screen = path("screen.txt");
  const std::string shell = "script -qec " + quote(command) + " /dev/null >" + quote(screen.string()) + " 2>&1";
  ASSERT_EQ(std::system(("sh -c " + quote(shell)).c_str()), 0);
  const std::string shown = readFile(screen);
  EXPECT_TRUE(contains(shown, "] 0/4 files")) << shown;
  EXPECT_TRUE(contains(shown, "] 3/4 files, about ")) << shown;
  EXPECT_TRUE(contains(shown, " s left")) << shown;
  EXPECT_TRUE(contains(shown, "f3.pcd: 160x120, 2 planes")) << shown;
}

TEST_F(PcdSegment, BatchGoesOnPastABadFileAndExitsWithOne) {
  const std::string first = writeScene("first.pcd");
  writeFile(path("bad.pcd"), "this is not a point cloud\n");
  const std::string last = writeScene("last.pcd");
  const Result result = run({first, path("bad.pcd").string(), last, "-o", path("out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_TRUE(fs::exists(path("out/first.labels.pcd")));
  EXPECT_TRUE(fs::exists(path("out/last.labels.pcd")));
  EXPECT_FALSE(fs::exists(path("out/bad.labels.pcd")));
  EXPECT_EQ(lineCount(result.out), 2u);
  EXPECT_TRUE(contains(result.err, path("bad.pcd").string() + ": not a PCD file")) << result.err;
  EXPECT_TRUE(contains(result.err, "1 of 3 inputs failed")) << result.err;
}

// -j 3 over seven inputs, one of them broken: every output byte for byte that of -j 1, and
// the same lines on stdout and stderr in input order (the times aside), whichever thread
// finishes first. The scenes differ (scaled), so swapped outputs would show.
TEST_F(PcdSegment, SegmentsInParallelExactlyAsOneAtATime) {
  fs::create_directory(path("in"));
  for (int i = 0; i < 7; ++i) {
    const std::string name = "in/f" + std::to_string(i) + ".pcd";
    if (i == 3) {
      writeFile(path(name), "not a point cloud\n");
      continue;
    }
    Cloud cloud = twoPlaneScene();
    for (pcl::PointXYZ& p : cloud) {
      p.x *= 1.0f + 0.1f * static_cast<float>(i);
      p.y *= 1.0f + 0.1f * static_cast<float>(i);
      p.z *= 1.0f + 0.1f * static_cast<float>(i);
    }
    writeScene(name, cloud);
  }
  const auto withoutTimes = [](std::string text, const std::string& out_dir) {
    std::string kept;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      const std::size_t ms = line.find(" ms -> ");
      if (ms != std::string::npos) line = line.substr(0, line.rfind(", ", ms)) + line.substr(ms + 3);
      const std::size_t dir = line.find(out_dir);
      if (dir != std::string::npos) line.replace(dir, out_dir.size(), "OUT");
      kept += line + "\n";
    }
    return kept;
  };
  const std::string serial_dir = path("serial").string();
  const std::string parallel_dir = path("parallel").string();
  const Result serial = run({path("in").string(), "-o", serial_dir, "--png", "--json", "-j", "1"});
  const Result parallel = run({path("in").string(), "-o", parallel_dir, "--png", "--json", "-j", "3"});
  EXPECT_EQ(serial.exit_code, 1) << serial.err;
  EXPECT_EQ(parallel.exit_code, 1) << parallel.err;
  EXPECT_EQ(lineCount(serial.out), 6u) << serial.out << serial.err;
  EXPECT_EQ(withoutTimes(parallel.out, parallel_dir), withoutTimes(serial.out, serial_dir));
  EXPECT_EQ(parallel.err, serial.err);
  EXPECT_TRUE(contains(parallel.err, "f3.pcd: not a PCD file")) << parallel.err;
  std::size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(serial_dir)) {
    const fs::path name = entry.path().filename();
    if (name.extension() == ".json") continue;  // holds the time of the call
    EXPECT_EQ(readFile(fs::path(parallel_dir) / name), readFile(entry.path())) << name;
    ++compared;
  }
  EXPECT_EQ(compared, 12u);  // six label PCDs and six PNGs
  for (int i : {0, 1, 2, 4, 5, 6}) {
    nlohmann::json a =
        nlohmann::json::parse(readFile(fs::path(serial_dir) / ("f" + std::to_string(i) + ".planes.json")));
    nlohmann::json b =
        nlohmann::json::parse(readFile(fs::path(parallel_dir) / ("f" + std::to_string(i) + ".planes.json")));
    a.erase("segmentation_ms");
    b.erase("segmentation_ms");
    EXPECT_EQ(a, b) << i;
  }
}

TEST_F(PcdSegment, QuietPrintsNothingOnSuccess) {
  const Result result = run({writeScene("scene.pcd"), "-o", path("out").string(), "--quiet"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_TRUE(result.err.empty()) << result.err;
}

// A frame with no finite point is a valid frame with no planes (the rule of the Python module
// and the ROS node): every output written, exit code 0, a one-line note.
TEST_F(PcdSegment, AllNanCloudGivesZeroPlanesAndAllOutputs) {
  Cloud empty(40, 30);
  for (auto& p : empty) p.x = p.y = p.z = std::numeric_limits<float>::quiet_NaN();
  empty.is_dense = false;
  const std::string input = writeScene("nan.pcd", empty);
  const Result result = run({input, "-o", path("out").string(), "--png", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "nan.pcd: 40x30, 0 planes")) << result.out;
  EXPECT_EQ(result.err, "pcd_segment: note: " + input +
                            ": no point has a finite x y z (all NaN, or no depth): a frame with no planes\n");
  pcl::PointCloud<pcl::PointXYZL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/nan.labels.pcd").string(), labelled), 0);
  EXPECT_EQ(labelled.size(), 1200u);
  for (const auto& p : labelled) EXPECT_EQ(p.label, 0u);
  EXPECT_TRUE(fs::exists(path("out/nan.labels.png")));
  const auto json = nlohmann::json::parse(readFile(path("out/nan.planes.json")));
  EXPECT_EQ(json.at("plane_count"), 0);
  EXPECT_TRUE(json.at("planes").empty());
  // --quiet: no note, and in a batch the empty frame is no failure of the others.
  const Result quiet = run({input, "-o", path("quiet").string(), "--quiet"});
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
  const Result batch = run({input, writeScene("scene.pcd"), "-o", path("batch").string()});
  EXPECT_EQ(batch.exit_code, 0) << batch.err;
  EXPECT_EQ(lineCount(batch.err), 1u) << batch.err;
  EXPECT_TRUE(contains(batch.out, "scene.pcd: 160x120, 2 planes")) << batch.out;
}

// Frames too small to hold much are segmented like any other, never refused: a 2 x 2 grid, a
// single column, a grid of two finite points.
TEST_F(PcdSegment, TinyFramesAreSegmentedAndWritten) {
  const Cloud scene = twoPlaneScene();
  for (const auto& [width, height, finite] :
       std::vector<std::array<std::uint32_t, 3>>{{2, 2, 4}, {1, 5, 5}, {2, 2, 2}}) {
    const std::string name = std::to_string(width) + "x" + std::to_string(height) + "_" + std::to_string(finite);
    SCOPED_TRACE(name);
    Cloud tiny(width, height);
    for (std::uint32_t i = 0; i < tiny.size(); ++i) {
      tiny[i] = scene.at(static_cast<int>(80 + i % width), static_cast<int>(40 + i / width));
      if (i >= finite) tiny[i].x = tiny[i].y = tiny[i].z = std::numeric_limits<float>::quiet_NaN();
    }
    tiny.is_dense = finite == tiny.size();
    const Result result =
        run({writeScene(name + ".pcd", tiny), "-o", path("out/" + name + ".pcd").string(), "--png", "--json"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;
    pcl::PointCloud<pcl::PointXYZL> labelled;
    ASSERT_EQ(pcl::io::loadPCDFile(path("out/" + name + ".pcd").string(), labelled), 0);
    EXPECT_EQ(labelled.width, width);
    EXPECT_EQ(labelled.height, height);
    EXPECT_TRUE(fs::exists(path("out/" + name + ".png")));
    const auto json = nlohmann::json::parse(readFile(path("out/" + name + ".json")));
    if (finite < 3) {
      EXPECT_EQ(json.at("plane_count"), 0);
    }
  }
}

// ---- bad input ----------------------------------------------------------------------------

TEST_F(PcdSegment, RejectsAMissingFile) {
  fs::create_directory(path("out"));
  expectRejected(path("missing.pcd").string(), "no such file");
}

TEST_F(PcdSegment, RejectsADirectoryWithoutPcdFiles) {
  fs::create_directory(path("out"));
  fs::create_directory(path("empty"));
  writeFile(path("empty/readme.txt"), "x");
  expectRejected(path("empty").string(), "no .pcd files");
}

TEST_F(PcdSegment, RejectsAnEmptyFile) {
  fs::create_directory(path("out"));
  writeFile(path("empty.pcd"), "");
  expectRejected(path("empty.pcd").string(), "empty file");
}

TEST_F(PcdSegment, RejectsAFileThatIsNotAPcd) {
  fs::create_directory(path("out"));
  std::string noise;
  for (int i = 0; i < 4096; ++i) noise += static_cast<char>((i * 7919) % 256);
  writeFile(path("noise.pcd"), noise);
  expectRejected(path("noise.pcd").string(), "not a PCD file");
}

TEST_F(PcdSegment, RejectsATruncatedCompressedPcd) {
  // PCL's reader trusts the compressed size in the file and reads past the end of a
  // truncated one; the app must catch this before PCL sees the file.
  fs::create_directory(path("out"));
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path("full.pcd").string(), twoPlaneScene()), 0);
  const std::string full = readFile(path("full.pcd"));
  for (const double fraction : {0.1, 0.5, 0.99}) {
    const std::string name = "cut" + std::to_string(static_cast<int>(fraction * 100)) + ".pcd";
    writeFile(path(name), full.substr(0, static_cast<std::size_t>(static_cast<double>(full.size()) * fraction)));
    SCOPED_TRACE(name);
    expectRejected(path(name).string(), "truncated");
  }
}

TEST_F(PcdSegment, RejectsATruncatedBinaryOrAsciiPcd) {
  fs::create_directory(path("out"));
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("binary.pcd").string(), twoPlaneScene()), 0);
  const std::string binary = readFile(path("binary.pcd"));
  writeFile(path("binary_cut.pcd"), binary.substr(0, binary.size() * 2 / 3));
  expectRejected(path("binary_cut.pcd").string(), "truncated");

  ASSERT_EQ(pcl::io::savePCDFileASCII(path("ascii.pcd").string(), twoPlaneScene()), 0);
  const std::string ascii = readFile(path("ascii.pcd"));
  writeFile(path("ascii_cut.pcd"), ascii.substr(0, ascii.size() * 2 / 3));
  expectRejected(path("ascii_cut.pcd").string(), "truncated");
}

TEST_F(PcdSegment, RejectsCorruptCompressedData) {
  fs::create_directory(path("out"));
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path("full.pcd").string(), twoPlaneScene()), 0);
  const std::string full = readFile(path("full.pcd"));
  const std::size_t data = full.find("DATA binary_compressed\n") + 23;
  ASSERT_LT(data + 200, full.size());

  // The uncompressed size field (second uint32 after the header) no longer matches the grid.
  std::string wrong_size = full;
  wrong_size[data + 4] = static_cast<char>(wrong_size[data + 4] + 1);
  writeFile(path("wrong_size.pcd"), wrong_size);
  expectRejected(path("wrong_size.pcd").string(), "corrupt");

  // The LZF stream itself is garbage: back-references before the start of the output.
  std::string garbage = full;
  std::fill(garbage.begin() + static_cast<std::ptrdiff_t>(data + 8),
            garbage.begin() + static_cast<std::ptrdiff_t>(data + 200), '\xff');
  writeFile(path("garbage.pcd"), garbage);
  expectRejected(path("garbage.pcd").string(), "corrupt");
}

TEST_F(PcdSegment, RejectsAHeaderThatAnnouncesMorePointsThanTheFileHolds) {
  // PCL allocates what the header announces before reading: 20000 x 20000 points would be
  // 4.8 GB of zeros. The app must refuse at once, not allocate.
  fs::create_directory(path("out"));
  for (const char* data : {"ascii", "binary", "binary_compressed"}) {
    const std::string name = std::string("huge_") + data + ".pcd";
    writeFile(path(name), std::string("VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 20000\n"
                                      "HEIGHT 20000\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 400000000\nDATA ") +
                              data + "\n" + std::string(1000, '\0'));
    SCOPED_TRACE(name);
    expectRejected(path(name).string(), "cannot hold");
  }
}

TEST_F(PcdSegment, RejectsAnUnorganizedCloud) {
  fs::create_directory(path("out"));
  Cloud scene = twoPlaneScene();
  scene.width = static_cast<std::uint32_t>(scene.size());
  scene.height = 1;
  writeScene("flat.pcd", scene);
  expectRejected(path("flat.pcd").string(), "needs an organized cloud");
}

TEST_F(PcdSegment, RejectsACloudWithoutXyz) {
  fs::create_directory(path("out"));
  pcl::PointCloud<pcl::Normal> normals(16, 12);
  for (auto& n : normals) n.normal_z = 1.0f;
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("normals.pcd").string(), normals), 0);
  expectRejected(path("normals.pcd").string(), "no x y z");
}

// One line naming the flag, not the library's field or setter, and not the whole help.
TEST_F(PcdSegment, RejectsBadOptionValuesInOneLineNamingTheFlag) {
  const std::string input = writeScene("scene.pcd");
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--distance-threshold", "-0.01"}, "--distance-threshold must be"},
      {{"--seed-size", "0"}, "--seed-size must be"},
      {{"--angular-threshold", "2"}, "--angular-threshold must be"},
      {{"--merge-distance", "nan"}, "--merge-distance must be"},
      {{"--subsample", "3"}, "--subsample must be 1, 2, 4 or 8, got 3"},
      {{"--min-inliers", "-4"}, "--min-inliers"},
      {{"--maximum-curvature", "-1"}, "--maximum-curvature must be"},
      {{"--seed-size", "abc"}, "--seed-size"},
      {{"--depth-noise-coefficient", "-1"}, "--depth-noise-coefficient must be"},
      {{"--depth-noise-constant", "-1"}, "--depth-noise-constant must be"},
      {{"--jobs", "0"}, "--jobs"},
      {{"-j", "many"}, "--jobs"},
      {{"--no-such-option"}, "--no-such-option"}};
  for (const auto& [option, message] : bad) {
    std::vector<std::string> arguments = {input, "-o", path("out").string()};
    arguments.insert(arguments.end(), option.begin(), option.end());
    SCOPED_TRACE(option[0]);
    const Result result = run(arguments);
    expectUsageError(result, "pcd_segment", message);
    for (const std::string library_name : {"subsampling", "setSubsampling", "seed_size", "floodplane::"}) {
      EXPECT_FALSE(contains(result.err, library_name)) << result.err;
    }
    EXPECT_FALSE(fs::exists(path("out"))) << "nothing is written after a usage error";
  }
  expectUsageError(run({input}), "pcd_segment", "--output is required");
  expectUsageError(run({"-o", path("out").string()}), "pcd_segment", "INPUT is required");
}

TEST_F(PcdSegment, RefusesASinglePcdOutputForSeveralInputs) {
  const Result result = run({writeScene("a.pcd"), writeScene("b.pcd"), "-o", path("both.pcd").string()});
  expectUsageError(result, "pcd_segment", "2 inputs");
  EXPECT_FALSE(fs::exists(path("both.pcd")));
  // A folder is several inputs when it holds several files.
  fs::create_directory(path("in"));
  writeScene("in/a.pcd");
  writeScene("in/b.pcd");
  expectUsageError(run({path("in").string(), "-o", path("both.pcd").string()}), "pcd_segment", "2 inputs");
  EXPECT_FALSE(fs::exists(path("both.pcd")));
}

// -o is a file when it ends in .pcd or .png, a directory when it ends in / or has no extension
// or exists as one; any other extension is refused rather than made a directory of that name.
TEST_F(PcdSegment, OutputIsAPcdOrPngFileOrADirectoryAndNothingElse) {
  const std::string input = writeScene("scene.pcd");
  for (const std::string refused : {"o/x.txt", "o/x.jpg", "o/x.json", "o/results.v2"}) {
    SCOPED_TRACE(refused);
    expectUsageError(run({input, "-o", path(refused).string()}), "pcd_segment",
                     "-o " + path(refused).string() + " looks like a");
    EXPECT_FALSE(fs::exists(path("o")));
  }
  ASSERT_EQ(run({input, "-o", path("o/x.pcd").string(), "--png"}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(path("o/x.pcd")));
  EXPECT_TRUE(fs::is_regular_file(path("o/x.png")));
  ASSERT_EQ(run({input, "-o", path("o/results.v2").string() + "/"}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(path("o/results.v2/scene.labels.pcd")));
  // An existing directory stays a directory, whatever its name.
  ASSERT_EQ(run({input, "-o", path("o/results.v2").string(), "--json"}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(path("o/results.v2/scene.planes.json")));
  ASSERT_EQ(run({input, "-o", path("o/plain").string()}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(path("o/plain/scene.labels.pcd")));
  ASSERT_EQ(run({input, "-o", path("o/y.PNG").string()}).exit_code, 0);
  EXPECT_TRUE(fs::is_regular_file(path("o/y.PNG")));
}

// -o NAME.png: the label image that --png draws, instead of the labelled cloud; the other
// outputs beside it with its stem, as for NAME.pcd.
TEST_F(PcdSegment, OutputPngIsTheLabelImageAlone) {
  const std::string input = writeScene("scene.pcd");
  ASSERT_EQ(run({input, "-o", path("cloud/scene.pcd").string(), "--png", "--json"}).exit_code, 0);
  const Result result = run({input, "-o", path("image/scene.png").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  EXPECT_TRUE(contains(result.out, "scene.pcd: 160x120, 2 planes, ")) << result.out;
  EXPECT_TRUE(contains(result.out, " -> " + path("image/scene.png").string() + "\n")) << result.out;
  EXPECT_EQ(readFile(path("image/scene.png")), readFile(path("cloud/scene.png")));
  const auto json = nlohmann::json::parse(readFile(path("image/scene.json")));
  EXPECT_EQ(json.at("plane_count"), 2);
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(path("image"))) written.push_back(entry.path().filename());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, (std::vector<std::string>{"scene.json", "scene.png"})) << "no labelled cloud";
  // --png asks for what -o names already; the image is the same.
  ASSERT_EQ(run({input, "-o", path("again.png").string(), "--png", "--quiet"}).exit_code, 0);
  EXPECT_EQ(readFile(path("again.png")), readFile(path("cloud/scene.png")));
  EXPECT_FALSE(fs::exists(path("again.pcd")));
  EXPECT_TRUE(contains(run({"--help"}).out, "OUT ending in .png: the label image of --png instead of the labelled"));
}

TEST_F(PcdSegment, OutputPngIsRefusedForSeveralInputsAndForTheInputItself) {
  const Result several = run({writeScene("a.pcd"), writeScene("b.pcd"), "-o", path("both.png").string()});
  expectUsageError(several, "pcd_segment", "-o " + path("both.png").string() + " names one .png file, but there are 2");
  EXPECT_FALSE(fs::exists(path("both.png")));
  // A file is never its own output: neither a depth image nor a cloud is overwritten.
  const std::string input = writeScene("self.pcd");
  const std::string before = readFile(path("self.pcd"));
  expectUsageError(run({input, "-o", input}), "pcd_segment", "-o " + input + " is the input itself");
  EXPECT_EQ(readFile(path("self.pcd")), before);
}

TEST_F(PcdSegment, HelpShowsTheLibraryDefaultsAndVersionPrintsTheVersion) {
  const Result help = run({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  const floodplane::Params defaults;
  const auto shown = [](double value) {
    std::ostringstream text;
    text << value;
    return text.str();
  };
  for (const auto& [option, value] :
       std::vector<std::pair<std::string, std::string>>{{"--angular-threshold", shown(defaults.angular_threshold)},
                                                        {"--subsample", std::to_string(defaults.subsampling)}}) {
    EXPECT_TRUE(contains(help.out, option + " ")) << option;
    EXPECT_TRUE(contains(help.out, "=" + value)) << option << " default " << value;
  }
  // The paper's lengths and the noise are derived from each frame unless given.
  for (const std::string option : {"--distance-threshold", "--seed-size", "--merge-distance", "--min-inliers",
                                   "--depth-noise-coefficient", "--depth-noise-constant"}) {
    EXPECT_TRUE(contains(help.out, option + " ")) << option;
  }
  EXPECT_TRUE(contains(help.out, "measured on each frame"));
  const Result version = run({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_TRUE(contains(version.out, FLOODPLANE_VERSION_STRING));
}

// ---- failed writes ------------------------------------------------------------------------

TEST_F(PcdSegment, ReportsAnOutputDirectoryThatCannotBeCreated) {
  // A regular file as the parent blocks the directory even for root, unlike permissions.
  writeFile(path("file"), "x");
  const Result result = run({writeScene("scene.pcd"), "-o", path("file/out").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_TRUE(contains(result.err, "cannot create output directory")) << result.err;
  EXPECT_EQ(readFile(path("file")), "x");
}

TEST_F(PcdSegment, LeavesAnExistingOutputWholeWhenAWriteFails) {
  // A file size limit (RLIMIT_FSIZE, with SIGXFSZ ignored so writes fail with EFBIG) stops the
  // write part-way, for root too. The previous output must survive unchanged, with no
  // temporary left beside it.
  const std::string input = writeScene("scene.pcd");
  fs::create_directory(path("out"));
  const std::string previous = "previous result\n";
  for (const bool ascii : {false, true}) {
    SCOPED_TRACE(ascii ? "ascii" : "binary compressed");
    writeFile(path("out/scene.labels.pcd"), previous);
    std::vector<std::string> arguments = {input, "-o", path("out").string()};
    if (ascii) arguments.push_back("--ascii");
    const Result result = run(arguments, "trap '' XFSZ; ulimit -f 1; ");
    EXPECT_EQ(result.exit_code, 1) << result.out;
    EXPECT_TRUE(contains(result.err, "scene.labels.pcd")) << result.err;
    EXPECT_EQ(readFile(path("out/scene.labels.pcd")), previous);
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(path("out"))) {
      ++files;
      EXPECT_EQ(entry.path().filename(), "scene.labels.pcd");
    }
    EXPECT_EQ(files, 1u);
  }
  // Without the limit the same run succeeds: the failure above was the limit.
  EXPECT_EQ(run({input, "-o", path("out").string()}).exit_code, 0);
  EXPECT_NE(readFile(path("out/scene.labels.pcd")), previous);
}

// ---- a real frame -------------------------------------------------------------------------

TEST_F(PcdSegment, SegmentsARealFrameAsTheLibraryDoes) {
  const fs::path frame = fs::path(FLOODPLANE_REAL_DATA_DIR) / "table_scene_mug_stereo_textured.pcd";
  if (!fs::exists(frame)) GTEST_SKIP() << "no real data at " << FLOODPLANE_REAL_DATA_DIR;
  const Result result = run({frame.string(), "-o", path("out").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  Cloud cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(frame.string(), cloud), 0);
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out/table_scene_mug_stereo_textured.labels.pcd").string(), labelled), 0);
  ASSERT_EQ(labelled.width, 640u);
  ASSERT_EQ(labelled.height, 480u);
  std::vector<std::uint32_t> labels;
  for (const auto& p : labelled) labels.push_back(p.label);
  const std::vector<std::uint32_t> expected = libraryLabels(cloud);
  EXPECT_EQ(labels, expected);
  const auto json = nlohmann::json::parse(readFile(path("out/table_scene_mug_stereo_textured.planes.json")));
  EXPECT_EQ(json.at("plane_count").get<std::uint32_t>(), *std::max_element(expected.begin(), expected.end()));
  EXPECT_GE(json.at("plane_count").get<int>(), 1) << "the table top at least";
  // The colour survives: the frame is not grey everywhere.
  pcl::PointCloud<pcl::PointXYZRGBA> original;
  ASSERT_EQ(pcl::io::loadPCDFile(frame.string(), original), 0);
  for (std::size_t i = 0; i < original.size(); i += 997) {
    ASSERT_EQ(labelled[i].r, original[i].r) << i;
    ASSERT_EQ(labelled[i].g, original[i].g) << i;
    ASSERT_EQ(labelled[i].b, original[i].b) << i;
  }
}

}  // namespace
}  // namespace floodplane::test
