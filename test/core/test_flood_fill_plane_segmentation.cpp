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
  EXPECT_EQ(seg.getSubsampling(), 1);
  EXPECT_DOUBLE_EQ(seg.getAngularThreshold(), 0.1);
}

TEST(FloodFillPlaneSegmentation, DerivesThePapersLengthsFromEachFrameUnlessTheyAreSet) {
  FloodFillPlaneSegmentation<pcl::PointXYZ> seg;
  EXPECT_DOUBLE_EQ(seg.getDistanceThreshold(), 0.0);  // sigma_plane: derived
  EXPECT_DOUBLE_EQ(seg.getSeedSize(), 0.0);           // sigma_seed: derived
  EXPECT_DOUBLE_EQ(seg.getMergeDistance(), 0.0);      // sigma_plane-merge: derived
  EXPECT_DOUBLE_EQ(seg.getAngularThreshold(), 0.1);   // theta_angle, the paper's
  EXPECT_EQ(seg.getSubsampling(), 1);
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

}  // namespace
}  // namespace floodplane
