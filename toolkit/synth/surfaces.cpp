// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "surfaces.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace floodplane::synth {
namespace {

// Rays closer to parallel with a plane than this (|n . direction|, direction z = 1) miss it:
// such a plane is seen edge-on and covers no pixel area.
constexpr double kParallelEpsilon = 1e-12;

}  // namespace

PolygonSurface::PolygonSurface(const Eigen::Vector3d& normal, double d, const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& axis_u, const Eigen::Vector3d& axis_v,
                               std::vector<Eigen::Vector2d> outline, std::vector<std::size_t> ring_ends,
                               std::uint32_t plane_id, std::uint32_t primitive)
    : normal_(normal),
      d_(d),
      origin_(origin),
      axis_u_(axis_u),
      axis_v_(axis_v),
      outline_(std::move(outline)),
      ring_ends_(std::move(ring_ends)),
      outline_min_(outline_.front()),
      outline_max_(outline_.front()),
      plane_id_(plane_id),
      primitive_(primitive) {
  for (const auto& vertex : outline_) {
    outline_min_ = outline_min_.cwiseMin(vertex);
    outline_max_ = outline_max_.cwiseMax(vertex);
  }
}

void PolygonSurface::intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const {
  const double denominator = normal_.dot(direction);
  if (std::abs(denominator) < kParallelEpsilon) {
    return;
  }
  const double t = -d_ / denominator;
  if (t <= 0.0 || t >= nearest.t) {
    return;
  }
  const Eigen::Vector3d offset = t * direction - origin_;
  if (contains({offset.dot(axis_u_), offset.dot(axis_v_)})) {
    nearest = {t, plane_id_, normal_, primitive_};
  }
}

// Even-odd rule: count the edges crossed by a ray from `point` towards +u. Works for convex
// and non-convex simple polygons (a staircase's side, an L-shaped panel), and counting the
// edges of the holes too takes the holes out.
bool PolygonSurface::contains(const Eigen::Vector2d& point) const {
  if ((point.array() < outline_min_.array()).any() || (point.array() > outline_max_.array()).any()) {
    return false;
  }
  bool inside = false;
  std::size_t ring_begin = 0;
  for (const std::size_t ring_end : ring_ends_) {
    for (std::size_t i = ring_begin, j = ring_end - 1; i < ring_end; j = i++) {
      const Eigen::Vector2d& a = outline_[i];
      const Eigen::Vector2d& b = outline_[j];
      if ((a.y() > point.y()) != (b.y() > point.y())) {
        const double crossing_u = a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
        if (point.x() < crossing_u) {
          inside = !inside;
        }
      }
    }
    ring_begin = ring_end;
  }
  return inside;
}

BoxSurface::BoxSurface(const Eigen::Isometry3d& camera_from_box, const Eigen::Vector3d& half_size,
                       const std::array<std::uint32_t, 6>& face_ids, std::uint32_t primitive)
    : box_from_camera_rotation_(camera_from_box.linear().transpose()),
      camera_in_box_(camera_from_box.inverse().translation()),
      half_size_(half_size),
      face_ids_(face_ids),
      primitive_(primitive) {}

// The slab method: the ray is inside the box where it is inside all three slabs; it enters
// through the face of the slab it enters last.
void BoxSurface::intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const {
  const Eigen::Vector3d local_direction = box_from_camera_rotation_ * direction;
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  std::size_t entry_face = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double origin = camera_in_box_[axis];
    const double step = local_direction[axis];
    const double half = half_size_[axis];
    if (std::abs(step) < kParallelEpsilon) {
      if (std::abs(origin) > half) {
        return;  // parallel to this slab and outside it
      }
      continue;
    }
    const double t_minus = (-half - origin) / step;
    const double t_plus = (half - origin) / step;
    // Moving towards +axis the ray enters through the -axis face (index 2 * axis + 1).
    const double t_near = step > 0.0 ? t_minus : t_plus;
    const double t_far = step > 0.0 ? t_plus : t_minus;
    if (t_near > t_enter) {
      t_enter = t_near;
      entry_face = 2 * static_cast<std::size_t>(axis) + (step > 0.0 ? 1 : 0);
    }
    t_exit = std::min(t_exit, t_far);
  }
  if (t_enter > t_exit || t_enter <= 0.0 || t_enter >= nearest.t) {
    return;
  }
  // Row `axis` of box_from_camera is the box's axis in camera coordinates.
  const auto axis = static_cast<Eigen::Index>(entry_face / 2);
  nearest = {t_enter, face_ids_[entry_face], box_from_camera_rotation_.row(axis).transpose(), primitive_};
}

