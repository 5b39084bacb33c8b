// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PCL's organized tabletop pipeline, as its apps/organized_segmentation_demo runs it with
// Euclidean clustering on: integral-image normals, OrganizedMultiPlaneSegmentation's
// segmentAndRefine for the planes, then OrganizedConnectedComponentSegmentation with a
// EuclideanClusterComparator over the points on no plane; clusters of more than 1000 points are
// the objects. Every setting is the demo's.

#include <pcl/common/angles.h>
#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/euclidean_cluster_comparator.h>
#include <pcl/segmentation/organized_connected_component_segmentation.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <limits>
#include <sstream>
#include <vector>

#include "baselines/omps_run.h"
#include "method.h"

namespace pcd_compare {

namespace {

// The demo's settings (PCL 1.13 apps/src/organized_segmentation_demo.cpp).
constexpr float kMaxDepthChangeFactor = 0.02f;
constexpr float kNormalSmoothingSize = 20.0f;  // [pixels]
constexpr unsigned kPlaneMinInliers = 10000;
constexpr double kAngularThresholdDegrees = 3.0;
constexpr double kPlaneDistanceThreshold = 0.02;    // [m]
constexpr float kClusterDistanceThreshold = 0.01f;  // [m], between grid neighbours, not depth-dependent
constexpr std::size_t kMinClusterPoints = 1000;     // a cluster is an object with more points

class PclOrganizedObjectsMethod : public Method {
 public:
  PclOrganizedObjectsMethod() : Method("pcl_organized", false) {
    normal_estimation_.setNormalEstimationMethod(normal_estimation_.COVARIANCE_MATRIX);
    normal_estimation_.setMaxDepthChangeFactor(kMaxDepthChangeFactor);
    normal_estimation_.setNormalSmoothingSize(kNormalSmoothingSize);
    planes_.setMinInliers(kPlaneMinInliers);
    planes_.setAngularThreshold(pcl::deg2rad(kAngularThresholdDegrees));
    planes_.setDistanceThreshold(kPlaneDistanceThreshold);
    comparator_->setDistanceThreshold(kClusterDistanceThreshold, false);
  }

  std::string parameters() const override {
    std::ostringstream text;
    text << "PCL's organized_segmentation_demo with Euclidean clustering: "
            "pcl::IntegralImageNormalEstimation COVARIANCE_MATRIX, max depth change factor "
         << kMaxDepthChangeFactor << ", normal smoothing size " << kNormalSmoothingSize
         << "; pcl::OrganizedMultiPlaneSegmentation::segmentAndRefine, min inliers " << kPlaneMinInliers
         << ", angular threshold " << kAngularThresholdDegrees << " deg, distance threshold " << kPlaneDistanceThreshold
         << " m; the points of no region over " << kPlaneMinInliers
         << " points clustered by pcl::OrganizedConnectedComponentSegmentation with "
            "pcl::EuclideanClusterComparator at "
         << kClusterDistanceThreshold << " m (the planes' points masked as NaN: PCL 1.13's exclude-label test is "
         << "inverted); clusters over " << kMinClusterPoints << " points are the objects; time includes normals";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    MethodRun result;
    result.labels.assign(cloud->size(), 0);
    if (!floodplane::baselines::normalWindowFits(cloud->width, cloud->height, kNormalSmoothingSize)) {
      // No normal, so no plane and no object: a valid frame too small for the normals' window.
      result.total_ms = millisecondsSince(start);
      result.parts_ms.emplace_back("normals", 0.0);
      return result;
    }
    const double normals_ms = floodplane::baselines::normalsThenPlanes(normal_estimation_, planes_, cloud, outputs_);

    // The demo's planes: the label cloud's regions of more than min-inliers points.
    std::vector<bool> plane_label(outputs_.label_indices.size(), false);
    for (std::size_t k = 0; k < outputs_.label_indices.size(); ++k) {
      plane_label[k] = outputs_.label_indices[k].indices.size() > kPlaneMinInliers;
    }
    // The demo passes these labels to EuclideanClusterComparator::setExcludeLabels, meaning
    // "never join a point on a plane". PCL 1.13's compare() tests the opposite: it joins two
    // points only when both labels ARE in the set, so the demo's call clusters the planes and
    // leaves the objects alone. The same intent without that test: the planes' points become
    // NaN in a copy of the cloud, which OrganizedConnectedComponentSegmentation skips, and the
    // comparator gets no labels.
    *off_planes_ = *cloud;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < off_planes_->size(); ++i) {
      const std::uint32_t label = (*outputs_.labels)[i].label;
      if (label < plane_label.size() && plane_label[label])
        (*off_planes_)[i].x = (*off_planes_)[i].y = (*off_planes_)[i].z = nan;
    }
    off_planes_->is_dense = false;
    comparator_->setInputCloud(off_planes_);
    pcl::OrganizedConnectedComponentSegmentation<pcl::PointXYZ, pcl::Label> clustering(comparator_);
    clustering.setInputCloud(off_planes_);
    clusters_.clear();
    cluster_indices_.clear();
    clustering.segment(clusters_, cluster_indices_);
    result.total_ms = millisecondsSince(start);
    result.parts_ms.emplace_back("normals", normals_ms);

    std::uint32_t object = 0;
    for (const pcl::PointIndices& cluster : cluster_indices_) {
      if (cluster.indices.size() <= kMinClusterPoints) continue;
      ++object;
      for (const pcl::index_t index : cluster.indices) result.labels[static_cast<std::size_t>(index)] = object;
    }
    return result;
  }

 private:
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation_;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> planes_;
  floodplane::baselines::OmpsOutputs<pcl::PointXYZ> outputs_;
  pcl::EuclideanClusterComparator<pcl::PointXYZ, pcl::Label>::Ptr comparator_ =
      std::make_shared<pcl::EuclideanClusterComparator<pcl::PointXYZ, pcl::Label>>();
  Cloud::Ptr off_planes_ = std::make_shared<Cloud>();
  pcl::PointCloud<pcl::Label> clusters_;
  std::vector<pcl::PointIndices> cluster_indices_;
};

}  // namespace

std::unique_ptr<Method> makePclOrganizedObjectsMethod() { return std::make_unique<PclOrganizedObjectsMethod>(); }

}  // namespace pcd_compare
