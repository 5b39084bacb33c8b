// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The segmentation methods pcd_compare runs: their common interface and how each is made. Each
// method lives in its own file so that the heavy PCL headers (sample consensus, OMPS, normal
// estimation) are compiled once, in the file that needs them.

#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pcd_compare {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Clock = std::chrono::steady_clock;
/// A value per parameter name.
using ParameterValues = std::map<std::string, double>;

/// The time from `start` to now. [ms]
inline double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// A label cloud's values, one per pixel of a cloud of `size` points; all 0 (nothing found)
/// when there is no label cloud of that size, as after bad data.
inline std::vector<std::uint32_t> labelValues(const pcl::PointCloud<pcl::Label>* labels, std::size_t size) {
  std::vector<std::uint32_t> values;
  if (labels != nullptr && labels->size() == size) {
    values.reserve(size);
    for (const pcl::Label& label : *labels) values.push_back(label.label);
  }
  values.resize(size, 0);
  return values;
}

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
  Method(std::string name, bool slow) : name_(std::move(name)), slow_(slow) {}
  virtual ~Method() = default;
  /// Short name used in tables, file names and --methods.
  const std::string& name() const { return name_; }
  /// Every parameter that decides the result, as text for the configuration block.
  virtual std::string parameters() const = 0;
  /// Segments one organized cloud. Deterministic: the same cloud gives the same labels.
  virtual MethodRun run(const Cloud::ConstPtr& cloud) = 0;
  /// Seconds a cloud (the sequential RANSACs): timed once, on the scored run, whatever
  /// --repeat says; their accuracy is the point of running them, not their exact time.
  bool slow() const { return slow_; }

 private:
  std::string name_;
  bool slow_;
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

/// floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ> with the library's defaults, at
/// the given sub-sampling factor.
std::unique_ptr<Method> makeFloodplaneMethod(std::optional<int> subsampling = std::nullopt);

// The baselines whose parameters can be tuned (PCL's OMPS and RANSAC, Open3D's RANSAC), made
// from values by name (baselines.cpp), and the tuned values that bench/tune_baselines.py writes
// per baseline and sensor model, which --tuned reads.

/// Per baseline, then per sensor model, the tuned values.
using TunedValues = std::map<std::string, std::map<std::string, ParameterValues>>;

/// The tunable `baseline` at `values` (missing names take their defaults), named `name`.
/// Throws std::invalid_argument for an unknown parameter or a value out of range.
std::unique_ptr<Method> makeBaseline(const std::string& baseline, const ParameterValues& values,
                                     const std::string& name);
/// Every parameter of `baseline` with its value, the defaults filled in: "name=value, ...".
std::string describeValues(const std::string& baseline, const ParameterValues& values);
/// Reads a tuning result; std::runtime_error naming the file if it cannot be read, parsed, or
/// names an unknown baseline, parameter or bad value.
TunedValues readTunedValues(const std::string& path);

// Each baseline at `values` that name every parameter with a valid value: makeBaseline fills in
// the defaults and checks them.
/// PCL's sequential RANSAC.
std::unique_ptr<Method> makeRansacMethod(const ParameterValues& values, const std::string& name);
/// Open3D's SegmentPlane, sequentially.
std::unique_ptr<Method> makeOpen3dRansacMethod(const ParameterValues& values, const std::string& name);
/// PCL's IntegralImageNormalEstimation + OrganizedMultiPlaneSegmentation::segmentAndRefine.
std::unique_ptr<Method> makeOmpsMethod(const ParameterValues& values, const std::string& name);

}  // namespace pcd_compare

namespace pcd_compare {

// The object methods of --objects: the same interface, MethodRun::labels an object id per pixel
// (0 = no object, 1..K). Each lives in its own file (the heavy PCL headers compiled once there)
// and stands in objectMethods()' table (object_methods.cpp) under its name.

/// A factory of an object method.
using ObjectMethodFactory = std::unique_ptr<Method> (*)();
/// The object methods by name, in the order --objects runs them by default.
const std::vector<std::pair<std::string, ObjectMethodFactory>>& objectMethods();

/// floodplane's PCL class: segmentAndRefine, then segmentObjects (floodplane_objects_method.cpp).
std::unique_ptr<Method> makeFloodplaneObjectsMethod();
/// PCL's organized tabletop pipeline as its apps/organized_segmentation_demo runs it
/// (pcl_organized_objects_method.cpp).
std::unique_ptr<Method> makePclOrganizedObjectsMethod();
/// PCL's supervoxels and LCCPSegmentation, as its example_lccp_segmentation runs them by default
/// (lccp_objects_method.cpp).
std::unique_ptr<Method> makeLccpObjectsMethod();
/// The same with the example's -ec -sc: extended convexity and the sanity criterion.
std::unique_ptr<Method> makeLccpExtendedObjectsMethod();

}  // namespace pcd_compare
