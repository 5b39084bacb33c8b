// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// PCL's LCCP (Stein et al., "Object partitioning using local convexity", CVPR 2014): supervoxels
// (pcl::SupervoxelClustering) joined across convex edges by pcl::LCCPSegmentation, every
// setting PCL's examples/segmentation/example_lccp_segmentation's default, or with that
// example's switches -ec -sc (extended convexity, k = 1, and the sanity criterion). LCCP
// partitions every surface, the table too, and knows no support: its largest segment is taken
// as the table and left out, and segments of at most 1000 points are left out as the organized
// pipeline's clusters are (pcl_organized_objects_method.cpp); the rest are the objects. The
// time is that of the PCL calls; leaving segments out is part of turning them into labels.

#include <pcl/segmentation/lccp_segmentation.h>
#include <pcl/segmentation/supervoxel_clustering.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <unordered_map>

#include "method.h"

namespace pcd_compare {

namespace {

// example_lccp_segmentation's defaults (PCL 1.13).
constexpr float kVoxelResolution = 0.0075f;  // [m]
constexpr float kSeedResolution = 0.03f;     // [m]
constexpr float kColorImportance = 0.0f;
constexpr float kSpatialImportance = 1.0f;
constexpr float kNormalImportance = 4.0f;
constexpr float kConcavityToleranceDegrees = 10.0f;
constexpr float kSmoothnessThreshold = 0.1f;
constexpr std::uint32_t kMinSegmentSize = 0;  // [supervoxels]: no merging of small segments
constexpr std::size_t kMinObjectPoints = 1000;

class LccpObjectsMethod : public Method {
 public:
  // extended: the example's -ec -sc.
  explicit LccpObjectsMethod(bool extended)
      : Method(extended ? "lccp_ec_sc" : "lccp", false), k_factor_(extended ? 1 : 0), sanity_criterion_(extended) {}

  std::string parameters() const override {
    std::ostringstream text;
    text << (sanity_criterion_ ? "PCL's example_lccp_segmentation -ec -sc, otherwise its defaults"
                               : "PCL's example_lccp_segmentation's defaults")
         << ": pcl::SupervoxelClustering<PointXYZ> voxel resolution " << kVoxelResolution << " m, seed resolution "
         << kSeedResolution << " m, colour/spatial/normal importance " << kColorImportance << "/" << kSpatialImportance
         << "/" << kNormalImportance
         << ", no single-camera transform, no refinement; pcl::LCCPSegmentation concavity tolerance "
         << kConcavityToleranceDegrees << " deg, smoothness check " << kSmoothnessThreshold << ", k factor "
         << k_factor_ << ", sanity criterion " << (sanity_criterion_ ? "on" : "off") << ", min segment size "
         << kMinSegmentSize << "; the largest segment (the table) left out, and segments of at most "
         << kMinObjectPoints << " points";
    return text.str();
  }

  MethodRun run(const Cloud::ConstPtr& cloud) override {
    const auto start = Clock::now();
    MethodRun result;
    result.labels.assign(cloud->size(), 0);
    // PCL's supervoxels need points: a frame without a finite one has no object.
    if (std::none_of(cloud->begin(), cloud->end(), [](const pcl::PointXYZ& p) { return pcl::isFinite(p); })) {
      result.total_ms = millisecondsSince(start);
      result.parts_ms.emplace_back("supervoxels", result.total_ms);
      return result;
    }
    pcl::SupervoxelClustering<pcl::PointXYZ> supervoxels(kVoxelResolution, kSeedResolution);
    supervoxels.setUseSingleCameraTransform(false);
    supervoxels.setInputCloud(cloud);
    supervoxels.setColorImportance(kColorImportance);
    supervoxels.setSpatialImportance(kSpatialImportance);
    supervoxels.setNormalImportance(kNormalImportance);
    std::map<std::uint32_t, pcl::Supervoxel<pcl::PointXYZ>::Ptr> clusters;
    supervoxels.extract(clusters);
    if (clusters.empty()) {
      result.total_ms = millisecondsSince(start);
      result.parts_ms.emplace_back("supervoxels", result.total_ms);
      return result;
    }
    std::multimap<std::uint32_t, std::uint32_t> adjacency;
    supervoxels.getSupervoxelAdjacency(adjacency);
    const double supervoxels_ms = millisecondsSince(start);
    pcl::LCCPSegmentation<pcl::PointXYZ> lccp;
    lccp.setConcavityToleranceThreshold(kConcavityToleranceDegrees);
    lccp.setSanityCheck(sanity_criterion_);
    lccp.setSmoothnessCheck(true, kVoxelResolution, kSeedResolution, kSmoothnessThreshold);
    lccp.setKFactor(k_factor_);
    lccp.setInputSupervoxels(clusters, adjacency);
    lccp.setMinSegmentSize(kMinSegmentSize);
    lccp.segment();
    const pcl::PointCloud<pcl::PointXYZL>::Ptr segments = supervoxels.getLabeledCloud();
    lccp.relabelCloud(*segments);
    result.total_ms = millisecondsSince(start);
    result.parts_ms.emplace_back("supervoxels", supervoxels_ms);

    // LCCP's segment labels are supervoxel labels; 0 is no point. The objects: every segment
    // but the largest, of more than kMinObjectPoints points, numbered 1.. in grid order.
    std::unordered_map<std::uint32_t, std::size_t> size;
    for (const pcl::PointXYZL& point : *segments) {
      if (point.label != 0) ++size[point.label];
    }
    std::uint32_t table = 0;
    std::size_t table_points = 0;
    for (const auto& [label, points] : size) {
      if (points > table_points || (points == table_points && label < table)) {
        table = label;
        table_points = points;
      }
    }
    std::unordered_map<std::uint32_t, std::uint32_t> object_of;
    for (std::size_t i = 0; i < segments->size(); ++i) {
      const std::uint32_t label = (*segments)[i].label;
      if (label == 0 || label == table || size[label] <= kMinObjectPoints) continue;
      const auto object = object_of.emplace(label, static_cast<std::uint32_t>(object_of.size() + 1)).first;
      result.labels[i] = object->second;
    }
    return result;
  }

 private:
  std::uint32_t k_factor_;  // 1: extended convexity
  bool sanity_criterion_;
};

}  // namespace

std::unique_ptr<Method> makeLccpObjectsMethod() { return std::make_unique<LccpObjectsMethod>(false); }

std::unique_ptr<Method> makeLccpExtendedObjectsMethod() { return std::make_unique<LccpObjectsMethod>(true); }

}  // namespace pcd_compare
