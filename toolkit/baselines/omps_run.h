// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// PCL's OrganizedMultiPlaneSegmentation as pcd_compare and the benchmarks run it: the settings
// of the paper's Sec. IV, the outputs of segmentAndRefine kept between calls, and the one safe
// way to call it on them. Header-only and without PCL's normal-estimation and segmentation
// headers: the caller, which has included them, passes its objects.

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/planar_region.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

namespace floodplane::baselines {

/// The settings of the paper's Sec. IV (PCL's organized segmentation demo).
struct OmpsSettings {
  static constexpr double max_depth_change_factor = 0.02;
  static constexpr double normal_smoothing_size = 6.0;  ///< [pixels]
  static constexpr double angular_threshold = 0.09;     ///< [rad]
  static constexpr double distance_threshold = 0.02;    ///< [m]
  static constexpr unsigned min_inliers = 50;
};

/// Sets `normal_estimation` (pcl::IntegralImageNormalEstimation) to average 3-D gradients and
/// `omps` (pcl::OrganizedMultiPlaneSegmentation) to OmpsSettings.
template <typename NormalEstimation, typename Omps>
void configureOmps(NormalEstimation& normal_estimation, Omps& omps) {
  normal_estimation.setNormalEstimationMethod(NormalEstimation::AVERAGE_3D_GRADIENT);
  normal_estimation.setMaxDepthChangeFactor(static_cast<float>(OmpsSettings::max_depth_change_factor));
  normal_estimation.setNormalSmoothingSize(static_cast<float>(OmpsSettings::normal_smoothing_size));
  omps.setMinInliers(OmpsSettings::min_inliers);
  omps.setAngularThreshold(OmpsSettings::angular_threshold);
  omps.setDistanceThreshold(OmpsSettings::distance_threshold);
}

template <typename PointT>
struct OmpsOutputs {
  std::vector<pcl::PlanarRegion<PointT>, Eigen::aligned_allocator<pcl::PlanarRegion<PointT>>> regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;  ///< plane k's pixels: the refined inlier set
  pcl::PointCloud<pcl::Label>::Ptr labels = std::make_shared<pcl::PointCloud<pcl::Label>>();
  std::vector<pcl::PointIndices> label_indices;
  std::vector<pcl::PointIndices> boundaries;
};

/// Whether PCL's IntegralImageNormalEstimation (border policy "ignore", the default) can run
/// on a `width` x `height` grid at `normal_smoothing_size` [pixels]. It leaves a border that
/// wide without normals, and on a grid not wider and higher than twice that it has no normal
/// to compute but writes the border past the grid's end (PCL 1.13: a crash on a 2 x 2 frame).
/// Such a frame has no normal, so OMPS finds no plane in it: callers skip it.
inline bool normalWindowFits(std::uint32_t width, std::uint32_t height, double normal_smoothing_size) {
  const std::uint64_t border = static_cast<std::uint64_t>(normal_smoothing_size);
  return width > 2 * border && height > 2 * border;
}

/// Runs `omps.segmentAndRefine` into `outputs`, every output emptied first. PCL 1.13 needs
/// this: segment() appends to the coefficient and inlier vectors it is given, and refine()
/// then indexes its per-label tables with the stale entries' labels, past their end on the
/// next cloud (heap corruption, seen as "double free or corruption" several files into a
/// batch). Its OrganizedConnectedComponentSegmentation resizes the label cloud with an
/// "invalid" fill that only reaches new elements, so labels left at NaN pixels by the
/// previous call index past its run table too.
template <typename Omps, typename PointT>
void segmentAndRefineAfresh(Omps& omps, OmpsOutputs<PointT>& outputs) {
  outputs.regions.clear();
  outputs.coefficients.clear();
  outputs.inliers.clear();
  outputs.labels->clear();
  outputs.label_indices.clear();
  outputs.boundaries.clear();
  omps.segmentAndRefine(outputs.regions, outputs.coefficients, outputs.inliers, outputs.labels, outputs.label_indices,
                        outputs.boundaries);
}

/// OMPS as its callers run it: `normal_estimation`'s normals of `cloud`, then
/// segmentAndRefineAfresh on them into `outputs`. Returns the normals' time [ms] (steady
/// clock), which the callers report apart. The caller checks normalWindowFits first.
template <typename NormalEstimation, typename Omps, typename PointT>
double normalsThenPlanes(NormalEstimation& normal_estimation, Omps& omps,
                         const typename pcl::PointCloud<PointT>::ConstPtr& cloud, OmpsOutputs<PointT>& outputs) {
  const auto start = std::chrono::steady_clock::now();
  auto normals = std::make_shared<pcl::PointCloud<pcl::Normal>>();
  normal_estimation.setInputCloud(cloud);
  normal_estimation.compute(*normals);
  const double normals_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  omps.setInputNormals(normals);
  omps.setInputCloud(cloud);
  segmentAndRefineAfresh(omps, outputs);
  return normals_ms;
}

}  // namespace floodplane::baselines
