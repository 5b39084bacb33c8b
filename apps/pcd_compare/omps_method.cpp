// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PCL's OrganizedMultiPlaneSegmentation with integral-image normals, as in PCL's own
// organized segmentation demo (its settings and the one safe call in baselines/omps_run.h).

#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <sstream>

#include "baselines/omps_run.h"
#include "method.h"

namespace pcd_compare {

namespace {

class OmpsMethod : public Method {
 public:
  OmpsMethod(const ParameterValues& values, std::string name) : Method(std::move(name), false), values_(values) {
    normal_estimation_.setNormalEstimationMethod(normal_estimation_.AVERAGE_3D_GRADIENT);
    normal_estimation_.setMaxDepthChangeFactor(static_cast<float>(values.at("max_depth_change_factor")));
    normal_estimation_.setNormalSmoothingSize(static_cast<float>(values.at("normal_smoothing_size")));
    segmentation_.setAngularThreshold(values.at("angular_threshold"));
    segmentation_.setDistanceThreshold(values.at("distance_threshold"));
    segmentation_.setMaximumCurvature(values.at("maximum_curvature"));
    segmentation_.setMinInliers(static_cast<unsigned>(values.at("min_inliers")));
  }

  std::string parameters() const override {
    std::ostringstream text;
    text << "pcl::IntegralImageNormalEstimation AVERAGE_3D_GRADIENT, max depth change factor "
         << values_.at("max_depth_change_factor") << ", normal smoothing size " << values_.at("normal_smoothing_size")
         << "; pcl::OrganizedMultiPlaneSegmentation<PointXYZ, Normal, Label>::segmentAndRefine, "
            "angular threshold "
         << segmentation_.getAngularThreshold() << " rad, distance threshold " << segmentation_.getDistanceThreshold()
         << " m, min inliers " << segmentation_.getMinInliers() << ", maximum curvature "
         << segmentation_.getMaximumCurvature() << "; time includes normals";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    MethodRun result;
    if (!floodplane::baselines::normalWindowFits(cloud->width, cloud->height, values_.at("normal_smoothing_size"))) {
      // No normal, so no plane: a valid frame too small for OMPS (PCL would write past it).
      result.labels.assign(cloud->size(), 0);
      result.total_ms = millisecondsSince(start);
      result.parts_ms.emplace_back("normals", 0.0);
      return result;
    }
    const double normals_ms =
        floodplane::baselines::normalsThenPlanes(normal_estimation_, segmentation_, cloud, outputs_);
    result.total_ms = millisecondsSince(start);
    result.parts_ms.emplace_back("normals", normals_ms);
    // OMPS's label cloud numbers connected components, not planes; the planes are the
    // refined inlier sets, so region k becomes label k + 1.
    result.labels.assign(cloud->size(), 0);
    for (std::size_t k = 0; k < outputs_.inliers.size(); ++k) {
      for (const pcl::index_t index : outputs_.inliers[k].indices) {
        result.labels[static_cast<std::size_t>(index)] = static_cast<std::uint32_t>(k + 1);
      }
    }
    return result;
  }

 private:
  ParameterValues values_;  // for the description: PCL's normal estimation has no getters
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation_;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> segmentation_;
  floodplane::baselines::OmpsOutputs<pcl::PointXYZ> outputs_;
};

}  // namespace

std::unique_ptr<Method> makeOmpsMethod(const ParameterValues& values, const std::string& name) {
  return std::make_unique<OmpsMethod>(values, name);
}

}  // namespace pcd_compare
