// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "ray_caster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace floodplane::synth {
namespace {

// Polygon vertices may be this far off their common plane (metres): hand-written decimals are
// rarely exact, and the polygon is drawn on its fitted plane anyway, so its points lie exactly
// on the ground-truth plane.
constexpr double kPlanarityTolerance = 1e-4;
// |cos| of the angle between a rectangle's edges; 1e-3 is 0.06 degrees off a right angle.
constexpr double kPerpendicularTolerance = 1e-3;
// Smaller lengths (metres) count as zero.
constexpr double kLengthEpsilon = 1e-9;
constexpr double kDegreesPerRadian = 57.29577951308232;
// A prism's extrusion must leave its base's plane by more than this angle (sine, ~0.06
// degrees): flatter, the prism has no volume to speak of.
constexpr double kExtrusionSineTolerance = 1e-3;

std::string formatNumber(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value;
  return text.str();
}

// Where a point lies relative to a simple polygon in 2D, by the even-odd rule (as
// PolygonSurface::contains, without its bounding-box shortcut).
bool insidePolygon2d(const std::vector<Eigen::Vector2d>& outline, const Eigen::Vector2d& point) {
  bool inside = false;
  for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    const Eigen::Vector2d& a = outline[i];
    const Eigen::Vector2d& b = outline[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < a.x() + (point.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
      inside = !inside;
    }
  }
  return inside;
}

double cross2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// True when the closed segments ab and cd share a point (collinear overlaps included).
bool segmentsTouch(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double side_c = cross2d(b - a, c - a);
  const double side_d = cross2d(b - a, d - a);
  const double side_a = cross2d(d - c, a - c);
  const double side_b = cross2d(d - c, b - c);
  if (((side_c > 0.0 && side_d < 0.0) || (side_c < 0.0 && side_d > 0.0)) &&
      ((side_a > 0.0 && side_b < 0.0) || (side_a < 0.0 && side_b > 0.0))) {
    return true;
  }
  const auto on_segment = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    return r.x() >= std::min(p.x(), q.x()) && r.x() <= std::max(p.x(), q.x()) && r.y() >= std::min(p.y(), q.y()) &&
           r.y() <= std::max(p.y(), q.y());
  };
  return (side_c == 0.0 && on_segment(a, b, c)) || (side_d == 0.0 && on_segment(a, b, d)) ||
         (side_a == 0.0 && on_segment(c, d, a)) || (side_b == 0.0 && on_segment(c, d, b));
}

// The index of an edge that crosses or touches a non-adjacent edge of the closed polygon, or
// nothing when the polygon is simple.
std::optional<std::size_t> selfIntersectingEdge(const std::vector<Eigen::Vector2d>& outline) {
  const std::size_t n = outline.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) {
        continue;  // adjacent through the closing edge
      }
      if (segmentsTouch(outline[i], outline[(i + 1) % n], outline[j], outline[(j + 1) % n])) {
        return i;
      }
    }
  }
  return std::nullopt;
}

// The plane of a polygon's vertices: centroid, unit normal by Newell's method (the sum of edge
// cross products is the normal scaled by twice the area, robust for non-convex polygons; it
// points to where the vertices run counter-clockwise), and twice the area.
struct PolygonPlane {
  Eigen::Vector3d centroid;
  Eigen::Vector3d normal;
  double twice_area;
};

PolygonPlane polygonPlane(const std::vector<Eigen::Vector3d>& vertices) {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& vertex : vertices) {
    centroid += vertex;
  }
  centroid /= static_cast<double>(vertices.size());
  Eigen::Vector3d area_normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    area_normal += (vertices[i] - centroid).cross(vertices[(i + 1) % vertices.size()] - centroid);
  }
  const double twice_area = area_normal.norm();
  return {centroid, twice_area > 0.0 ? Eigen::Vector3d(area_normal / twice_area) : Eigen::Vector3d::Zero(), twice_area};
}

// The surfaces a scene's primitives turn into, in the order RayCaster::cast tests them.
struct SurfaceLists {
  std::vector<PolygonSurface>& polygons;
  std::vector<BoxSurface>& boxes;
  std::vector<SphereSurface>& spheres;
  std::vector<CylinderSurface>& cylinders;
  std::vector<PrismSurface>& prisms;
  std::vector<GroundTruthPlane>& planes;
};

// Turns one primitive into viewpoint-frame surfaces and ground-truth planes, checking its
// geometry; used with std::visit.
class SurfaceBuilder {
 public:
  SurfaceBuilder(const Eigen::Isometry3d& camera_from_world, std::string viewpoint, std::string where,
                 std::string label, std::uint32_t primitive, const SurfaceLists& lists)
      : camera_from_world_(camera_from_world),
        viewpoint_(std::move(viewpoint)),
        where_(std::move(where)),
        label_(std::move(label)),
        primitive_(primitive),
        lists_(lists) {}

