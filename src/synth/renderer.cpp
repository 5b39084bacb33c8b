#include "synth/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "projector_view.h"
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

// What the sensor reports for the exact hit `hit` on the ray through pixel `index` in
// `direction` (z = 1): a depth, or nothing.
std::optional<double> measuredDepth(const Scene& scene, const RenderSettings& settings, const ProjectorView* projector,
                                    const Eigen::Vector3d& direction, const SurfaceHit& hit, std::size_t index) {
  switch (settings.sensor) {
    case SensorModel::none:
      return hit.t;  // direction.z() == 1, so the hit's depth is t
    case SensorModel::kinect: {
      PixelRandom random(settings.seed, index);
      return measureKinectDepth(hit.t, settings.kinect, random);
    }
    case SensorModel::scanner: {
      const Eigen::Vector3d point = hit.t * direction;
      const Eigen::Vector3d normal = hit.normal.dot(direction) > 0.0 ? Eigen::Vector3d(-hit.normal) : hit.normal;
      const double camera_cosine = -normal.dot(direction) / direction.norm();
      const Illumination light = projector->illuminate(point, normal);
      PixelRandom random(settings.seed, index);
      const double signal = scannerReturnSignal(scene.primitives[hit.primitive].albedo, camera_cosine, light.cosine);
      const auto measured = measureScannerDepth(hit.t, signal, settings.scanner, random);
      return light.lit ? measured : std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

RenderedFrame renderScene(const Scene& scene, const RenderSettings& settings) {
  checkIntrinsics(scene);
  const RayCaster caster(scene);
  std::optional<ProjectorView> projector;
  if (settings.sensor == SensorModel::scanner) {
    projector.emplace(scene, settings.scanner);
  }
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
      const std::optional<double> depth =
          measuredDepth(scene, settings, projector ? &*projector : nullptr, direction, hit, index);
      if (!depth) {
        continue;
      }
      frame.points[index] = (*depth * direction).cast<float>();
      frame.labels[index] = hit.plane_id;
      if (hit.plane_id > 0) {
        ++frame.planes[hit.plane_id - 1].pixel_count;
      }
    }
  }
  return frame;
}

}  // namespace floodplane::synth
