// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Open3D's plane RANSAC (geometry::PointCloud::SegmentPlane), run sequentially as PCL's is:
// the best plane, its inliers taken away, again, until a plane has too few inliers. The only
// file that includes Open3D's headers.

#include <omp.h>
#include <open3d/geometry/PointCloud.h>
#include <open3d/utility/Logging.h>
#include <open3d/utility/Random.h>

#include <sstream>

#include "method.h"

namespace pcd_compare {

namespace {

constexpr int kRansacN = 3;  // points per hypothesis: a plane through three points
constexpr int kIterations = 1000;
constexpr int kSeed = 12345;

// Open3D 0.16 runs SegmentPlane's hypotheses in an OpenMP loop that stops early once enough
// have been tried, so with several threads which hypotheses run depends on the scheduling.
// One thread (as every method here runs) makes the result a function of the seed alone.
class SingleOpenMpThread {
 public:
  SingleOpenMpThread() : previous_(omp_get_max_threads()) { omp_set_num_threads(1); }
  ~SingleOpenMpThread() { omp_set_num_threads(previous_); }
  SingleOpenMpThread(const SingleOpenMpThread&) = delete;
  SingleOpenMpThread& operator=(const SingleOpenMpThread&) = delete;

 private:
  int previous_;
};

class Open3dRansacMethod : public Method {
 public:
  Open3dRansacMethod(const ParameterValues& values, std::string name)
      : Method(std::move(name), true),
        distance_threshold_(values.at("distance_threshold")),
        min_inliers_(static_cast<std::size_t>(values.at("min_inliers"))) {
    open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Warning);
  }

  std::string parameters() const override {
    std::ostringstream text;
    text << "open3d::geometry::PointCloud::SegmentPlane (Open3D 0.16), distance threshold " << distance_threshold_
         << " m, ransac_n " << kRansacN << ", " << kIterations
         << " iterations, probability 0.99999999 (Open3D's default: it may stop early); sequential: "
            "the best plane, its inliers removed, again on the rest until a plane has < "
         << min_inliers_ << " inliers; on the finite points only; one OpenMP thread; utility::random::Seed(" << kSeed
         << ") before every cloud, deterministic";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    const SingleOpenMpThread one_thread;
    open3d::utility::random::Seed(kSeed);
    MethodRun result;
    result.labels = extractPlanesInTurn(*cloud, min_inliers_, kRansacN, [&](const pcl::Indices& remaining) {
      open3d::geometry::PointCloud points;
      points.points_.reserve(remaining.size());
      for (const pcl::index_t i : remaining) points.points_.emplace_back((*cloud)[i].x, (*cloud)[i].y, (*cloud)[i].z);
      const auto [plane, inliers] = points.SegmentPlane(distance_threshold_, kRansacN, kIterations);
      (void)plane;
      pcl::Indices pixels(inliers.size());
      for (std::size_t k = 0; k < inliers.size(); ++k) pixels[k] = remaining[inliers[k]];
      return pixels;
    });
    result.total_ms = millisecondsSince(start);
    return result;
  }

 private:
  double distance_threshold_;
  std::size_t min_inliers_;
};

}  // namespace

std::unique_ptr<Method> makeOpen3dRansacMethod(const ParameterValues& values, const std::string& name) {
  return std::make_unique<Open3dRansacMethod>(values, name);
}

}  // namespace pcd_compare
