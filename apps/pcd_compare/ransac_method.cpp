// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PCL's sequential RANSAC baseline: find the best plane, take its inliers away, repeat.

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <cstdlib>
#include <memory>
#include <sstream>

#include "method.h"

namespace pcd_compare {

namespace {

class RansacMethod : public Method {
 public:
  RansacMethod(const ParameterValues& values, std::string name)
      : Method(std::move(name), true), min_inliers_(static_cast<std::size_t>(values.at("min_inliers"))) {
    // SACSegmentation's default `random = false` makes every RANSAC it creates seed its
    // generator with the fixed 12345 (pcl/sample_consensus/sac_model.h), so runs repeat
    // exactly; srand covers any std::rand use inside PCL as well.
    std::srand(12345u);
    segmentation_.setModelType(pcl::SACMODEL_PLANE);
    segmentation_.setMethodType(pcl::SAC_RANSAC);
    segmentation_.setDistanceThreshold(values.at("distance_threshold"));
    segmentation_.setOptimizeCoefficients(true);
  }

  std::string parameters() const override {
    std::ostringstream text;
    text << "pcl::SACSegmentation<PointXYZ> SACMODEL_PLANE, SAC_RANSAC, distance threshold "
         << segmentation_.getDistanceThreshold() << " m, optimize coefficients, max iterations "
         << segmentation_.getMaxIterations() << " and probability " << segmentation_.getProbability()
         << " (PCL defaults), single thread; sequential: extract the best plane, repeat on "
            "the rest until a plane has < "
         << min_inliers_
         << " inliers; NaN points excluded first (by index); fixed seed 12345 (PCL's "
            "non-random mode), deterministic";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    segmentation_.setInputCloud(cloud);
    MethodRun result;
    // The remaining points as indices into the organized cloud: the inliers PCL returns are
    // then grid positions, and no copy of the cloud is made per plane.
    result.labels = extractPlanesInTurn(*cloud, min_inliers_, 3, [this](const pcl::Indices& remaining) {
      segmentation_.setIndices(std::make_shared<const pcl::Indices>(remaining));
      segmentation_.segment(inliers_, coefficients_);
      return inliers_.indices;
    });
    result.total_ms = millisecondsSince(start);
    return result;
  }

 private:
  std::size_t min_inliers_;
  pcl::SACSegmentation<pcl::PointXYZ> segmentation_;
  pcl::PointIndices inliers_;
  pcl::ModelCoefficients coefficients_;
};

}  // namespace

std::unique_ptr<Method> makeRansacMethod(const ParameterValues& values, const std::string& name) {
  return std::make_unique<RansacMethod>(values, name);
}

}  // namespace pcd_compare
