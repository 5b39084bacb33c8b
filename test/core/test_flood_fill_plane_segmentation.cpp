// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The PCL-facing class: OMPS's interface and meaning, agreement with PCL, bad input.
#include <gtest/gtest.h>

#include <pcl/common/centroid.h>
#include <pcl/common/eigen.h>
#include <pcl/common/transforms.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/io/pcd_io.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "test_scenes.h"

namespace floodplane {
namespace {

test::Pinhole kinect() { return test::kinectView(640, 480); }

template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr toCloud(const test::RenderedGrid& scene) {
  typename pcl::PointCloud<PointT>::Ptr cloud(new pcl::PointCloud<PointT>);
  cloud->resize(static_cast<pcl::uindex_t>(scene.width), static_cast<pcl::uindex_t>(scene.height));
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    (*cloud)[i].x = scene.xyz[3 * i];
    (*cloud)[i].y = scene.xyz[3 * i + 1];
    (*cloud)[i].z = scene.xyz[3 * i + 2];
  }
  cloud->is_dense = false;
  return cloud;
}

// Every output of segmentAndRefine's full overload.
template <typename PointT>
struct AllOutputs {
  typename FloodFillPlaneSegmentation<PointT>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels;
};

template <typename PointT>
AllOutputs<PointT> segmentAndRefine(FloodFillPlaneSegmentation<PointT>& seg) {
  AllOutputs<PointT> out;
  seg.segmentAndRefine(out.regions, out.coefficients, out.inliers, out.labels, out.label_indices, out.boundaries);
  return out;
}

template <typename PointT>
class FloodFillPlaneSegmentationTyped : public ::testing::Test {};
using PointTypes = ::testing::Types<pcl::PointXYZ, pcl::PointXYZRGB, pcl::PointXYZRGBA, pcl::PointXYZI, pcl::PointXYZL>;
TYPED_TEST_SUITE(FloodFillPlaneSegmentationTyped, PointTypes);

TYPED_TEST(FloodFillPlaneSegmentationTyped, FillsEveryOutputOfSegmentAndRefineConsistently) {
  using Seg = FloodFillPlaneSegmentation<TypeParam>;
  const auto cloud = toCloud<TypeParam>(test::render(kinect(), test::roomCorner(), 0.004, 1));
  Seg seg;
  seg.setInputCloud(cloud);
  const AllOutputs<TypeParam> out = segmentAndRefine(seg);
  const auto& [regions, coefficients, inliers, label_indices, boundaries, labels] = out;

  ASSERT_EQ(regions.size(), 3u);
  ASSERT_EQ(coefficients.size(), 3u);
  ASSERT_EQ(inliers.size(), 3u);
  ASSERT_EQ(boundaries.size(), 3u);
  ASSERT_EQ(label_indices.size(), 4u);
  ASSERT_TRUE(labels);
  EXPECT_EQ(labels->width, cloud->width);
  EXPECT_EQ(labels->height, cloud->height);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const std::uint32_t label = static_cast<std::uint32_t>(k + 1);
    const Eigen::Vector4f c(coefficients[k].values[0], coefficients[k].values[1], coefficients[k].values[2],
                            coefficients[k].values[3]);
    EXPECT_NEAR(c.head<3>().norm(), 1.0f, 1e-5f);
    EXPECT_GT(c[3], 0.0f) << "normal must face the sensor at the origin";
    EXPECT_EQ(regions[k].getCoefficients(), c);
    EXPECT_EQ(regions[k].getCount(), inliers[k].indices.size());
    EXPECT_EQ(label_indices[k + 1].indices, inliers[k].indices);
    if (k > 0) {
      EXPECT_GE(inliers[k - 1].indices.size(), inliers[k].indices.size());
    }
    for (int i : inliers[k].indices) ASSERT_EQ((*labels)[i].label, label);
    // The contour: ordered, closed, on the region's border.
    ASSERT_FALSE(boundaries[k].indices.empty());
    EXPECT_EQ(regions[k].getContour().size(), boundaries[k].indices.size());
    const auto& contour = boundaries[k].indices;
    for (std::size_t j = 0; j < contour.size(); ++j) {
      ASSERT_EQ((*labels)[contour[j]].label, label);
      const int a = contour[j], b = contour[(j + 1) % contour.size()];
      EXPECT_LE(std::abs(a % 640 - b % 640), 1);
      EXPECT_LE(std::abs(a / 640 - b / 640), 1);
    }
  }
  std::size_t labelled = 0;
  for (const auto& l : *labels) labelled += l.label != 0;
  EXPECT_EQ(labelled, inliers[0].indices.size() + inliers[1].indices.size() + inliers[2].indices.size());
  for (int i : label_indices[0].indices) {
    EXPECT_EQ((*labels)[i].label, 0u);
    EXPECT_TRUE(pcl::isXYZFinite((*cloud)[i]));
  }
}

