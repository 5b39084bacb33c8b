// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane itself, through its PCL drop-in class, as a user would call it.

#include <optional>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/io/params_json.h"
#include "method.h"

namespace pcd_compare {

namespace {

class FloodplaneMethod : public Method {
 public:
  // The library's defaults as "floodplane", or sub-sampling s as "floodplane/s".
  explicit FloodplaneMethod(std::optional<int> subsampling)
      : Method(subsampling ? "floodplane/" + std::to_string(*subsampling) : "floodplane", false) {
    if (subsampling) segmentation_.setSubsampling(*subsampling);
  }

  std::string parameters() const override {
    return "FloodFillPlaneSegmentation<PointXYZ>::segmentAndRefine, library defaults: " +
           floodplane::io::describeParams(segmentation_.getParams());
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    segmentation_.setInputCloud(cloud);
    segmentation_.segmentAndRefine(regions_, coefficients_, inliers_, labels_, label_indices_, boundaries_);
    MethodRun result;
    result.total_ms = millisecondsSince(start);
    // The label cloud is documented to number plane k as label k, 0 for no plane.
    result.labels = labelValues(labels_.get(), cloud->size());
    return result;
  }

 private:
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation_;
  // Kept between runs, as an application segmenting a stream would.
  floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>::Regions regions_;
  std::vector<pcl::ModelCoefficients> coefficients_;
  std::vector<pcl::PointIndices> inliers_;
  pcl::PointCloud<pcl::Label>::Ptr labels_;
  std::vector<pcl::PointIndices> label_indices_;
  std::vector<pcl::PointIndices> boundaries_;
};

}  // namespace

std::unique_ptr<Method> makeFloodplaneMethod(std::optional<int> subsampling) {
  return std::make_unique<FloodplaneMethod>(subsampling);
}

}  // namespace pcd_compare
