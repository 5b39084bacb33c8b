// pcd_compare's methods as a library: Open3D's sequential RANSAC and floodplane at
// sub-sampling 2 on small rendered scenes (planes found, labels in range, determinism, a cloud
// that is mostly NaN), the baselines' parameter table, and the sequence truncation the tuner
// scores min_inliers with.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "baselines.h"
#include "eval/segmentation_metrics.h"
#include "input_cloud.h"
#include "method.h"

namespace {

using namespace pcd_compare;

const std::string kStaircase = std::string(PCD_COMPARE_SCENE_DIR) + "/staircase.none.pcd";
const std::string kTabletop = std::string(PCD_COMPARE_SCENE_DIR) + "/tabletop.kinect.pcd";

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
  const auto method = makeOpen3dRansacMethod();
  EXPECT_EQ(method->name(), "open3d_ransac");
  // A sequential RANSAC merges coplanar treads and cuts risers (IoU about 0.3 on this scene,
  // as PCL's): the floor is found, so the mean is well above zero.
  expectPlanesFound(*method, input, 0.2);
}

TEST(Open3dRansac, IsDeterministic) {
  const InputCloud input = loadInputCloud(kTabletop);
  const auto method = makeOpen3dRansacMethod();
  const std::vector<std::uint32_t> first = method->run(input.cloud).labels;
  EXPECT_EQ(makeOpen3dRansacMethod()->run(input.cloud).labels, first);
  EXPECT_EQ(method->run(input.cloud).labels, first);
}

TEST(Open3dRansac, DistanceThresholdAndMinInliersChangeTheResult) {
  const InputCloud input = loadInputCloud(kTabletop);
  const std::vector<std::uint32_t> standard = makeOpen3dRansacMethod()->run(input.cloud).labels;
  EXPECT_NE(makeOpen3dRansacMethod({0.04, 100})->run(input.cloud).labels, standard);
  // A larger min_inliers stops the same sequence earlier: a prefix of the planes.
  const std::vector<std::uint32_t> fewer = makeOpen3dRansacMethod({0.01, 3000})->run(input.cloud).labels;
  EXPECT_LT(planeLabels(fewer).size(), planeLabels(standard).size());
  EXPECT_EQ(fewer, truncateSequence(standard, 3000));
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
  for (const auto& method : {makeOpen3dRansacMethod(), makeFloodplaneMethod(2)}) {
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
  const MethodRun run = makeOpen3dRansacMethod()->run(input.cloud);
  EXPECT_TRUE(planeLabels(run.labels).empty());
}

TEST(Baselines, MakeEachMethodWithItsDefaultsAndRejectBadValues) {
  for (const std::string name : {"omps", "ransac", "open3d_ransac"}) {
    const Baseline* baseline = findBaseline(name);
    ASSERT_NE(baseline, nullptr) << name;
    EXPECT_EQ(baseline->make({}, name + " (tuned)")->name(), name + " (tuned)");
    EXPECT_THROW(baseline->make({{"no_such_parameter", 1.0}}, name), std::invalid_argument) << name;
    EXPECT_THROW(baseline->make({{"min_inliers", 2.5}}, name), std::invalid_argument) << name;
    EXPECT_THROW(baseline->make({{"distance_threshold", -0.01}}, name), std::invalid_argument) << name;
  }
  EXPECT_EQ(findBaseline("floodplane"), nullptr);
  EXPECT_EQ(findBaseline("ransac")->truncation_parameter, "min_inliers");
  EXPECT_EQ(findBaseline("omps")->truncation_parameter, "");
}

TEST(Baselines, TunedValuesReachTheMethod) {
  const std::string described = findBaseline("omps")->make({{"maximum_curvature", 0.05}}, "omps")->parameters();
  EXPECT_NE(described.find("maximum curvature 0.05"), std::string::npos) << described;
  const std::string ransac = findBaseline("ransac")->make({{"distance_threshold", 0.03}}, "ransac")->parameters();
  EXPECT_NE(ransac.find("distance threshold 0.03 m"), std::string::npos) << ransac;
}

TEST(TruncateSequence, KeepsThePlanesBeforeTheFirstTooSmallOne) {
  // Plane 1: 4 pixels, plane 2: 2, plane 3: 3 (larger than 2, but after it).
  const std::vector<std::uint32_t> labels = {1, 1, 2, 0, 1, 3, 3, 3, 1, 2};
  EXPECT_EQ(truncateSequence(labels, 1), labels);
  EXPECT_EQ(truncateSequence(labels, 2), labels);
  EXPECT_EQ(truncateSequence(labels, 3), (std::vector<std::uint32_t>{1, 1, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(truncateSequence(labels, 5), std::vector<std::uint32_t>(labels.size(), 0));
}

}  // namespace