TEST(FloodFillPlaneSegmentation, AgreesWithALeastSquaresFitOfItsInliers) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 2));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Centroids centroids;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Covariances covariances;
  pcl::PointCloud<pcl::Label> labels;
  std::vector<pcl::PointIndices> label_indices;
  seg.segment(coefficients, inliers, centroids, covariances, labels, label_indices);
  ASSERT_EQ(coefficients.size(), 3u);
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
    Eigen::Vector4f centroid;
    pcl::computeMeanAndCovarianceMatrix(*cloud, inliers[k].indices, covariance, centroid);
    float eigenvalue;
    Eigen::Vector3f normal;
    pcl::eigen33(covariance, eigenvalue, normal);
    const Eigen::Vector3f ours(coefficients[k].values[0], coefficients[k].values[1], coefficients[k].values[2]);
    EXPECT_GT(std::abs(ours.dot(normal)), std::cos(1e-3f)) << "plane " << k;
    EXPECT_NEAR(std::abs(coefficients[k].values[3]), std::abs(normal.dot(centroid.head<3>())), 2e-3f);
    EXPECT_LT((centroids[k] - centroid).norm(), 1e-4f);
    // PCL accumulates in float, which is good to about 1e-3 here; the reference for the
    // covariance is a two-pass computation in double.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int i : inliers[k].indices) mean += (*cloud)[i].getVector3fMap().cast<double>();
    mean /= static_cast<double>(inliers[k].indices.size());
    Eigen::Matrix3d exact = Eigen::Matrix3d::Zero();
    for (int i : inliers[k].indices) {
      const Eigen::Vector3d d = (*cloud)[i].getVector3fMap().cast<double>() - mean;
      exact += d * d.transpose();
    }
    exact /= static_cast<double>(inliers[k].indices.size());
    EXPECT_LT((covariances[k].cast<double>() - exact).norm(), 1e-5 * exact.norm());
  }
}

TEST(FloodFillPlaneSegmentation, AgreesWithOrganizedMultiPlaneSegmentationUpToSign) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.002, 4));
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> estimator;
  estimator.setNormalEstimationMethod(estimator.AVERAGE_3D_GRADIENT);
  estimator.setMaxDepthChangeFactor(0.02f);
  estimator.setNormalSmoothingSize(10.0f);
  estimator.setInputCloud(cloud);
  estimator.compute(*normals);
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> omps;
  omps.setInputCloud(cloud);
  omps.setInputNormals(normals);
  omps.setMinInliers(5000);
  omps.setAngularThreshold(0.05);
  omps.setDistanceThreshold(0.02);
  std::vector<pcl::ModelCoefficients> theirs, ours;
  std::vector<pcl::PointIndices> their_inliers, our_inliers;
  omps.segment(theirs, their_inliers);
  ASSERT_GE(theirs.size(), 3u);

  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  seg.segment(ours, our_inliers);
  ASSERT_EQ(ours.size(), 3u);
  for (const pcl::ModelCoefficients& t : theirs) {
    const Eigen::Vector4f a(t.values[0], t.values[1], t.values[2], t.values[3]);
    float best = 0.f;
    Eigen::Vector4f match = Eigen::Vector4f::Zero();
    for (const pcl::ModelCoefficients& o : ours) {
      const Eigen::Vector4f b(o.values[0], o.values[1], o.values[2], o.values[3]);
      if (std::abs(a.head<3>().dot(b.head<3>())) > best) {
        best = std::abs(a.head<3>().dot(b.head<3>()));
        match = a.head<3>().dot(b.head<3>()) < 0 ? Eigen::Vector4f(-b) : b;
      }
    }
    EXPECT_GT(best, std::cos(2.0f * static_cast<float>(M_PI) / 180.0f));
    EXPECT_NEAR(match[3], a[3], 0.02f);
  }
}

