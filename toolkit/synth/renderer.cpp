// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "projector_view.h"
#include "ray_caster.h"
#include "synth/plane_fold.h"
#include "synth/scanner_speckle.h"

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
// `direction` (z = 1): a depth, or nothing. The sensor measures `sensed_depth`, the hit's depth
// moved along the ray by the calibration's errors (warp, bend; hit.t without them); the
// projector lights the surface where it is. Sets `light` for the scanner.
std::optional<double> measuredDepth(const Scene& scene, const RenderSettings& settings, const ProjectorView* projector,
                                    const Eigen::Vector3d& direction, const SurfaceHit& hit, double sensed_depth,
                                    std::size_t index, ProjectorLight& light) {
  switch (settings.sensor) {
    case SensorModel::none:
      return hit.t;  // direction.z() == 1, so the hit's depth is t
    case SensorModel::kinect: {
      PixelRandom random(settings.seed, index);
      return measureKinectDepth(sensed_depth, settings.kinect, random);
    }
    case SensorModel::scanner: {
      const Eigen::Vector3d point = hit.t * direction;
      const Eigen::Vector3d normal = hit.normal.dot(direction) > 0.0 ? Eigen::Vector3d(-hit.normal) : hit.normal;
      const double camera_cosine = -normal.dot(direction) / direction.norm();
      const Illumination illumination = projector->illuminate(point, normal);
      light = !illumination.in_field ? ProjectorLight::outside_field
              : illumination.lit     ? ProjectorLight::lit
                                     : ProjectorLight::shadowed;
      PixelRandom random(settings.seed, index);
      const double signal =
          scannerReturnSignal(scene.primitives[hit.primitive].albedo, camera_cosine, illumination.cosine);
      const auto measured = measureScannerDepth(sensed_depth, signal, settings.scanner, random);
      return illumination.lit ? measured : std::nullopt;
    }
  }
  return std::nullopt;
}

// The quirks `settings` turn on for its sensor model, as the ground truth records them.
SensorQuirks quirksInEffect(const RenderSettings& settings) {
  SensorQuirks quirks;
  if (settings.sensor == SensorModel::none) return quirks;
  if (settings.warp.amplitude != 0.0) {  // a negative or NaN amplitude goes on to DepthWarp, which rejects it
    quirks.warp_amplitude = settings.warp.amplitude;
    quirks.warp_seed = settings.warp.seed;
  }
  if (settings.sensor == SensorModel::kinect && settings.kinect.bend_curvature != 0.0) {
    quirks.bend_curvature = settings.kinect.bend_curvature;
    quirks.bend_reference_depth = settings.kinect.bend_reference_depth;
  }
  if (settings.sensor == SensorModel::scanner) {
    if (settings.scanner.range_bits > 0) {
      quirks.range_bits = settings.scanner.range_bits;
      quirks.range_code_near = settings.scanner.range_code_near;
      quirks.range_code_far = settings.scanner.range_code_far;
    }
    quirks.speckle = settings.scanner.speckle;
  }
  return quirks;
}

// Faces of one plane (normals and offsets equal up to round-off).
bool coplanar(const GroundTruthPlane& a, const GroundTruthPlane& b) {
  constexpr double kEpsilon = 1e-6;
  return a.normal.dot(b.normal) > 1.0 - kEpsilon && std::abs(a.d - b.d) < kEpsilon * std::max(1.0, std::abs(a.d));
}

// One continuous flat surface is one ground-truth plane: faces that lie in one plane and meet
// in the image (4-neighbouring pixels of the exact hits `surface`, measured or not) carry the
// label of the face with the smallest id. Primitives flush with each other (the fronts of a
// shelf's boards and side panels, two stacked boxes of one size) form one surface, which no
// segmentation could cut where the primitives happen to meet.
void mergeTouchingCoplanarFaces(RenderedFrame& frame, const std::vector<std::uint32_t>& surface) {
  std::vector<std::uint32_t> root(frame.planes.size() + 1);
  for (std::uint32_t id = 0; id < root.size(); ++id) root[id] = id;
  const auto find = [&](std::uint32_t id) {
    while (root[id] != id) id = root[id] = root[root[id]];
    return id;
  };
  const auto unite = [&](std::uint32_t a, std::uint32_t b) {
    if (a == 0 || b == 0 || a == b || !coplanar(frame.planes[a - 1], frame.planes[b - 1])) return;
    a = find(a);
    b = find(b);
    if (a != b) root[std::max(a, b)] = std::min(a, b);
  };
  const auto width = static_cast<std::size_t>(frame.intrinsics.width);
  for (std::size_t i = 0; i < surface.size(); ++i) {
    if (i % width + 1 < width) unite(surface[i], surface[i + 1]);
    if (i + width < surface.size()) unite(surface[i], surface[i + width]);
  }
  foldPlanes(frame, find);
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
  frame.quirks = quirksInEffect(settings);
  frame.intrinsics = intrinsics;
  frame.world_from_camera = Eigen::Quaterniond(scene.world_from_camera.linear()).normalized();
  frame.planes = caster.planes();
  const auto pixel_count = static_cast<std::size_t>(intrinsics.width) * static_cast<std::size_t>(intrinsics.height);
  const Eigen::Vector3f no_point = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  frame.points.assign(pixel_count, no_point);
  frame.labels.assign(pixel_count, 0);
  std::vector<std::uint32_t> surface(pixel_count, 0);  // the exact hit's plane, measured or not

  // The calibration's errors, when on: the depth the sensor believes it sees.
  const std::optional<DepthWarp> warp = frame.quirks.warp_amplitude != 0.0
                                            ? std::optional<DepthWarp>(std::in_place, settings.warp, intrinsics)
                                            : std::nullopt;
  const bool bend = frame.quirks.bend_curvature != 0.0;
  // The speckle needs every pixel's exact depth and light, measured or not.
  const bool speckle = frame.quirks.speckle;
  std::vector<double> exact_depth(speckle ? pixel_count : 0, std::numeric_limits<double>::infinity());
  std::vector<ProjectorLight> light(speckle ? pixel_count : 0, ProjectorLight::no_surface);

  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) {
      const std::size_t index = static_cast<std::size_t>(v) * intrinsics.width + u;
      const Eigen::Vector3d direction = intrinsics.rayThroughPixel(u, v);
      const SurfaceHit hit = caster.cast(direction);
      if (!std::isfinite(hit.t)) {
        continue;
      }
      surface[index] = hit.plane_id;
      double sensed_depth = hit.t;
      if (warp) sensed_depth += warp->at(u, v);
      if (bend) sensed_depth += kinectBendOffset(hit.t, direction.head<2>().squaredNorm(), settings.kinect);
      ProjectorLight pixel_light = ProjectorLight::no_surface;
      const std::optional<double> depth = measuredDepth(scene, settings, projector ? &*projector : nullptr, direction,
                                                        hit, sensed_depth, index, pixel_light);
      if (speckle) {
        exact_depth[index] = hit.t;
        light[index] = pixel_light;
      }
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
  if (speckle) addScannerSpeckle(exact_depth, light, settings.scanner, settings.seed, frame);
  mergeTouchingCoplanarFaces(frame, surface);
  return frame;
}

}  // namespace floodplane::synth
