// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "projector_view.h"

#include <cmath>

namespace floodplane::synth {
namespace {

// A surface hit from the projector nearer than (1 - kOccluderMargin) of the way to the point
// shadows it. The point's own surface comes back at t = 1 up to round-off (relative 1e-15,
// more at grazing incidence); 1e-7 (0.1 micrometres at 1 m) is far above that and far below
// any gap between two surfaces of a scene.
constexpr double kOccluderMargin = 1e-7;

}  // namespace

ProjectorView::ProjectorView(const Scene& scene, const ScannerParams& params)
    : position_(params.baseline, 0.0, 0.0),
      // Turning by atan(b / c) about y brings the projector's axis onto (0, 0, c) - position.
      projector_from_camera_(
          Eigen::AngleAxisd(std::atan2(params.baseline, params.convergence_distance), Eigen::Vector3d::UnitY())
              .toRotationMatrix()),
      half_width_(params.projector_half_width),
      half_height_(params.projector_half_height),
      // The caster keeps the camera's axes: only the projector's position matters for shadows.
      caster_(scene, scene.world_from_camera * Eigen::Translation3d(params.baseline, 0.0, 0.0), "projector") {}

bool ProjectorView::inField(const Eigen::Vector3d& to_point) const {
  const Eigen::Vector3d aimed = projector_from_camera_ * to_point;
  return aimed.z() > 0.0 && std::abs(aimed.x()) <= half_width_ * aimed.z() &&
         std::abs(aimed.y()) <= half_height_ * aimed.z();
}

Illumination ProjectorView::illuminate(const Eigen::Vector3d& point, const Eigen::Vector3d& normal) const {
  // In the caster's frame (the camera's axes moved to the projector) the ray from the
  // projector to the point has the direction point - position and reaches it at t = 1.
  const Eigen::Vector3d to_point = point - position_;
  const double cosine = -normal.dot(to_point) / to_point.norm();
  const bool in_field = inField(to_point);
  if (cosine <= 0.0 || !in_field) {
    return {false, cosine, in_field};  // the projector sees the surface's back, or does not reach it
  }
  const SurfaceHit first = caster_.cast(to_point);
  return {first.t >= 1.0 - kOccluderMargin, cosine, true};
}

}  // namespace floodplane::synth
