#pragma once
// A scene turned into camera-frame surfaces, with its ground-truth planes, ready to cast rays.

#include <Eigen/Core>
#include <vector>

#include "synth/rendered_frame.h"
#include "synth/scene.h"
#include "surfaces.h"

namespace floodplane::synth {

class RayCaster {
 public:
  /// Checks the scene's geometry and throws SceneError naming the scene's source and the
  /// primitive at fault: sizes that are not positive, a rectangle whose edges are not
  /// perpendicular, a polygon that is degenerate or not planar, a camera inside a solid.
  explicit RayCaster(const Scene& scene);

  /// The nearest surface along the ray from the camera centre in `direction` (z = 1).
  SurfaceHit cast(const Eigen::Vector3d& direction) const;

  /// Every ground-truth plane (pixel counts still 0), ordered by id from 1.
  const std::vector<GroundTruthPlane>& planes() const { return planes_; }

 private:
  std::vector<PolygonSurface> polygons_;
  std::vector<BoxSurface> boxes_;
  std::vector<SphereSurface> spheres_;
  std::vector<CylinderSurface> cylinders_;
  std::vector<GroundTruthPlane> planes_;
};

}  // namespace floodplane::synth
