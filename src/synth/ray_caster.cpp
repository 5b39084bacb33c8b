#include "ray_caster.h"

#include <array>
#include <cmath>
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

std::string formatNumber(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value;
  return text.str();
}

// Turns one primitive into camera-frame surfaces and ground-truth planes, checking its
// geometry; used with std::visit.
class SurfaceBuilder {
 public:
  SurfaceBuilder(const Eigen::Isometry3d& camera_from_world, std::string where, std::string label,
                 std::vector<PolygonSurface>& polygons, std::vector<BoxSurface>& boxes,
                 std::vector<SphereSurface>& spheres, std::vector<CylinderSurface>& cylinders,
                 std::vector<GroundTruthPlane>& planes)
      : camera_from_world_(camera_from_world),
        where_(std::move(where)),
        label_(std::move(label)),
        polygons_(polygons),
        boxes_(boxes),
        spheres_(spheres),
        cylinders_(cylinders),
        planes_(planes) {}

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
                rectangle.center + half_u + half_v, rectangle.center - half_u + half_v});
  }

  void operator()(const Polygon& polygon) const { addPolygon(polygon.vertices); }

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
      fail("the camera is inside this box");
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
    boxes_.emplace_back(camera_from_box, half_size, face_ids);
  }

  void operator()(const Sphere& sphere) const {
    if (sphere.radius <= 0.0) {
      fail("radius must be positive");
    }
    const Eigen::Vector3d center = camera_from_world_ * sphere.center;
    if (center.norm() <= sphere.radius) {
      fail("the camera is inside this sphere");
    }
    spheres_.emplace_back(center, sphere.radius);
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
      fail("the camera is inside this cylinder");
    }
    const std::uint32_t top = addPlane(axis, base + cylinder.height * axis, "top", false);
    const std::uint32_t bottom = addPlane(-axis, base, "bottom", false);
    cylinders_.emplace_back(base, axis, cylinder.radius, cylinder.height, top, bottom);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(where_ + ": " + what); }

  // Adds a plane through `point` with normal `normal` (for a solid's face, pointing out of
  // the solid) and returns its id. The stored normal is turned towards the camera.
  std::uint32_t addPlane(const Eigen::Vector3d& normal, const Eigen::Vector3d& point, const char* face,
                         bool two_sided) const {
    GroundTruthPlane plane;
    plane.id = static_cast<std::uint32_t>(planes_.size() + 1);
    plane.normal = normal.normalized();
    plane.d = -plane.normal.dot(point);
    // The camera (the origin) is on the side `normal` points to exactly when d > 0.
    plane.faces_camera = two_sided ? std::abs(plane.d) > kLengthEpsilon : plane.d > kLengthEpsilon;
    if (plane.d < 0.0) {
      plane.normal = -plane.normal;
      plane.d = -plane.d;
    }
    plane.primitive = label_;
    plane.face = face;
    planes_.push_back(plane);
    return plane.id;
  }

  void addPolygon(const std::vector<Eigen::Vector3d>& world_vertices) const {
    if (world_vertices.size() < 3) {
      fail("a polygon needs at least 3 vertices, it has " + std::to_string(world_vertices.size()));
    }
    std::vector<Eigen::Vector3d> vertices;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& vertex : world_vertices) {
      vertices.push_back(camera_from_world_ * vertex);
      centroid += vertices.back();
    }
    centroid /= static_cast<double>(vertices.size());
    // Newell's method: the sum of edge cross products is the normal scaled by twice the area,
    // robust for non-convex polygons.
    Eigen::Vector3d area_normal = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      area_normal += (vertices[i] - centroid).cross(vertices[(i + 1) % vertices.size()] - centroid);
    }
    if (area_normal.norm() < kLengthEpsilon) {
      fail("the polygon has no area (its vertices are collinear or repeated)");
    }
    const Eigen::Vector3d normal = area_normal.normalized();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      const double off_plane = std::abs(normal.dot(vertices[i] - centroid));
      if (off_plane > kPlanarityTolerance) {
        fail("the polygon is not planar: vertex " + std::to_string(i) + " is " + formatNumber(off_plane * 1000.0) +
             " mm off the plane of the others");
      }
    }
    const std::uint32_t id = addPlane(normal, centroid, "", true);
    const GroundTruthPlane& plane = planes_.back();
    const Eigen::Vector3d axis_u = plane.normal.unitOrthogonal();
    const Eigen::Vector3d axis_v = plane.normal.cross(axis_u);
    std::vector<Eigen::Vector2d> outline;
    for (const auto& vertex : vertices) {
      outline.emplace_back((vertex - centroid).dot(axis_u), (vertex - centroid).dot(axis_v));
    }
    polygons_.emplace_back(plane.normal, plane.d, centroid, axis_u, axis_v, std::move(outline), id);
  }

  const Eigen::Isometry3d& camera_from_world_;
  std::string where_;
  std::string label_;
  std::vector<PolygonSurface>& polygons_;
  std::vector<BoxSurface>& boxes_;
  std::vector<SphereSurface>& spheres_;
  std::vector<CylinderSurface>& cylinders_;
  std::vector<GroundTruthPlane>& planes_;
};

}  // namespace

RayCaster::RayCaster(const Scene& scene) {
  const Eigen::Isometry3d camera_from_world = scene.world_from_camera.inverse();
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& primitive = scene.primitives[i];
    const std::string description = describePrimitive(i, shapeTypeName(primitive.shape), primitive.name);
    std::visit(SurfaceBuilder(camera_from_world, scene.source + ": " + description,
                              primitive.name.empty() ? description : primitive.name, polygons_, boxes_, spheres_,
                              cylinders_, planes_),
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
  return nearest;
}

}  // namespace floodplane::synth
