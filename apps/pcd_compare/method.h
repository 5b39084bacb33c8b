#pragma once
// The common interface of the segmentation methods pcd_compare runs. Each method lives in its
// own file so that the heavy PCL headers (sample consensus, OMPS, normal estimation) are
// compiled once, in the file that needs them.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "floodplane/segmenter.h"

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
  /// floodplane's own phase times, when it was asked to measure them (Fig. 5).
  std::optional<floodplane::PhaseTimes> phases;
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
};

/// floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> with the library's defaults, at
/// the given sub-sampling factor; `measure_phases` turns on its phase timer.
std::unique_ptr<Method> makeFloodplaneMethod(int subsampling = 1, bool measure_phases = false);
/// PCL's sequential RANSAC: the best plane, removed, again, until one has < 100 inliers.
std::unique_ptr<Method> makeRansacMethod();
/// PCL's IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation::segmentAndRefine.
std::unique_ptr<Method> makeOmpsMethod();

}  // namespace pcd_compare