  void operator()(const Rectangle& rectangle) const {
    const double length_u = rectangle.edge_u.norm();
    const double length_v = rectangle.edge_v.norm();
    if (length_u < kLengthEpsilon || length_v < kLengthEpsilon) {
      fail("edge_u and edge_v must not be zero");
    }
    const double cosine = rectangle.edge_u.dot(rectangle.edge_v) / (length_u * length_v);
    if (std::abs(cosine) > kPerpendicularTolerance) {
      fail("edge_u and edge_v must be perpendicular, they are " + formatNumber(std::acos(cosine) * kDegreesPerRadian) +
           " degrees apart");
    }
    const Eigen::Vector3d half_u = rectangle.edge_u / 2.0;
    const Eigen::Vector3d half_v = rectangle.edge_v / 2.0;
    addPolygon({rectangle.center - half_u - half_v, rectangle.center + half_u - half_v,
                rectangle.center + half_u + half_v, rectangle.center - half_u + half_v},
               {});
  }

  void operator()(const Polygon& polygon) const { addPolygon(polygon.vertices, polygon.holes); }

  void operator()(const Box& box) const {
    if ((box.size.array() <= 0.0).any()) {
      fail("size must be positive in all three dimensions");
    }
    const Eigen::Matrix3d& rotation = box.rotation;
    if (!(rotation.transpose() * rotation).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
        rotation.determinant() <= 0.0) {
      fail("rotation is not a rotation matrix");
    }
    Eigen::Isometry3d world_from_box = Eigen::Isometry3d::Identity();
    world_from_box.linear() = rotation;
    world_from_box.translation() = box.center;
    const Eigen::Isometry3d camera_from_box = camera_from_world_ * world_from_box;
    const Eigen::Vector3d half_size = box.size / 2.0;
    const Eigen::Vector3d camera_in_box = camera_from_box.inverse().translation();
    if ((camera_in_box.array().abs() < half_size.array()).all()) {
      fail("the " + viewpoint_ + " is inside this box");
    }
    static constexpr std::array<const char*, 6> face_names{"+x", "-x", "+y", "-y", "+z", "-z"};
    std::array<std::uint32_t, 6> face_ids{};
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? 1.0 : -1.0;
        const Eigen::Vector3d outward = sign * camera_from_box.linear().col(axis);
        const Eigen::Vector3d face_center = camera_from_box.translation() + half_size[axis] * outward;
        const std::size_t face = 2 * static_cast<std::size_t>(axis) + static_cast<std::size_t>(side);
        face_ids[face] = addPlane(outward, face_center, face_names[face], false);
      }
    }
    lists_.boxes.emplace_back(camera_from_box, half_size, face_ids, primitive_);
  }

  void operator()(const Sphere& sphere) const {
    if (sphere.radius <= 0.0) {
      fail("radius must be positive");
    }
    const Eigen::Vector3d center = camera_from_world_ * sphere.center;
    if (center.norm() <= sphere.radius) {
      fail("the " + viewpoint_ + " is inside this sphere");
    }
    lists_.spheres.emplace_back(center, sphere.radius, primitive_);
  }

  void operator()(const Cylinder& cylinder) const {
    if (cylinder.radius <= 0.0 || cylinder.height <= 0.0) {
      fail("radius and height must be positive");
    }
    if (cylinder.axis.norm() < kLengthEpsilon) {
      fail("axis must not be zero");
    }
    const Eigen::Vector3d base = camera_from_world_ * cylinder.base;
    const Eigen::Vector3d axis = camera_from_world_.linear() * cylinder.axis.normalized();
    const Eigen::Vector3d camera_from_base = -base;
    const double along_axis = camera_from_base.dot(axis);
    const double across_axis = (camera_from_base - along_axis * axis).norm();
    if (along_axis >= 0.0 && along_axis <= cylinder.height && across_axis <= cylinder.radius) {
      fail("the " + viewpoint_ + " is inside this cylinder");
    }
    const std::uint32_t top = addPlane(axis, base + cylinder.height * axis, "top", false);
    const std::uint32_t bottom = addPlane(-axis, base, "bottom", false);
    lists_.cylinders.emplace_back(base, axis, cylinder.radius, cylinder.height, top, bottom, primitive_);
  }

  void operator()(const Prism& prism) const {
    std::vector<Eigen::Vector3d> base;
    for (const auto& vertex : prism.base) {
      base.push_back(camera_from_world_ * vertex);
    }
    const Eigen::Vector3d extrusion = camera_from_world_.linear() * prism.extrusion;
    const PolygonPlane plane = checkedPlane(base, "base", "the base");
    // sign(extrusion . normal) turns the base's winding into "outward": the prism lies on the
    // extrusion's side of its base.
    const double rise = extrusion.dot(plane.normal);
    if (std::abs(rise) < kExtrusionSineTolerance * extrusion.norm() || extrusion.norm() < kLengthEpsilon) {
      fail("extrusion must leave the base's plane (it is zero or lies in the plane)");
    }
    const double orientation = rise > 0.0 ? 1.0 : -1.0;
    const Eigen::Vector3d axis_u = plane.normal.unitOrthogonal();
    const Eigen::Vector3d axis_v = plane.normal.cross(axis_u);
    std::vector<Eigen::Vector2d> outline;
    for (const auto& vertex : base) {
      outline.emplace_back((vertex - plane.centroid).dot(axis_u), (vertex - plane.centroid).dot(axis_v));
    }
    if (const auto edge = selfIntersectingEdge(outline)) {
      fail("the base is not a simple polygon: edge " + std::to_string(*edge) + " crosses or touches another edge");
    }
    // The viewpoint is inside when its shadow along the extrusion falls inside the base, between
    // the base and the top.
    const double sweep = -plane.normal.dot(plane.centroid) / rise;  // origin = base point + sweep * extrusion
    const Eigen::Vector3d on_base = -sweep * extrusion - plane.centroid;
    if (sweep > 0.0 && sweep < 1.0 && insidePolygon2d(outline, {on_base.dot(axis_u), on_base.dot(axis_v)})) {
      fail("the " + viewpoint_ + " is inside this prism");
    }

    std::vector<PolygonSurface> faces;
    std::vector<Eigen::Vector3d> top;
    for (const auto& vertex : base) {
      top.push_back(vertex + extrusion);
    }
    faces.push_back(facePolygon(top, orientation * plane.normal, "top"));
    faces.push_back(facePolygon(base, -orientation * plane.normal, "bottom"));
    Eigen::Vector3d bounding_center = plane.centroid + 0.5 * extrusion;
    double bounding_radius = 0.0;
    for (std::size_t i = 0; i < base.size(); ++i) {
      const Eigen::Vector3d& a = base[i];
      const Eigen::Vector3d& b = base[(i + 1) % base.size()];
      faces.push_back(facePolygon({a, b, b + extrusion, a + extrusion}, orientation * (b - a).cross(extrusion),
                                  "side " + std::to_string(i)));
      bounding_radius = std::max({bounding_radius, (a - bounding_center).norm(), (top[i] - bounding_center).norm()});
    }
    // A margin of a micrometre keeps rays that touch a vertex from being rejected by round-off.
    lists_.prisms.emplace_back(std::move(faces), bounding_center, bounding_radius + 1e-6);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(where_ + ": " + what); }

  // Adds a plane through `point` with normal `normal` (for a solid's face, pointing out of
  // the solid) and returns its id. The stored normal is turned towards the camera.
  std::uint32_t addPlane(const Eigen::Vector3d& normal, const Eigen::Vector3d& point, std::string face,
                         bool two_sided) const {
    GroundTruthPlane plane;
    plane.id = static_cast<std::uint32_t>(lists_.planes.size() + 1);
    plane.normal = normal.normalized();
    plane.d = -plane.normal.dot(point);
    // The camera (the origin) is on the side `normal` points to exactly when d > 0.
    plane.faces_camera = two_sided ? std::abs(plane.d) > kLengthEpsilon : plane.d > kLengthEpsilon;
    if (plane.d < 0.0) {
      plane.normal = -plane.normal;
      plane.d = -plane.d;
    }
    plane.primitive = label_;
    plane.face = std::move(face);
    lists_.planes.push_back(plane);
    return plane.id;
  }

  // The plane of a polygon's vertices (viewpoint frame), after checking there are enough of
  // them, that they span an area and lie on one plane. `what` names the vertex list in
  // messages ("vertices", "holes[0]", "base"), `whole` the polygon ("the polygon", "the base").
  PolygonPlane checkedPlane(const std::vector<Eigen::Vector3d>& vertices, const std::string& what,
                            const std::string& whole) const {
    if (vertices.size() < 3) {
      fail(whole + " needs at least 3 vertices, it has " + std::to_string(vertices.size()));
    }
    const PolygonPlane plane = polygonPlane(vertices);
    if (plane.twice_area < kLengthEpsilon) {
      fail(whole + " has no area (its vertices are collinear or repeated)");
    }
    checkOnPlane(vertices, plane, what, whole);
    return plane;
  }

  void checkOnPlane(const std::vector<Eigen::Vector3d>& vertices, const PolygonPlane& plane, const std::string& what,
                    const std::string& whole) const {
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const double off_plane = std::abs(plane.normal.dot(vertices[i] - plane.centroid));
      if (off_plane > kPlanarityTolerance) {
        fail(whole + " is not planar: " + what + "[" + std::to_string(i) + "] is " + formatNumber(off_plane * 1000.0) +
             " mm off the plane of the outline");
      }
    }
  }

  // One flat ring (vertices in the viewpoint frame) drawn on its own plane, with the given
  // outward normal and plane listing: a prism's face.
  PolygonSurface facePolygon(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& outward,
                             std::string face) const {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& vertex : vertices) {
      centroid += vertex;
    }
    centroid /= static_cast<double>(vertices.size());
    const std::uint32_t id = addPlane(outward, centroid, std::move(face), false);
    return ringSurface(lists_.planes.back(), centroid, {vertices}, id);
  }

  // A PolygonSurface on `plane` (its normal already turned towards the viewpoint) through
  // `origin`, with the rings' vertices expressed in a basis of the plane.
  PolygonSurface ringSurface(const GroundTruthPlane& plane, const Eigen::Vector3d& origin,
                             const std::vector<std::vector<Eigen::Vector3d>>& rings, std::uint32_t id) const {
    const Eigen::Vector3d axis_u = plane.normal.unitOrthogonal();
    const Eigen::Vector3d axis_v = plane.normal.cross(axis_u);
    std::vector<Eigen::Vector2d> outline;
    std::vector<std::size_t> ring_ends;
    for (const auto& ring : rings) {
      for (const auto& vertex : ring) {
        outline.emplace_back((vertex - origin).dot(axis_u), (vertex - origin).dot(axis_v));
      }
      ring_ends.push_back(outline.size());
    }
    return {plane.normal, plane.d, origin, axis_u, axis_v, std::move(outline), std::move(ring_ends), id, primitive_};
  }

  void addPolygon(const std::vector<Eigen::Vector3d>& world_vertices,
                  const std::vector<std::vector<Eigen::Vector3d>>& world_holes) const {
    std::vector<std::vector<Eigen::Vector3d>> rings(1);
    for (const auto& vertex : world_vertices) {
      rings[0].push_back(camera_from_world_ * vertex);
    }
    const PolygonPlane plane = checkedPlane(rings[0], "vertices", "the polygon");
    for (std::size_t h = 0; h < world_holes.size(); ++h) {
      const std::string name = "holes[" + std::to_string(h) + "]";
      if (world_holes[h].size() < 3) {
        fail("hole " + std::to_string(h) + " needs at least 3 vertices, it has " +
             std::to_string(world_holes[h].size()));
      }
      rings.emplace_back();
      for (const auto& vertex : world_holes[h]) {
        rings.back().push_back(camera_from_world_ * vertex);
      }
      checkOnPlane(rings.back(), plane, name, "the polygon");
    }
    const std::uint32_t id = addPlane(plane.normal, plane.centroid, "", true);
    lists_.polygons.push_back(ringSurface(lists_.planes.back(), plane.centroid, rings, id));
  }

  const Eigen::Isometry3d& camera_from_world_;
  std::string viewpoint_;
  std::string where_;
  std::string label_;
  std::uint32_t primitive_;
  SurfaceLists lists_;
};

}  // namespace

