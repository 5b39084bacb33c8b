// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_compare's methods as a library: Open3D's sequential RANSAC and floodplane at
// sub-sampling 2 on small rendered scenes (planes found, labels in range, determinism, a cloud
// that is mostly NaN), the baselines made from values by name, and the tuned values' file.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "eval/segmentation_metrics.h"
#include "input_cloud.h"
#include "method.h"

namespace {

using namespace pcd_compare;

const std::string kStaircase = std::string(PCD_COMPARE_SCENE_DIR) + "/staircase.none.pcd";
const std::string kTabletop = std::string(PCD_COMPARE_SCENE_DIR) + "/tabletop.kinect.pcd";

// Open3D's sequential RANSAC at `values`, the defaults filled in.
std::unique_ptr<Method> open3dRansac(const ParameterValues& values = {}) {
  return makeBaseline("open3d_ransac", values, "open3d_ransac");
}

// The distinct non-zero labels of a run.
std::set<std::uint32_t> planeLabels(const std::vector<std::uint32_t>& labels) {
  std::set<std::uint32_t> planes(labels.begin(), labels.end());
  planes.erase(0);
  return planes;
}

double meanIou(const InputCloud& input, const std::vector<std::uint32_t>& labels) {
  floodplane::eval::MetricsOptions options;
  options.min_points = floodplane::eval::defaultMinPoints(input.cloud->width, input.cloud->height);
  return floodplane::eval::evaluateSegmentation(*input.ground_truth, labels, input.valid, options).mean_iou;
}

// The checks every method must pass on a scene with ground truth: a label per pixel, planes
// numbered 1..k without gaps, none on a pixel without a point, and a mean IoU of at least
// `min_iou`.
void expectPlanesFound(Method& method, const InputCloud& input, double min_iou) {
  const MethodRun run = method.run(input.cloud);
  ASSERT_EQ(run.labels.size(), input.cloud->size()) << method.name();
  const std::set<std::uint32_t> planes = planeLabels(run.labels);
  ASSERT_GE(planes.size(), 3u) << method.name();
  EXPECT_EQ(*planes.rbegin(), planes.size()) << method.name() << ": labels 1..k without gaps";
  for (std::size_t i = 0; i < run.labels.size(); ++i) {
    if (input.valid[i] == 0) {
      ASSERT_EQ(run.labels[i], 0u) << method.name() << " labelled a NaN pixel " << i;
    }
  }
  EXPECT_GE(meanIou(input, run.labels), min_iou) << method.name();
  EXPECT_GT(run.total_ms, 0.0) << method.name();
}

// The staircase with 90 % of its pixels turned to NaN, scattered (fixed seed).
InputCloud mostlyNaN(InputCloud input) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < input.cloud->size(); ++i) {
    if (uniform(random) < 0.9f) {
      (*input.cloud)[i].x = (*input.cloud)[i].y = (*input.cloud)[i].z = nan;
      input.valid[i] = 0;
    }
  }
  input.cloud->is_dense = false;
  return input;
}

TEST(Open3dRansac, FindsTheStaircasePlanesWithLabelsInRange) {
  const InputCloud input = loadInputCloud(kStaircase);
  const auto method = open3dRansac();
  EXPECT_EQ(method->name(), "open3d_ransac");
  // A sequential RANSAC merges coplanar treads and cuts risers (IoU about 0.3 on this scene,
  // as PCL's): the floor is found, so the mean is well above zero.
  expectPlanesFound(*method, input, 0.2);
}

TEST(Open3dRansac, IsDeterministic) {
  const InputCloud input = loadInputCloud(kTabletop);
  const auto method = open3dRansac();
  const std::vector<std::uint32_t> first = method->run(input.cloud).labels;
  EXPECT_EQ(open3dRansac()->run(input.cloud).labels, first);
  EXPECT_EQ(method->run(input.cloud).labels, first);
}

TEST(Open3dRansac, DistanceThresholdAndMinInliersChangeTheResult) {
  const InputCloud input = loadInputCloud(kTabletop);
  const std::vector<std::uint32_t> standard = open3dRansac()->run(input.cloud).labels;
  EXPECT_NE(open3dRansac({{"distance_threshold", 0.04}})->run(input.cloud).labels, standard);
  // A larger min_inliers stops the same sequence earlier: a prefix of the planes.
  const std::vector<std::uint32_t> fewer = open3dRansac({{"min_inliers", 3000}})->run(input.cloud).labels;
  EXPECT_LT(planeLabels(fewer).size(), planeLabels(standard).size());
  const std::size_t kept = planeLabels(fewer).size();
  for (std::size_t i = 0; i < fewer.size(); ++i) ASSERT_EQ(fewer[i], standard[i] <= kept ? standard[i] : 0u) << i;
}

TEST(FloodplaneSubsampled, FindsTheStaircasePlanesWithLabelsInRange) {
  const InputCloud input = loadInputCloud(kStaircase);
  const auto method = makeFloodplaneMethod(2);
  EXPECT_EQ(method->name(), "floodplane/2");
  // At 320x240, sub-sampling 2 sees the 16 steps at 160x120: measured 0.62 (1.00 at s = 1).
  expectPlanesFound(*method, input, 0.5);
}

TEST(NewMethods, SurviveACloudThatIsMostlyNaN) {
  const InputCloud input = mostlyNaN(loadInputCloud(kStaircase));
  for (const auto& method : {open3dRansac(), makeFloodplaneMethod(2)}) {
    const MethodRun run = method->run(input.cloud);
    ASSERT_EQ(run.labels.size(), input.cloud->size()) << method->name();
    for (std::size_t i = 0; i < run.labels.size(); ++i) {
      if (input.valid[i] == 0) {
        ASSERT_EQ(run.labels[i], 0u) << method->name() << " labelled a NaN pixel " << i;
      }
    }
  }
}