// A ball 0.15 m across in front of a wall 2 m away: the ball is the one object on the wall
// (its support), as OrganizedConnectedComponentSegmentation would give it, labels and indices;
// the same when the cloud and its sensor origin move together.
TEST(FloodFillPlaneSegmentation, SegmentsTheObjectsOnThePlanes) {
  const test::RenderedGrid scene = test::render(
      test::kinectView(160, 120), {test::frontalPlane(2.0, 1)}, {test::ball(Eigen::Vector3d(0.1, 0.0, 1.6), 0.15, 2)},
      [](double) { return 0.0; }, 1);
  const auto cloud = toCloud<pcl::PointXYZ>(scene);
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  pcl::PointCloud<pcl::Label> labels;
  std::vector<pcl::PointIndices> indices(3);
  seg.segmentObjects(labels, indices);  // nothing segmented yet: empty outputs
  EXPECT_TRUE(labels.empty());
  EXPECT_TRUE(indices.empty());
  seg.setInputCloud(cloud);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  seg.segmentAndRefine(regions);
  seg.segmentObjects(labels, indices);
  ASSERT_EQ(labels.width, cloud->width);
  ASSERT_EQ(labels.height, cloud->height);
  ASSERT_EQ(indices.size(), 1u);
  ASSERT_EQ(seg.getLastObjects().objects.size(), 1u);
  EXPECT_EQ(seg.getLastObjects().objects[0].support, 1u);
  std::size_t ball = 0;
  std::size_t ball_in_object = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (scene.truth[i] == 1) {
      EXPECT_EQ(labels[i].label, 0u) << "a wall pixel in an object: " << i;
    }
    ball += scene.truth[i] == 2;
    ball_in_object += scene.truth[i] == 2 && labels[i].label == 1;
  }
  EXPECT_GT(ball_in_object, 0.95 * static_cast<double>(ball));
  EXPECT_EQ(indices[0].indices.size(), ball_in_object);
  for (const int i : indices[0].indices) EXPECT_EQ(labels[static_cast<std::size_t>(i)].label, 1u);

  // Moved with its sensor: the same objects, their figures relative to the sensor.
  const Eigen::Vector3f shift(0.5f, -1.0f, 2.0f);
  pcl::PointCloud<pcl::PointXYZ>::Ptr moved(new pcl::PointCloud<pcl::PointXYZ>(*cloud));
  for (auto& p : *moved) p.getVector3fMap() += shift;
  moved->sensor_origin_.head<3>() = shift;
  const Eigen::Vector3d centroid = seg.getLastObjects().objects[0].centroid;
  seg.setInputCloud(moved);
  seg.segmentAndRefine(regions);
  pcl::PointCloud<pcl::Label> moved_labels;
  seg.segmentObjects(moved_labels, indices);
  ASSERT_EQ(moved_labels.size(), labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) ASSERT_EQ(moved_labels[i].label, labels[i].label) << i;
  EXPECT_TRUE(seg.getLastObjects().objects[0].centroid.isApprox(centroid, 1e-5));
}

TEST(FloodFillPlaneSegmentation, GivesEmptyOutputsWithoutAnInputCloud) {
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  std::vector<pcl::ModelCoefficients> coefficients(2);
  std::vector<pcl::PointIndices> inliers(2), label_indices(2), boundaries(2);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions(2);
  pcl::PointCloud<pcl::Label>::Ptr labels;
  seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
  EXPECT_TRUE(regions.empty());
  EXPECT_TRUE(coefficients.empty());
  EXPECT_TRUE(inliers.empty());
  EXPECT_TRUE(label_indices.empty());
  EXPECT_TRUE(boundaries.empty());
  ASSERT_TRUE(labels);
  EXPECT_TRUE(labels->empty());
}

TEST(FloodFillPlaneSegmentation, RejectsAnUnorganizedCloudWithEmptyOutputs) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (int i = 0; i < 1000; ++i) cloud->push_back(pcl::PointXYZ(0.001f * static_cast<float>(i), 0.0f, 1.0f));
  ASSERT_EQ(cloud->height, 1u);
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  std::vector<pcl::ModelCoefficients> coefficients(1);
  std::vector<pcl::PointIndices> inliers(1);
  seg.segment(coefficients, inliers);
  EXPECT_TRUE(coefficients.empty());
  EXPECT_TRUE(inliers.empty());
}

TEST(FloodFillPlaneSegmentation, FindsNoPlaneInAnAllNaNCloud) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cloud->resize(64, 48, pcl::PointXYZ(nan, nan, nan));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  seg.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
  EXPECT_TRUE(regions.empty());
  EXPECT_EQ(labels->size(), cloud->size());
  for (const auto& l : *labels) EXPECT_EQ(l.label, 0u);
  ASSERT_EQ(label_indices.size(), 1u);
  EXPECT_TRUE(label_indices[0].indices.empty());  // NaN points are not "finite points without a plane"
}