RayCaster::RayCaster(const Scene& scene) : RayCaster(scene, scene.world_from_camera, "camera") {}

RayCaster::RayCaster(const Scene& scene, const Eigen::Isometry3d& world_from_viewpoint, const std::string& viewpoint) {
  const Eigen::Isometry3d camera_from_world = world_from_viewpoint.inverse();
  const SurfaceLists lists{polygons_, boxes_, spheres_, cylinders_, prisms_, planes_};
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& primitive = scene.primitives[i];
    const std::string description = describePrimitive(i, shapeTypeName(primitive.shape), primitive.name);
    std::visit(
        SurfaceBuilder(camera_from_world, viewpoint, scene.source + ": " + description,
                       primitive.name.empty() ? description : primitive.name, static_cast<std::uint32_t>(i), lists),
        primitive.shape);
  }
}

SurfaceHit RayCaster::cast(const Eigen::Vector3d& direction) const {
  SurfaceHit nearest;
  for (const auto& polygon : polygons_) {
    polygon.intersect(direction, nearest);
  }
  for (const auto& box : boxes_) {
    box.intersect(direction, nearest);
  }
  for (const auto& sphere : spheres_) {
    sphere.intersect(direction, nearest);
  }
  for (const auto& cylinder : cylinders_) {
    cylinder.intersect(direction, nearest);
  }
  for (const auto& prism : prisms_) {
    prism.intersect(direction, nearest);
  }
  return nearest;
}

}  // namespace floodplane::synth
