// PCL's sequential RANSAC baseline: find the best plane, take its inliers away, repeat.

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "method.h"

namespace pcd_compare {

namespace {

class RansacMethod : public Method {
 public:
  RansacMethod(const SequentialRansacParameters& parameters, std::string name)
      : parameters_(parameters), name_(std::move(name)) {
    // SACSegmentation's default `random = false` makes every RANSAC it creates seed its
    // generator with the fixed 12345 (pcl/sample_consensus/sac_model.h), so runs repeat
    // exactly; srand covers any std::rand use inside PCL as well.
    std::srand(12345u);
    segmentation_.setModelType(pcl::SACMODEL_PLANE);
    segmentation_.setMethodType(pcl::SAC_RANSAC);
    segmentation_.setDistanceThreshold(parameters_.distance_threshold);
    segmentation_.setOptimizeCoefficients(true);
  }

  std::string name() const override { return name_; }
  bool slow() const override { return true; }

  std::string parameters() const override {
    std::ostringstream text;
    text << "pcl::SACSegmentation<PointXYZ> SACMODEL_PLANE, SAC_RANSAC, distance threshold "
         << parameters_.distance_threshold << " m, optimize coefficients, max iterations "
         << segmentation_.getMaxIterations() << " and probability " << segmentation_.getProbability()
         << " (PCL defaults), single thread; sequential: extract the best plane, repeat on "
            "the rest until a plane has < "
         << parameters_.min_inliers
         << " inliers; NaN points excluded first (by index); fixed seed 12345 (PCL's "
            "non-random mode), deterministic";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    using Clock = std::chrono::steady_clock;
    MethodRun result;
    result.labels.assign(cloud->size(), 0);
    const auto start = Clock::now();

    // The remaining points as indices into the organized cloud: the inliers PCL returns are
    // then grid positions, and no copy of the cloud is made per plane.
    auto remaining = std::make_shared<pcl::Indices>();
    remaining->reserve(cloud->size());
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      const pcl::PointXYZ& p = (*cloud)[i];
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
        remaining->push_back(static_cast<pcl::index_t>(i));
      }
    }
    segmentation_.setInputCloud(cloud);
    std::uint32_t next_label = 1;
    while (remaining->size() >= 3) {
      segmentation_.setIndices(remaining);
      segmentation_.segment(inliers_, coefficients_);
      if (inliers_.indices.size() < parameters_.min_inliers) {
        break;
      }
      for (const pcl::index_t index : inliers_.indices) {
        result.labels[static_cast<std::size_t>(index)] = next_label;
      }
      ++next_label;
      // Inliers are a subset of `remaining`; keep the rest, in order.
      auto rest = std::make_shared<pcl::Indices>();
      rest->reserve(remaining->size() - inliers_.indices.size());
      for (const pcl::index_t index : *remaining) {
        if (result.labels[static_cast<std::size_t>(index)] == 0) {
          rest->push_back(index);
        }
      }
      remaining = rest;
    }
    const std::chrono::duration<double, std::milli> elapsed = Clock::now() - start;
    result.total_ms = elapsed.count();
    return result;
  }

 private:
  SequentialRansacParameters parameters_;
  std::string name_;
  pcl::SACSegmentation<pcl::PointXYZ> segmentation_;
  pcl::PointIndices inliers_;
  pcl::ModelCoefficients coefficients_;
};

}  // namespace

std::unique_ptr<Method> makeRansacMethod(const SequentialRansacParameters& parameters, const std::string& name) {
  return std::make_unique<RansacMethod>(parameters, name);
}

}  // namespace pcd_compare
