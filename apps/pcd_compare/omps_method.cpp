// PCL's OrganizedMultiPlaneSegmentation with integral-image normals, as in PCL's own
// organized segmentation demo.

#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include <chrono>
#include <sstream>

#include "method.h"

namespace pcd_compare {

namespace {

constexpr float kMaxDepthChangeFactor = 0.02f;
constexpr float kNormalSmoothingSize = 6.0f;
constexpr double kAngularThreshold = 0.09;  // [rad]
constexpr double kDistanceThreshold = 0.02;  // [m]
constexpr unsigned kMinInliers = 50;

class OmpsMethod : public Method {
 public:
  OmpsMethod() {
    normal_estimation_.setNormalEstimationMethod(
        pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal>::AVERAGE_3D_GRADIENT);
    normal_estimation_.setMaxDepthChangeFactor(kMaxDepthChangeFactor);
    normal_estimation_.setNormalSmoothingSize(kNormalSmoothingSize);
    segmentation_.setMinInliers(kMinInliers);
    segmentation_.setAngularThreshold(kAngularThreshold);
    segmentation_.setDistanceThreshold(kDistanceThreshold);
  }

  std::string name() const override { return "omps"; }

  std::string parameters() const override {
    std::ostringstream text;
    text << "pcl::IntegralImageNormalEstimation AVERAGE_3D_GRADIENT, max depth change factor "
         << kMaxDepthChangeFactor << ", normal smoothing size " << kNormalSmoothingSize
         << "; pcl::OrganizedMultiPlaneSegmentation<PointXYZ, Normal, Label>::segmentAndRefine, "
            "angular threshold "
         << segmentation_.getAngularThreshold() << " rad, distance threshold "
         << segmentation_.getDistanceThreshold() << " m, min inliers "
         << segmentation_.getMinInliers() << ", maximum curvature "
         << segmentation_.getMaximumCurvature() << " (PCL default); time includes normals";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
    normal_estimation_.setInputCloud(cloud);
    normal_estimation_.compute(*normals);
    const auto normals_done = Clock::now();

    segmentation_.setInputNormals(normals);
    segmentation_.setInputCloud(cloud);
    auto labels = std::make_shared<pcl::PointCloud<pcl::Label>>();
    // PCL 1.13's segment() appends to the coefficient and inlier vectors it is given, and
    // refine() then indexes its per-label tables with the stale entries' labels: past their
    // end on the next cloud (heap corruption, seen as "double free or corruption" several
    // files into a batch). Every output starts empty.
    regions_.clear();
    coefficients_.clear();
    inliers_.clear();
    label_indices_.clear();
    boundaries_.clear();
    segmentation_.segmentAndRefine(regions_, coefficients_, inliers_, labels, label_indices_,
                                   boundaries_);
    const auto end = Clock::now();

    MethodRun result;
    result.total_ms = std::chrono::duration<double, std::milli>(end - start).count();
    result.parts_ms.emplace_back(
        "normals", std::chrono::duration<double, std::milli>(normals_done - start).count());
    // OMPS's label cloud numbers connected components, not planes; the planes are the
    // refined inlier sets, so region k becomes label k + 1.
    result.labels.assign(cloud->size(), 0);
    for (std::size_t k = 0; k < inliers_.size(); ++k) {
      for (const pcl::index_t index : inliers_[k].indices) {
        result.labels[static_cast<std::size_t>(index)] = static_cast<std::uint32_t>(k + 1);
      }
    }
    return result;
  }

 private:
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normal_estimation_;
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> segmentation_;
  std::vector<pcl::PlanarRegion<pcl::PointXYZ>,
              Eigen::aligned_allocator<pcl::PlanarRegion<pcl::PointXYZ>>>
      regions_;
  std::vector<pcl::ModelCoefficients> coefficients_;
  std::vector<pcl::PointIndices> inliers_;
  std::vector<pcl::PointIndices> label_indices_;
  std::vector<pcl::PointIndices> boundaries_;
};

}  // namespace

std::unique_ptr<Method> makeOmpsMethod() { return std::make_unique<OmpsMethod>(); }

}  // namespace pcd_compare