TEST(FloodFillPlaneSegmentation, RejectsBadParametersInTheSetterThatTookThem) {
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([&] { seg.setDistanceThreshold(-0.01); }).find("setDistanceThreshold"), std::string::npos);
  EXPECT_NE(message([&] { seg.setAngularThreshold(0.0); }).find("setAngularThreshold"), std::string::npos);
  EXPECT_NE(message([&] { seg.setAngularThreshold(std::nan("")); }).find("setAngularThreshold"), std::string::npos);
  EXPECT_NE(message([&] { seg.setMaximumCurvature(-1.0); }).find("setMaximumCurvature"), std::string::npos);
  EXPECT_NE(message([&] { seg.setSeedSize(0.0); }).find("setSeedSize"), std::string::npos);
  EXPECT_NE(message([&] { seg.setMergeDistance(-3.0); }).find("setMergeDistance"), std::string::npos);
  EXPECT_NE(message([&] { seg.setSubsampling(3); }).find("setSubsampling"), std::string::npos);
  EXPECT_NE(message([&] { seg.setDepthNoiseCoefficient(-1.0); }).find("setDepthNoiseCoefficient"), std::string::npos);
  Params bad;
  bad.seed_size = -1.0;
  EXPECT_NE(message([&] { seg.setParams(bad); }).find("seed_size"), std::string::npos);
  EXPECT_NE(message([&] { seg.setDepthNoiseConstant(-0.001); }).find("setDepthNoiseConstant"), std::string::npos);
  // Nothing changed: the lengths are still derived from each frame, the rest as before.
  EXPECT_FALSE(seg.getParams().distance_threshold);
  EXPECT_FALSE(seg.getParams().seed_size);
  EXPECT_TRUE(seg.getParams().estimatesNoise());
  EXPECT_EQ(seg.getSubsampling(), 4);
  EXPECT_DOUBLE_EQ(seg.getAngularThreshold(), 0.1);
}

TEST(FloodFillPlaneSegmentation, DerivesThePapersLengthsFromEachFrameUnlessTheyAreSet) {
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_DOUBLE_EQ(seg.getDistanceThreshold(), 0.0);  // sigma_plane: derived
  EXPECT_DOUBLE_EQ(seg.getSeedSize(), 0.0);           // sigma_seed: derived
  EXPECT_DOUBLE_EQ(seg.getMergeDistance(), 0.0);      // sigma_plane-merge: derived
  EXPECT_DOUBLE_EQ(seg.getAngularThreshold(), 0.1);   // theta_angle, the paper's
  EXPECT_EQ(seg.getSubsampling(), 4);                 // coarse to fine
  EXPECT_FALSE(seg.getProjectPoints());
  EXPECT_TRUE(seg.getParams().estimatesNoise());
  // Set, they are the paper's fixed lengths.
  seg.setDistanceThreshold(0.01);
  seg.setSeedSize(0.06);
  seg.setMergeDistance(0.03);
  seg.setDepthNoiseCoefficient(0.0);
  EXPECT_DOUBLE_EQ(seg.getDistanceThreshold(), 0.01);
  EXPECT_DOUBLE_EQ(seg.getSeedSize(), 0.06);
  EXPECT_DOUBLE_EQ(seg.getMergeDistance(), 0.03);
  EXPECT_FALSE(seg.getParams().estimatesNoise());
}

TEST(FloodFillPlaneSegmentation, GivesTheSameResultWhenCloudAndSensorMoveTogether) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 6));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  std::vector<pcl::ModelCoefficients> before, after;
  pcl::PointCloud<pcl::Label> labels_before, labels_after;
  std::vector<pcl::PointIndices> inliers, label_indices;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Centroids centroids;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Covariances covariances;
  seg.segment(before, inliers, centroids, covariances, labels_before, label_indices);

  Eigen::Affine3f motion = Eigen::Affine3f::Identity();
  motion.translate(Eigen::Vector3f(2.0f, -1.0f, 0.5f));
  motion.rotate(Eigen::AngleAxisf(0.7f, Eigen::Vector3f(1, 2, 3).normalized()));
  pcl::PointCloud<pcl::PointXYZ>::Ptr moved(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::transformPointCloud(*cloud, *moved, motion);
  moved->sensor_origin_ << motion.translation(), 0.0f;
  moved->sensor_orientation_ = Eigen::Quaternionf(motion.rotation());
  seg.setInputCloud(moved);
  seg.segment(after, inliers, centroids, covariances, labels_after, label_indices);

  ASSERT_EQ(after.size(), before.size());
  std::size_t same = 0;
  for (std::size_t i = 0; i < labels_before.size(); ++i) same += labels_before[i].label == labels_after[i].label;
  EXPECT_GT(static_cast<double>(same) / static_cast<double>(labels_before.size()), 0.999);
  for (std::size_t k = 0; k < before.size(); ++k) {
    const Eigen::Vector3f n_before(before[k].values[0], before[k].values[1], before[k].values[2]);
    const Eigen::Vector3f n_after(after[k].values[0], after[k].values[1], after[k].values[2]);
    EXPECT_GT((motion.rotation() * n_before).dot(n_after), 0.99999f);
  }
}

