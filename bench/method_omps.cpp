// PCL OrganizedMultiPlaneSegmentation with IntegralImageNormalEstimation, the settings of the
// paper's Sec. IV (and pcd_compare): average 3-D gradient, smoothing 6, depth change 0.02,
// angular threshold 0.09 rad, distance threshold 0.02 m, min inliers 50. Normal estimation is
// part of the timed call, since OMPS cannot run without it.
#include <benchmark/benchmark.h>

#include <pcl/features/integral_image_normal.h>
#include <pcl/segmentation/organized_multi_plane_segmentation.h>

#include "bench_frames.h"
#include "methods.h"

namespace floodplane::bench {

namespace {

void runOmps(benchmark::State& state, const Frame& frame) {
  pcl::IntegralImageNormalEstimation<pcl::PointXYZ, pcl::Normal> normals_estimation;
  normals_estimation.setNormalEstimationMethod(normals_estimation.AVERAGE_3D_GRADIENT);
  normals_estimation.setNormalSmoothingSize(6.0f);
  normals_estimation.setMaxDepthChangeFactor(0.02f);
  pcl::OrganizedMultiPlaneSegmentation<pcl::PointXYZ, pcl::Normal, pcl::Label> omps;
  omps.setAngularThreshold(0.09);
  omps.setDistanceThreshold(0.02);
  omps.setMinInliers(50);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  std::vector<pcl::PlanarRegion<pcl::PointXYZ>, Eigen::aligned_allocator<pcl::PlanarRegion<pcl::PointXYZ>>> regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers, label_indices, boundaries;
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  for (auto _ : state) {
    normals_estimation.setInputCloud(frame.cloud);
    normals_estimation.compute(*normals);
    omps.setInputCloud(frame.cloud);
    omps.setInputNormals(normals);
    // PCL 1.13's OrganizedConnectedComponentSegmentation resizes the label cloud with an
    // "invalid" fill that only reaches new elements, so labels left from the previous call
    // at NaN pixels index past its run table and crash it: start from an empty cloud.
    labels->clear();
    // segment() appends to the coefficient and inlier vectors, and refine() indexes its
    // per-label tables with the stale entries: every output starts empty.
    regions.clear();
    coefficients.clear();
    inliers.clear();
    label_indices.clear();
    boundaries.clear();
    omps.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
    benchmark::DoNotOptimize(regions.data());
  }
  state.counters["planes"] = static_cast<double>(regions.size());
}

void add(const std::string& name, FrameSource frame) {
  benchmark::RegisterBenchmark(name.c_str(), [frame](benchmark::State& state) { runOmps(state, frame()); })
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

std::string ompsConfiguration() {
  return "PCL OMPS: IntegralImageNormalEstimation (AVERAGE_3D_GRADIENT, smoothing 6, max depth change 0.02) + "
         "OrganizedMultiPlaneSegmentation (angular 0.09 rad, distance 0.02 m, min inliers 50), segmentAndRefine";
}

void registerOmps() {
  for (const Frame& frame : realFrames()) add("omps/real:" + frame.name, real(frame));
  for (const std::string& scene : sceneNames()) add("omps/scene:" + scene, rendered(scene, 640, 480));
}

}  // namespace floodplane::bench
