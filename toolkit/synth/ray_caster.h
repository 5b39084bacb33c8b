// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene turned into camera-frame surfaces, with its ground-truth planes, ready to cast rays.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "surfaces.h"
#include "synth/rendered_frame.h"
#include "synth/scene.h"

namespace floodplane::synth {

class RayCaster {
 public:
  /// Checks the scene's geometry and throws SceneError naming the scene's source and the
  /// primitive at fault: sizes that are not positive, a rectangle whose edges are not
  /// perpendicular, a polygon that is degenerate or not planar, a camera inside a solid.
  explicit RayCaster(const Scene& scene);

  /// The same scene seen from another viewpoint (a structured-light projector): surfaces and
  /// planes in the frame `world_from_viewpoint` maps to world coordinates; `viewpoint` names it
  /// in messages ("the projector is inside this box").
  RayCaster(const Scene& scene, const Eigen::Isometry3d& world_from_viewpoint, const std::string& viewpoint);

  /// The nearest surface along the ray from the viewpoint in `direction`: at t * direction.
  /// Through a pixel (direction z = 1) t is the depth.
  SurfaceHit cast(const Eigen::Vector3d& direction) const;

  /// Every ground-truth plane (pixel counts still 0), ordered by id from 1.
  const std::vector<GroundTruthPlane>& planes() const { return planes_; }

 private:
  std::vector<PolygonSurface> polygons_;
  std::vector<BoxSurface> boxes_;
  std::vector<SphereSurface> spheres_;
  std::vector<CylinderSurface> cylinders_;
  std::vector<PrismSurface> prisms_;
  std::vector<GroundTruthPlane> planes_;
};

}  // namespace floodplane::synth