TEST(FloodFillPlaneSegmentation, ProjectsContoursOntoTheirPlanesOnRequest) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 8));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  seg.setProjectPoints(true);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions;
  seg.segmentAndRefine(regions);
  ASSERT_EQ(regions.size(), 3u);
  for (const auto& region : regions) {
    const Eigen::Vector4f c = region.getCoefficients();
    for (const auto& p : region.getContour()) EXPECT_NEAR(c.head<3>().dot(p.getVector3fMap()) + c[3], 0.0f, 1e-4f);
  }
}

TEST(FloodFillPlaneSegmentation, SegmentsWithoutRefinementInSegment) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.01, 10));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions plain, refined;
  seg.segment(plain);
  seg.segmentAndRefine(refined);
  ASSERT_EQ(plain.size(), refined.size());
  unsigned plain_total = 0, refined_total = 0;
  for (std::size_t k = 0; k < plain.size(); ++k) {
    plain_total += plain[k].getCount();
    refined_total += refined[k].getCount();
  }
  EXPECT_GE(refined_total, plain_total);
}

// With the phase timer on, the class's phases are the core's plus its own conversion, and
// together they fit in the call; off, they are all zero.
TEST(FloodFillPlaneSegmentation, TimesTheCoresPhasesAndItsOwnConversion) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 2));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  segmentAndRefine(seg);
  EXPECT_EQ(seg.getLastPhases().total(), 0.0);

  seg.setMeasurePhases(true);
  const auto start = std::chrono::steady_clock::now();
  segmentAndRefine(seg);
  const double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const PhaseTimes& phases = seg.getLastPhases();
  const PhaseTimes& core = seg.getLastSegmentation().phases;
  EXPECT_GT(phases.pcl_conversion, 0.0);
  EXPECT_EQ(core.pcl_conversion, 0.0);
  EXPECT_EQ(phases.flood_fill, core.flood_fill);
  EXPECT_EQ(phases.region_output, core.region_output);
  EXPECT_DOUBLE_EQ(phases.total(), core.total() + phases.pcl_conversion);
  EXPECT_LE(phases.total(), wall_ms);
}

TEST(FloodFillPlaneSegmentation, SegmentsTheRealFrames) {
  const std::filesystem::path folder(FLOODPLANE_REAL_DATA_DIR);
  if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "no real data at " << folder;
  std::size_t frames = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".pcd") continue;
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    ASSERT_EQ(pcl::io::loadPCDFile(entry.path().string(), *cloud), 0) << entry.path();
    FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
    seg.setInputCloud(cloud);
    const AllOutputs<pcl::PointXYZ> out = segmentAndRefine(seg);
    const auto& [regions, coefficients, inliers, label_indices, boundaries, labels] = out;
    ASSERT_FALSE(regions.empty()) << entry.path();
    // Every real frame shows a floor, a table or a wall covering at least a twentieth of the
    // image (the least: five_people, whose floor shows between the people on 8.7 %).
    EXPECT_GT(inliers[0].indices.size(), cloud->size() / 20) << entry.path();
    for (const auto& region : regions) EXPECT_GE(region.getCount(), seg.getMinInliers());
    ++frames;
  }
  EXPECT_EQ(frames, 7u);
}

// ---- planes over a stream of clouds ---------------------------------------------------------

// The label each ground-truth plane of `scene` carries: the most common one on its pixels.
std::map<int, std::uint32_t> labelOfEachTruePlane(const test::RenderedGrid& scene,
                                                  const pcl::PointCloud<pcl::Label>& labels) {
  std::map<int, std::map<std::uint32_t, std::size_t>> votes;
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (scene.truth[i] != 0 && labels[i].label != 0) ++votes[scene.truth[i]][labels[i].label];
  std::map<int, std::uint32_t> label_of;
  for (const auto& [truth, counts] : votes) {
    const auto best = std::max_element(counts.begin(), counts.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    label_of[truth] = best->first;
  }
  return label_of;
}

// The cloud of `scene` with the points of ground-truth plane `truth` gone (no return).
pcl::PointCloud<pcl::PointXYZ>::Ptr withoutPlane(const test::RenderedGrid& scene, int truth) {
  auto cloud = toCloud<pcl::PointXYZ>(scene);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < cloud->size(); ++i)
    if (scene.truth[i] == truth) (*cloud)[i].x = (*cloud)[i].y = (*cloud)[i].z = nan;
  return cloud;
}

