// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// floodplane's objects on the planes, through its PCL drop-in class as a user would call it:
// segmentAndRefine for the planes, then segmentObjects for what stands on them.

#include <sstream>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/io/params_json.h"
#include "method.h"

namespace pcd_compare {

namespace {

class FloodplaneObjectsMethod : public Method {
 public:
  FloodplaneObjectsMethod() : Method("floodplane", false) {}

  std::string parameters() const override {
    std::ostringstream text;
    text << "FloodFillPlaneSegmentation<PointXYZ>::segmentAndRefine then segmentObjects, library defaults: "
         << floodplane::io::describeParams(segmentation_.getParams())
         << "; floodplane::ObjectOptions defaults; time includes the planes";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    segmentation_.setInputCloud(cloud);
    segmentation_.segmentAndRefine(regions_, coefficients_, inliers_, labels_, label_indices_, boundaries_);
    const double planes_ms = millisecondsSince(start);
    segmentation_.segmentObjects(objects_, object_indices_);
    MethodRun result;
    result.total_ms = millisecondsSince(start);
    result.parts_ms = {{"planes", planes_ms}, {"objects", result.total_ms - planes_ms}};
    // The object cloud numbers object k as label k, 0 for no object.
    result.labels = labelValues(&objects_, cloud->size());
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
  pcl::PointCloud<pcl::Label> objects_;
  std::vector<pcl::PointIndices> object_indices_;
};

}  // namespace

std::unique_ptr<Method> makeFloodplaneObjectsMethod() { return std::make_unique<FloodplaneObjectsMethod>(); }

}  // namespace pcd_compare