SphereSurface::SphereSurface(const Eigen::Vector3d& center, double radius, std::uint32_t primitive)
    : center_(center), radius_(radius), primitive_(primitive) {}

void SphereSurface::intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const {
  // |t d - c|^2 = r^2  <=>  (d.d) t^2 - 2 (d.c) t + (c.c - r^2) = 0; the smaller root is the
  // entry point because the camera is outside the sphere.
  const double a = direction.squaredNorm();
  const double b = direction.dot(center_);
  const double c = center_.squaredNorm() - radius_ * radius_;
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) {
    return;
  }
  const double t = (b - std::sqrt(discriminant)) / a;
  if (t > 0.0 && t < nearest.t) {
    nearest = {t, 0, (t * direction - center_) / radius_, primitive_};
  }
}

CylinderSurface::CylinderSurface(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double radius, double height,
                                 std::uint32_t top_id, std::uint32_t bottom_id, std::uint32_t primitive)
    : base_(base),
      axis_(axis),
      radius_(radius),
      height_(height),
      top_id_(top_id),
      bottom_id_(bottom_id),
      primitive_(primitive) {}

void CylinderSurface::intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const {
  // The side: the ray's components across the axis must have length r. With w the ray origin
  // relative to the base, |w_perp + t d_perp|^2 = r^2; the smaller root is the entry.
  const Eigen::Vector3d w = -base_;
  const Eigen::Vector3d w_perp = w - w.dot(axis_) * axis_;
  const Eigen::Vector3d d_perp = direction - direction.dot(axis_) * axis_;
  const double a = d_perp.squaredNorm();
  if (a > kParallelEpsilon) {
    const double b = w_perp.dot(d_perp);
    const double c = w_perp.squaredNorm() - radius_ * radius_;
    const double discriminant = b * b - a * c;
    if (discriminant >= 0.0) {
      const double t = (-b - std::sqrt(discriminant)) / a;
      const Eigen::Vector3d from_base = w + t * direction;
      const double along_axis = from_base.dot(axis_);
      if (t > 0.0 && t < nearest.t && along_axis >= 0.0 && along_axis <= height_) {
        nearest = {t, 0, (from_base - along_axis * axis_) / radius_, primitive_};
      }
    }
  }
  // A cap hit nearer than the side hit is where the ray enters through that cap.
  intersectCap(direction, base_ + height_ * axis_, top_id_, nearest);
  intersectCap(direction, base_, bottom_id_, nearest);
}

void CylinderSurface::intersectCap(const Eigen::Vector3d& direction, const Eigen::Vector3d& cap_center,
                                   std::uint32_t cap_id, SurfaceHit& nearest) const {
  const double denominator = axis_.dot(direction);
  if (std::abs(denominator) < kParallelEpsilon) {
    return;
  }
  const double t = axis_.dot(cap_center) / denominator;
  if (t <= 0.0 || t >= nearest.t) {
    return;
  }
  if ((t * direction - cap_center).squaredNorm() <= radius_ * radius_) {
    nearest = {t, cap_id, axis_, primitive_};
  }
}

PrismSurface::PrismSurface(std::vector<PolygonSurface> faces, const Eigen::Vector3d& bounding_center,
                           double bounding_radius)
    : faces_(std::move(faces)),
      bounding_center_(bounding_center),
      bounding_radius_squared_(bounding_radius * bounding_radius) {}

void PrismSurface::intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const {
  // The ray misses the bounding sphere when it passes its centre farther than the radius:
  // |c|^2 - (c.d)^2 / |d|^2 > r^2. The camera is outside the prism, so the nearest face hit is
  // where the ray enters it.
  const double along = bounding_center_.dot(direction);
  if (bounding_center_.squaredNorm() - along * along / direction.squaredNorm() > bounding_radius_squared_) {
    return;
  }
  for (const PolygonSurface& face : faces_) {
    face.intersect(direction, nearest);
  }
}

}  // namespace floodplane::synth
