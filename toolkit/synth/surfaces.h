// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Scene surfaces in the camera frame, ready for ray casting. Every ray starts at the camera
// centre (the origin) with a direction whose z is 1, so the ray parameter t is the depth z.
// Each intersect() keeps the nearer of its own hit and the hit passed in; a miss leaves
// `nearest` unchanged.

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace floodplane::synth {

struct SurfaceHit {
  double t = std::numeric_limits<double>::infinity();  ///< depth of the hit; infinity: none
  std::uint32_t plane_id = 0;                          ///< 0 for a non-planar surface
  /// The surface normal at the hit, unit length, either orientation: the scanner model needs
  /// the angles of incidence, and curved surfaces have no ground-truth plane to take it from.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  std::uint32_t primitive = 0;  ///< index of the hit primitive in the scene's list
};

/// A flat polygon (rectangles are polygons too): its plane, an orthonormal basis in the plane
/// and its outline in that basis: one ring, or the outer ring followed by its holes, every ring
/// ending where `ring_ends` says (one past its last vertex).
class PolygonSurface {
 public:
  PolygonSurface(const Eigen::Vector3d& normal, double d, const Eigen::Vector3d& origin, const Eigen::Vector3d& axis_u,
                 const Eigen::Vector3d& axis_v, std::vector<Eigen::Vector2d> outline,
                 std::vector<std::size_t> ring_ends, std::uint32_t plane_id, std::uint32_t primitive);
  void intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const;

 private:
  bool contains(const Eigen::Vector2d& point) const;

  Eigen::Vector3d normal_;
  double d_;
  Eigen::Vector3d origin_;
  Eigen::Vector3d axis_u_;
  Eigen::Vector3d axis_v_;
  std::vector<Eigen::Vector2d> outline_;
  std::vector<std::size_t> ring_ends_;
  Eigen::Vector2d outline_min_;  // bounding rectangle of the outline, for a quick reject
  Eigen::Vector2d outline_max_;
  std::uint32_t plane_id_;
  std::uint32_t primitive_;
};

/// A solid box: `camera_from_box` maps box coordinates (centred, axis-aligned) to the camera
/// frame. face_ids in the order +x, -x, +y, -y, +z, -z.
class BoxSurface {
 public:
  BoxSurface(const Eigen::Isometry3d& camera_from_box, const Eigen::Vector3d& half_size,
             const std::array<std::uint32_t, 6>& face_ids, std::uint32_t primitive);
  void intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const;

 private:
  Eigen::Matrix3d box_from_camera_rotation_;
  Eigen::Vector3d camera_in_box_;  // the ray origin in box coordinates
  Eigen::Vector3d half_size_;
  std::array<std::uint32_t, 6> face_ids_;
  std::uint32_t primitive_;
};

class SphereSurface {
 public:
  SphereSurface(const Eigen::Vector3d& center, double radius, std::uint32_t primitive);
  void intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const;

 private:
  Eigen::Vector3d center_;
  double radius_;
  std::uint32_t primitive_;
};

/// A solid capped cylinder; `axis` has unit length. The side has no plane id.
class CylinderSurface {
 public:
  CylinderSurface(const Eigen::Vector3d& base, const Eigen::Vector3d& axis, double radius, double height,
                  std::uint32_t top_id, std::uint32_t bottom_id, std::uint32_t primitive);
  void intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const;

 private:
  void intersectCap(const Eigen::Vector3d& direction, const Eigen::Vector3d& cap_center, std::uint32_t cap_id,
                    SurfaceHit& nearest) const;

  Eigen::Vector3d base_;
  Eigen::Vector3d axis_;
  double radius_;
  double height_;
  std::uint32_t top_id_;
  std::uint32_t bottom_id_;
  std::uint32_t primitive_;
};

/// A solid prism as its flat faces, behind a bounding sphere that most rays miss.
class PrismSurface {
 public:
  PrismSurface(std::vector<PolygonSurface> faces, const Eigen::Vector3d& bounding_center, double bounding_radius);
  void intersect(const Eigen::Vector3d& direction, SurfaceHit& nearest) const;

 private:
  std::vector<PolygonSurface> faces_;
  Eigen::Vector3d bounding_center_;
  double bounding_radius_squared_;
};

}  // namespace floodplane::synth