// Outputs passed again to the next call are written over in place (they keep their storage):
// what a call leaves must be what fresh outputs get, whatever the last call left in them.
TEST(FloodFillPlaneSegmentation, WritesOverTheOutputsOfTheLastCallAsIfTheyWereNew) {
  const test::RenderedGrid scene = test::render(kinect(), test::roomCorner(), 0.004, 5);
  const auto full = toCloud<pcl::PointXYZ>(scene);
  const auto fewer = withoutPlane(scene, 1);
  const auto small = toCloud<pcl::PointXYZ>(test::render(test::kinectView(320, 240), test::roomCorner(), 0.004, 6));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  AllOutputs<pcl::PointXYZ> reused;
  for (const auto& cloud : {full, fewer, small, full}) {
    seg.setInputCloud(cloud);
    seg.segmentAndRefine(reused.regions, reused.coefficients, reused.inliers, reused.labels, reused.label_indices,
                         reused.boundaries);
    const AllOutputs<pcl::PointXYZ> fresh = segmentAndRefine(seg);
    ASSERT_FALSE(fresh.regions.empty());
    ASSERT_EQ(reused.regions.size(), fresh.regions.size());
    for (std::size_t k = 0; k < fresh.regions.size(); ++k) {
      EXPECT_EQ(reused.regions[k].getCount(), fresh.regions[k].getCount());
      EXPECT_EQ(reused.regions[k].getCentroid(), fresh.regions[k].getCentroid());
      EXPECT_EQ(reused.regions[k].getCovariance(), fresh.regions[k].getCovariance());
      EXPECT_EQ(reused.regions[k].getCoefficients(), fresh.regions[k].getCoefficients());
      const auto& a = reused.regions[k].getContour();
      const auto& b = fresh.regions[k].getContour();
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t j = 0; j < a.size(); ++j) ASSERT_EQ(a[j].getVector3fMap(), b[j].getVector3fMap());
    }
    ASSERT_EQ(reused.coefficients.size(), fresh.coefficients.size());
    for (std::size_t k = 0; k < fresh.coefficients.size(); ++k)
      EXPECT_EQ(reused.coefficients[k].values, fresh.coefficients[k].values);
    const auto same_indices = [](const std::vector<pcl::PointIndices>& a, const std::vector<pcl::PointIndices>& b) {
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t k = 0; k < a.size(); ++k) EXPECT_EQ(a[k].indices, b[k].indices) << "list " << k;
    };
    same_indices(reused.inliers, fresh.inliers);
    same_indices(reused.label_indices, fresh.label_indices);
    same_indices(reused.boundaries, fresh.boundaries);
    ASSERT_EQ(reused.labels->width, cloud->width);
    ASSERT_EQ(reused.labels->height, cloud->height);
    ASSERT_EQ(reused.labels->size(), fresh.labels->size());
    for (std::size_t i = 0; i < fresh.labels->size(); ++i)
      ASSERT_EQ((*reused.labels)[i].label, (*fresh.labels)[i].label);
  }
}

TEST(FloodFillPlaneSegmentation, GivesTheSameTrackIdsWhenTheSameCloudIsSegmentedTwice) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 3));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_FALSE(seg.getTracking());
  seg.setInputCloud(cloud);
  segmentAndRefine(seg);
  EXPECT_TRUE(seg.getTrackIds().empty()) << "no track ids while tracking is off";
  EXPECT_EQ(seg.getTracker().frameCount(), 0u);

  seg.setTracking(true);
  const AllOutputs<pcl::PointXYZ> first = segmentAndRefine(seg);
  const std::vector<std::uint32_t> first_ids = seg.getTrackIds();
  EXPECT_EQ(first_ids, (std::vector<std::uint32_t>{1, 2, 3}));  // the first frame's, in order of size
  const AllOutputs<pcl::PointXYZ> second = segmentAndRefine(seg);
  EXPECT_EQ(seg.getTrackIds(), first_ids);
  ASSERT_EQ(second.labels->size(), first.labels->size());
  for (std::size_t i = 0; i < cloud->size(); ++i) ASSERT_EQ((*second.labels)[i].label, (*first.labels)[i].label);

  const PlaneTracker& tracker = seg.getTracker();
  EXPECT_EQ(tracker.frameCount(), 2u);
  ASSERT_EQ(tracker.tracks().size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t id = seg.getTrackIds()[k];
    const PlaneTrack* track = tracker.track(id);
    ASSERT_NE(track, nullptr);
    EXPECT_EQ(track->first_frame, 0u);
    EXPECT_EQ(track->last_frame, 1u);
    EXPECT_EQ(track->frames_seen, 2u);
    EXPECT_EQ(track->plane, static_cast<int>(k));
    // The label outputs follow the ids, the plane outputs stay by size.
    EXPECT_EQ(second.label_indices[id].indices, second.inliers[k].indices);
    for (int i : second.inliers[k].indices) ASSERT_EQ((*second.labels)[i].label, id);
    const Eigen::Vector3f normal(second.coefficients[k].values[0], second.coefficients[k].values[1],
                                 second.coefficients[k].values[2]);
    EXPECT_GT(normal.cast<double>().dot(track->normal), 0.99999);
  }
}

