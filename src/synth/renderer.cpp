#include "synth/renderer.h"

#include <cmath>
#include <limits>
#include <string>

#include "ray_caster.h"

namespace floodplane::synth {
namespace {

void checkIntrinsics(const Scene& scene) {
  const CameraIntrinsics& intrinsics = scene.intrinsics;
  // 2^15 pixels a side is far beyond any depth camera and keeps width * height well in range.
  constexpr int kMaxSide = 1 << 15;
  if (intrinsics.width < 1 || intrinsics.height < 1 || intrinsics.width > kMaxSide || intrinsics.height > kMaxSide) {
    throw SceneError(scene.source + ": camera: image size " + std::to_string(intrinsics.width) + "x" +
                     std::to_string(intrinsics.height) + " is out of range");
  }
  if (!(intrinsics.fx > 0.0) || !(intrinsics.fy > 0.0) || !std::isfinite(intrinsics.fx) ||
      !std::isfinite(intrinsics.fy) || !std::isfinite(intrinsics.cx) || !std::isfinite(intrinsics.cy)) {
    throw SceneError(scene.source + ": camera: fx and fy must be positive, and cx, cy finite numbers");
  }
}

}  // namespace

RenderedFrame renderScene(const Scene& scene, const RenderSettings& settings) {
  checkIntrinsics(scene);
  const RayCaster caster(scene);
  const CameraIntrinsics& intrinsics = scene.intrinsics;

  RenderedFrame frame;
  frame.scene_name = scene.name;
  frame.scene_description = scene.description;
  frame.sensor = settings.sensor;
  frame.seed = settings.seed;
  frame.intrinsics = intrinsics;
  frame.planes = caster.planes();
  const auto pixel_count = static_cast<std::size_t>(intrinsics.width) * static_cast<std::size_t>(intrinsics.height);
  const Eigen::Vector3f no_point = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  frame.points.assign(pixel_count, no_point);
  frame.labels.assign(pixel_count, 0);

  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const std::size_t index = static_cast<std::size_t>(v) * intrinsics.width + u;
      const Eigen::Vector3d direction = intrinsics.rayThroughPixel(u, v);
      const SurfaceHit hit = caster.cast(direction);
      if (!std::isfinite(hit.t)) {
        continue;
      }
      // direction.z() == 1, so the hit's depth is t.
      double depth = hit.t;
      if (settings.sensor == SensorModel::kinect) {
        PixelRandom random(settings.seed, index);
        const auto measured = measureKinectDepth(hit.t, settings.kinect, random);
        if (!measured) {
          continue;
        }
        depth = *measured;
      }
      frame.points[index] = (depth * direction).cast<float>();
      frame.labels[index] = hit.plane_id;
      if (hit.plane_id > 0) {
        ++frame.planes[hit.plane_id - 1].pixel_count;
      }
    }
  }
  return frame;
}

}  // namespace floodplane::synth