TEST(Open3dRansac, CloudWithFewerValidPointsThanASampleGivesNoPlane) {
  InputCloud input = loadInputCloud(kStaircase);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 2; i < input.cloud->size(); ++i) {
    (*input.cloud)[i].x = (*input.cloud)[i].y = (*input.cloud)[i].z = nan;
  }
  const MethodRun run = open3dRansac()->run(input.cloud);
  EXPECT_TRUE(planeLabels(run.labels).empty());
}

TEST(Baselines, MakeEachMethodWithItsDefaultsAndRejectBadValues) {
  for (const std::string name : {"omps", "ransac", "open3d_ransac"}) {
    EXPECT_EQ(makeBaseline(name, {}, name + " (tuned)")->name(), name + " (tuned)");
    EXPECT_THROW(makeBaseline(name, {{"no_such_parameter", 1.0}}, name), std::invalid_argument) << name;
    EXPECT_THROW(makeBaseline(name, {{"min_inliers", 2.5}}, name), std::invalid_argument) << name;
    EXPECT_THROW(makeBaseline(name, {{"distance_threshold", -0.01}}, name), std::invalid_argument) << name;
  }
  EXPECT_THROW(makeBaseline("floodplane", {}, "floodplane"), std::invalid_argument);
  // The sequential RANSACs are timed once by pcd_compare, the others repeatedly.
  EXPECT_TRUE(makeBaseline("ransac", {}, "ransac")->slow());
  EXPECT_TRUE(makeBaseline("open3d_ransac", {}, "open3d_ransac")->slow());
  EXPECT_FALSE(makeBaseline("omps", {}, "omps")->slow());
  EXPECT_FALSE(makeFloodplaneMethod(1)->slow());
}

TEST(Baselines, TunedValuesReachTheMethodAndItsDescription) {
  const std::string described = makeBaseline("omps", {{"maximum_curvature", 0.05}}, "omps")->parameters();
  EXPECT_NE(described.find("maximum curvature 0.05"), std::string::npos) << described;
  const std::string ransac = makeBaseline("ransac", {{"distance_threshold", 0.03}}, "ransac")->parameters();
  EXPECT_NE(ransac.find("distance threshold 0.03 m"), std::string::npos) << ransac;
  // Every parameter, the defaults filled in, in one order: what bench/tune_baselines.py reads.
  EXPECT_EQ(describeValues("ransac", {{"min_inliers", 300}}), "distance_threshold=0.01, min_inliers=300");
  EXPECT_EQ(describeValues("omps", {}).rfind("angular_threshold=", 0), 0u);
}

TEST(Baselines, TunedValuesFileIsReadAndCheckedByName) {
  const std::string dir = ::testing::TempDir();
  const std::string good = dir + "/pcd_compare_tuned_good.json";
  std::ofstream(good) << R"({"methods": {"omps": {"by_sensor": {"kinect": {"parameters": {"min_inliers": 200}},
                                                               "none": {"parameters": {}}}}}})";
  const TunedValues tuned = readTunedValues(good);
  EXPECT_EQ(tuned.at("omps").at("kinect").at("min_inliers"), 200.0);
  EXPECT_TRUE(tuned.at("omps").at("none").empty());
  const std::string bad = dir + "/pcd_compare_tuned_bad.json";
  std::ofstream(bad) << R"({"methods": {"omps": {"by_sensor": {"kinect": {"parameters": {"bogus": 1}}}}}})";
  try {
    readTunedValues(bad);
    FAIL() << "a bad parameter was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(bad + ": omps has no parameter 'bogus'"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(readTunedValues(dir + "/no_such_file.json"), std::runtime_error);
}

// The object methods (--objects) on the tabletop: each made by its table's name, an object id
// per pixel numbered 1..K without gaps, none on a pixel without a point, the same labels twice;
// and a frame without a point gives no object.
TEST(ObjectMethods, FindObjectsOnTheTabletopDeterministically) {
  const InputCloud input = loadInputCloud(kTabletop);
  ASSERT_EQ(objectMethods().size(), 4u);
  for (const auto& [name, make] : objectMethods()) {
    const auto method = make();
    EXPECT_EQ(method->name(), name);
    EXPECT_FALSE(method->parameters().empty()) << name;
    const MethodRun run = method->run(input.cloud);
    ASSERT_EQ(run.labels.size(), input.cloud->size()) << name;
    const std::set<std::uint32_t> objects = planeLabels(run.labels);
    ASSERT_FALSE(objects.empty()) << name;
    EXPECT_EQ(*objects.rbegin(), objects.size()) << name << ": objects 1..K without gaps";
    for (std::size_t i = 0; i < run.labels.size(); ++i) {
      if (input.valid[i] == 0) {
        ASSERT_EQ(run.labels[i], 0u) << name << " labelled a NaN pixel " << i;
      }
    }
    EXPECT_EQ(method->run(input.cloud).labels, run.labels) << name;
    EXPECT_GT(run.total_ms, 0.0) << name;

    InputCloud empty = loadInputCloud(kTabletop);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (auto& point : *empty.cloud) point.x = point.y = point.z = nan;
    EXPECT_TRUE(planeLabels(method->run(empty.cloud).labels).empty()) << name;
  }
}

}  // namespace