TEST(FloodFillPlaneSegmentation, KeepsTrackIdsWhenAPlaneLeavesTheViewAndReturns) {
  const test::RenderedGrid scene = test::render(kinect(), test::roomCorner(), 0.004, 4);
  const auto full = toCloud<pcl::PointXYZ>(scene);
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setTracking(true);
  seg.setInputCloud(full);
  const std::map<int, std::uint32_t> first = labelOfEachTruePlane(scene, *segmentAndRefine(seg).labels);
  ASSERT_EQ(first.size(), 3u);

  // The largest plane gone: the others move up in size rank but keep their ids (here through
  // segment(), whose label cloud carries them as segmentAndRefine's does).
  const auto largest = std::find_if(first.begin(), first.end(), [](const auto& entry) { return entry.second == 1; });
  ASSERT_NE(largest, first.end());
  seg.setInputCloud(withoutPlane(scene, largest->first));
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Centroids centroids;
  FloodFillPlaneSegmentation<pcl::PointXYZ>::Covariances covariances;
  pcl::PointCloud<pcl::Label> labels;
  seg.segment(coefficients, inliers, centroids, covariances, labels, label_indices);
  ASSERT_EQ(coefficients.size(), 2u);
  EXPECT_NE(seg.getTrackIds()[0], 1u) << "the largest plane now is another one";
  std::map<int, std::uint32_t> expected = first;
  expected.erase(largest->first);
  EXPECT_EQ(labelOfEachTruePlane(scene, labels), expected);
  ASSERT_EQ(label_indices.size(), 4u);  // 0 and ids 1 .. 3, of which 1 has no points here
  EXPECT_TRUE(label_indices[1].indices.empty());

  // Back in view: every plane has its first id, and no track was started.
  seg.setInputCloud(full);
  EXPECT_EQ(labelOfEachTruePlane(scene, *segmentAndRefine(seg).labels), first);
  EXPECT_EQ(seg.getTracker().tracks().size(), 3u);
  EXPECT_EQ(seg.getTracker().track(1)->frames_seen, 2u);
  EXPECT_EQ(seg.getTracker().track(1)->last_frame, 2u);
}

TEST(FloodFillPlaneSegmentation, FollowsPlanesAcrossALargeCameraMoveWhenGivenTheMotion) {
  const auto before = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 5));
  // The camera 0.4 m forward and turned 0.1 rad to the left: far more than the tracker's limits
  // for a frame without a motion (0.08 m of plane offset).
  Eigen::Affine3d motion = Eigen::Affine3d::Identity();
  motion.translate(Eigen::Vector3d(0.1, 0.0, 0.4));
  motion.rotate(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()));
  pcl::PointCloud<pcl::PointXYZ>::Ptr after(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::transformPointCloud(*before, *after, motion.inverse().cast<float>());  // P_current = motion^-1 P_previous

  FloodFillPlaneSegmentation<pcl::PointXYZ> blind, told;
  for (auto* seg : {&blind, &told}) {
    seg->setTracking(true);
    seg->setInputCloud(before);
    segmentAndRefine(*seg);
    seg->setInputCloud(after);
  }
  told.setCameraMotion(motion.matrix());
  segmentAndRefine(blind);
  segmentAndRefine(told);
  ASSERT_EQ(told.getTrackIds().size(), 3u);
  EXPECT_EQ(std::set<std::uint32_t>(told.getTrackIds().begin(), told.getTrackIds().end()),
            (std::set<std::uint32_t>{1, 2, 3}));
  EXPECT_GT(*std::max_element(blind.getTrackIds().begin(), blind.getTrackIds().end()), 3u)
      << "without the motion, the moved back wall is a new surface";
  // The motion is for one frame only: the same cloud again, without one, keeps the ids.
  const std::vector<std::uint32_t> ids = told.getTrackIds();
  segmentAndRefine(told);
  EXPECT_EQ(told.getTrackIds(), ids);
}

