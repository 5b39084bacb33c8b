// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/camera_placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synth/renderer.h"
#include "synth/surface_distance.h"

namespace floodplane::synth {

ViewSummary summarizeView(const Scene& scene, const ViewRequirements& requirements) {
  ViewSummary summary;
  const Eigen::Vector3d position = scene.world_from_camera.translation();
  summary.clearance = nearestSurfaceDistance(scene, position);
  summary.inside_solid = insideAnySolid(scene, position);
  if (summary.inside_solid) {
    return summary;
  }
  Scene preview = scene;
  preview.intrinsics = scene.intrinsics.scaledTo(requirements.preview_width, requirements.preview_height);
  const RenderedFrame frame = renderScene(preview, RenderSettings{});
  std::size_t hits = 0;
  for (const Eigen::Vector3f& point : frame.points) {
    hits += std::isnan(point.z()) ? 0 : 1;
  }
  const auto pixels = static_cast<double>(frame.points.size());
  summary.coverage = static_cast<double>(hits) / pixels;
  for (const GroundTruthPlane& plane : frame.planes) {
    const double fraction = static_cast<double>(plane.pixel_count) / pixels;
    summary.planes += fraction >= requirements.min_plane_fraction ? 1 : 0;
    summary.largest_plane = std::max(summary.largest_plane, fraction);
  }
  const auto centre =
      static_cast<std::size_t>(requirements.preview_height / 2) * static_cast<std::size_t>(requirements.preview_width) +
      static_cast<std::size_t>(requirements.preview_width / 2);
  const float depth = frame.points[centre].z();
  summary.centre_depth = std::isnan(depth) ? std::numeric_limits<double>::infinity() : static_cast<double>(depth);
  return summary;
}

bool meetsRequirements(const ViewSummary& summary, const ViewRequirements& requirements) {
  return !summary.inside_solid && summary.clearance >= requirements.min_clearance &&
         summary.clearance <= requirements.max_clearance && summary.coverage >= requirements.min_coverage &&
         summary.planes >= requirements.min_planes && summary.largest_plane <= requirements.max_plane_fraction &&
         summary.centre_depth >= requirements.min_centre_depth && summary.centre_depth <= requirements.max_centre_depth;
}

}  // namespace floodplane::synth
