#pragma once
// The common interface of the segmentation methods pcd_compare runs. Each method lives in its
// own file so that the heavy PCL headers (sample consensus, OMPS, normal estimation) are
// compiled once, in the file that needs them.

#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "common/omps_run.h"

namespace pcd_compare {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// What one run of a method gives back.
struct MethodRun {
  /// A label per pixel of the organized grid, row-major; 0 = no plane.
  std::vector<std::uint32_t> labels;
  /// Time of the whole segmentation (everything from the organized cloud in memory to the
  /// method's own output; not the conversion to `labels`). [ms]
  double total_ms = 0.0;
  /// Named parts of total_ms worth reporting on their own (OMPS: "normals"). [ms]
  std::vector<std::pair<std::string, double>> parts_ms;
};

class Method {
 public:
  virtual ~Method() = default;
  /// Short name used in tables, file names and --methods.
  virtual std::string name() const = 0;
  /// Every parameter that decides the result, as text for the configuration block.
  virtual std::string parameters() const = 0;
  /// Segments one organized cloud. Deterministic: the same cloud gives the same labels.
  virtual MethodRun run(const Cloud::ConstPtr& cloud) = 0;
  /// Seconds a cloud (the sequential RANSACs): timed once, on the scored run, whatever
  /// --repeat says; their accuracy is the point of running them, not their exact time.
  virtual bool slow() const { return false; }
};

/// The sequential extraction both RANSAC baselines run: `best_plane(remaining)` gives the
/// inliers (pixel indices) of the best plane through `remaining` (the pixels of the finite
/// points not yet labelled, in grid order); planes are labelled 1, 2, ... in extraction order
/// until one has fewer than `min_inliers` inliers or fewer than `min_points` points are left.
template <typename BestPlane>
std::vector<std::uint32_t> extractPlanesInTurn(const Cloud& cloud, std::size_t min_inliers, std::size_t min_points,
                                               BestPlane best_plane) {
  std::vector<std::uint32_t> labels(cloud.size(), 0);
  pcl::Indices remaining;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (pcl::isFinite(cloud[i])) remaining.push_back(static_cast<pcl::index_t>(i));
  }
  const auto labelled = [&labels](pcl::index_t i) { return labels[static_cast<std::size_t>(i)] != 0; };
  for (std::uint32_t label = 1; remaining.size() >= min_points; ++label) {
    const pcl::Indices inliers = best_plane(remaining);
    if (inliers.size() < min_inliers) break;
    for (const pcl::index_t index : inliers) labels[static_cast<std::size_t>(index)] = label;
    remaining.erase(std::remove_if(remaining.begin(), remaining.end(), labelled), remaining.end());
  }
  return labels;
}

/// The parameters of a sequential RANSAC (PCL's or Open3D's): the best plane is extracted,
/// then the best plane of the rest, until a plane has fewer than `min_inliers` inliers.
struct SequentialRansacParameters {
  double distance_threshold = 0.01;  ///< inlier distance from the plane [m]
  std::size_t min_inliers = 100;     ///< the plane that stops the sequence (and is dropped)
};

/// The parameters of PCL's IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation.
/// The defaults are the paper's Sec. IV settings (common/omps_run.h) and PCL's default maximum
/// curvature.
struct OmpsParameters {
  using Settings = floodplane::apps::OmpsSettings;
  double angular_threshold = Settings::angular_threshold;          ///< [rad]
  double distance_threshold = Settings::distance_threshold;        ///< [m]
  double normal_smoothing_size = Settings::normal_smoothing_size;  ///< [pixels]
  /// Depth change that ends a normal's smoothing area, as a factor of the depth [1/m].
  double max_depth_change_factor = Settings::max_depth_change_factor;
  double maximum_curvature = 0.001;  ///< of a region's points; PCL's default
  std::size_t min_inliers = Settings::min_inliers;
};

/// floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> with the library's defaults, at
/// the given sub-sampling factor.
std::unique_ptr<Method> makeFloodplaneMethod(int subsampling = 1);
/// PCL's sequential RANSAC. Labels number the planes in the order they were extracted.
std::unique_ptr<Method> makeRansacMethod(const SequentialRansacParameters& parameters = {},
                                         const std::string& name = "ransac");
/// Open3D's SegmentPlane, sequentially. Labels number the planes in the order they were
/// extracted.
std::unique_ptr<Method> makeOpen3dRansacMethod(const SequentialRansacParameters& parameters = {},
                                               const std::string& name = "open3d_ransac");
/// PCL's IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation::segmentAndRefine.
std::unique_ptr<Method> makeOmpsMethod(const OmpsParameters& parameters = {}, const std::string& name = "omps");

}  // namespace pcd_compare