TEST(FloodFillPlaneSegmentation, RejectsABadCameraMotionOrTrackerOptionsInTheirSetters) {
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  const Eigen::Matrix4d scaled = 2.0 * Eigen::Matrix4d::Identity();
  EXPECT_NE(message([&] { seg.setCameraMotion(scaled); }).find("setCameraMotion"), std::string::npos);
  Eigen::Matrix4d not_finite = Eigen::Matrix4d::Identity();
  not_finite(0, 3) = std::nan("");
  EXPECT_NE(message([&] { seg.setCameraMotion(not_finite); }).find("rigid"), std::string::npos);
  PlaneTracker::Options options;
  options.max_lost_frames = -1;
  const std::string bad_options = message([&] { seg.setTrackerOptions(options); });
  EXPECT_NE(bad_options.find("setTrackerOptions"), std::string::npos) << bad_options;
  EXPECT_NE(bad_options.find("max_lost_frames"), std::string::npos) << bad_options;
  EXPECT_EQ(seg.getTrackerOptions().max_lost_frames, PlaneTracker::Options().max_lost_frames);
  EXPECT_EQ(message([&] { seg.setCameraMotion(Eigen::Matrix4d::Identity()); }), "no exception");
}

TEST(FloodFillPlaneSegmentation, StartsANewSequenceWhenTrackingIsSwitchedOffAndOn) {
  const auto cloud = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 7));
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  seg.setInputCloud(cloud);
  seg.setTracking(true);
  segmentAndRefine(seg);
  seg.setTracking(true);  // no change: the sequence goes on
  segmentAndRefine(seg);
  EXPECT_EQ(seg.getTracker().frameCount(), 2u);
  seg.setTracking(false);
  const AllOutputs<pcl::PointXYZ> ranks = segmentAndRefine(seg);
  EXPECT_EQ(seg.getTracker().frameCount(), 0u);
  EXPECT_EQ(ranks.label_indices.size(), 4u);
  seg.setTracking(true);
  segmentAndRefine(seg);
  EXPECT_EQ(seg.getTracker().frameCount(), 1u);
  EXPECT_EQ(seg.getTrackIds(), (std::vector<std::uint32_t>{1, 2, 3}));
  // A call that segments nothing is no frame.
  seg.setInputCloud(pcl::PointCloud<pcl::PointXYZ>::Ptr(new pcl::PointCloud<pcl::PointXYZ>));
  segmentAndRefine(seg);
  EXPECT_TRUE(seg.getTrackIds().empty());
  EXPECT_EQ(seg.getTracker().frameCount(), 1u);
}

TEST(FloodFillPlaneSegmentation, ContinuesFromThePreviousCloudWithAHeadStart) {
  const auto first = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 7));
  const auto second = toCloud<pcl::PointXYZ>(test::render(kinect(), test::roomCorner(), 0.004, 8));
  FloodFillPlaneSegmentation<pcl::PointXYZ> cold, warm;
  EXPECT_FALSE(warm.getHeadStart());
  warm.setHeadStart(true);
  EXPECT_TRUE(warm.getHeadStart());
  warm.setInputCloud(first);
  segmentAndRefine(warm);
  EXPECT_FALSE(warm.getLastSegmentation().stats.head_start) << "the first cloud";
  const NoiseModel first_noise = warm.getLastSegmentation().noise;
  for (auto* seg : {&cold, &warm}) seg->setInputCloud(second);
  const AllOutputs<pcl::PointXYZ> from_cold = segmentAndRefine(cold);
  const AllOutputs<pcl::PointXYZ> from_warm = segmentAndRefine(warm);
  EXPECT_FALSE(cold.getLastSegmentation().stats.head_start);
  EXPECT_TRUE(warm.getLastSegmentation().stats.head_start);
  EXPECT_EQ(warm.getLastSegmentation().noise.sigma_quadratic, first_noise.sigma_quadratic);
  EXPECT_NE(cold.getLastSegmentation().noise.sigma_quadratic, first_noise.sigma_quadratic);
  ASSERT_EQ(from_warm.coefficients.size(), from_cold.coefficients.size());
  for (std::size_t k = 0; k < from_cold.coefficients.size(); ++k) {
    const auto& a = from_warm.coefficients[k].values;
    const auto& b = from_cold.coefficients[k].values;
    EXPECT_GT(a[0] * b[0] + a[1] * b[1] + a[2] * b[2], 0.9999) << "plane " << k;
  }
  // A changed parameter: the next cloud starts cold, the one after continues.
  warm.setMaximumCurvature(0.3);
  segmentAndRefine(warm);
  EXPECT_FALSE(warm.getLastSegmentation().stats.head_start);
  segmentAndRefine(warm);
  EXPECT_TRUE(warm.getLastSegmentation().stats.head_start);
}

}  // namespace
}  // namespace floodplane
