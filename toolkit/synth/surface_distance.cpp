// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/surface_distance.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace floodplane::synth {
namespace {

using Ring = std::vector<Eigen::Vector3d>;

double distanceToSegment(const Eigen::Vector3d& point, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d edge = b - a;
  const double length_squared = edge.squaredNorm();
  const double along = length_squared > 0.0 ? std::clamp((point - a).dot(edge) / length_squared, 0.0, 1.0) : 0.0;
  return (point - (a + along * edge)).norm();
}

// The plane of a ring by Newell's method: a unit normal and a point on it.
void ringPlane(const Ring& ring, Eigen::Vector3d& normal, Eigen::Vector3d& centroid) {
  centroid = Eigen::Vector3d::Zero();
  for (const auto& vertex : ring) centroid += vertex;
  centroid /= static_cast<double>(ring.size());
  normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    normal += (ring[i] - centroid).cross(ring[(i + 1) % ring.size()] - centroid);
  }
  normal.normalize();
}

// Even-odd rule over every ring (outline and holes) in a basis of the plane.
bool insideRings(const std::vector<Ring>& rings, const Eigen::Vector3d& normal, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& point) {
  const Eigen::Vector3d axis_u = normal.unitOrthogonal();
  const Eigen::Vector3d axis_v = normal.cross(axis_u);
  const auto flat = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector2d((p - origin).dot(axis_u), (p - origin).dot(axis_v));
  };
  const Eigen::Vector2d q = flat(point);
  bool inside = false;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Eigen::Vector2d a = flat(ring[i]);
      const Eigen::Vector2d b = flat(ring[j]);
      if ((a.y() > q.y()) != (b.y() > q.y()) && q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y())) {
        inside = !inside;
      }
    }
  }
  return inside;
}

// Distance to a flat region bounded by `rings` (the first the outline, the others holes):
// straight to the plane above the region, else to the nearest edge.
double distanceToFlatRegion(const std::vector<Ring>& rings, const Eigen::Vector3d& point) {
  Eigen::Vector3d normal;
  Eigen::Vector3d centroid;
  ringPlane(rings.front(), normal, centroid);
  const double height = normal.dot(point - centroid);
  if (insideRings(rings, normal, centroid, point - height * normal)) {
    return std::abs(height);
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      nearest = std::min(nearest, distanceToSegment(point, ring[i], ring[(i + 1) % ring.size()]));
    }
  }
  return nearest;
}

std::vector<Ring> prismFaces(const Prism& prism) {
  std::vector<Ring> faces;
  Ring top;
  for (const auto& vertex : prism.base) top.push_back(vertex + prism.extrusion);
  faces.push_back(prism.base);
  faces.push_back(top);
  for (std::size_t i = 0; i < prism.base.size(); ++i) {
    const Eigen::Vector3d& a = prism.base[i];
    const Eigen::Vector3d& b = prism.base[(i + 1) % prism.base.size()];
    faces.push_back({a, b, b + prism.extrusion, a + prism.extrusion});
  }
  return faces;
}

// Signed distance to a box (negative inside), in the box's own frame.
double boxSignedDistance(const Box& box, const Eigen::Vector3d& point) {
  const Eigen::Vector3d local = box.rotation.transpose() * (point - box.center);
  const Eigen::Vector3d excess = local.cwiseAbs() - box.size / 2.0;
  return excess.cwiseMax(0.0).norm() + std::min(excess.maxCoeff(), 0.0);
}

// Signed distance to a capped cylinder (negative inside).
double cylinderSignedDistance(const Cylinder& cylinder, const Eigen::Vector3d& point) {
  const Eigen::Vector3d axis = cylinder.axis.normalized();
  const Eigen::Vector3d offset = point - cylinder.base;
  const double along = offset.dot(axis);
  const double across = (offset - along * axis).norm();
  const Eigen::Vector2d excess(across - cylinder.radius,
                               std::abs(along - cylinder.height / 2.0) - cylinder.height / 2.0);
  return excess.cwiseMax(0.0).norm() + std::min(excess.maxCoeff(), 0.0);
}

struct DistanceVisitor {
  const Eigen::Vector3d& point;

  double operator()(const Rectangle& rectangle) const {
    const Eigen::Vector3d u = rectangle.edge_u / 2.0;
    const Eigen::Vector3d v = rectangle.edge_v / 2.0;
    const Eigen::Vector3d& c = rectangle.center;
    return distanceToFlatRegion({{c - u - v, c + u - v, c + u + v, c - u + v}}, point);
  }
  double operator()(const Polygon& polygon) const {
    std::vector<Ring> rings{polygon.vertices};
    rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
    return distanceToFlatRegion(rings, point);
  }
  double operator()(const Box& box) const { return std::abs(boxSignedDistance(box, point)); }
  double operator()(const Sphere& sphere) const { return std::abs((point - sphere.center).norm() - sphere.radius); }
  double operator()(const Cylinder& cylinder) const { return std::abs(cylinderSignedDistance(cylinder, point)); }
  double operator()(const Prism& prism) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Ring& face : prismFaces(prism)) nearest = std::min(nearest, distanceToFlatRegion({face}, point));
    return nearest;
  }
};

struct InsideVisitor {
  const Eigen::Vector3d& point;

  bool operator()(const Rectangle&) const { return false; }
  bool operator()(const Polygon&) const { return false; }
  bool operator()(const Box& box) const { return boxSignedDistance(box, point) < 0.0; }
  bool operator()(const Sphere& sphere) const { return (point - sphere.center).norm() < sphere.radius; }
  bool operator()(const Cylinder& cylinder) const { return cylinderSignedDistance(cylinder, point) < 0.0; }
  bool operator()(const Prism& prism) const {
    // Inside when the point's shadow along the extrusion falls inside the base, between base
    // and top.
    Eigen::Vector3d normal;
    Eigen::Vector3d centroid;
    ringPlane(prism.base, normal, centroid);
    const double rise = normal.dot(prism.extrusion);
    const double sweep = normal.dot(point - centroid) / rise;
    return sweep > 0.0 && sweep < 1.0 && insideRings({prism.base}, normal, centroid, point - sweep * prism.extrusion);
  }
};

}  // namespace

double distanceToSurface(const Shape& shape, const Eigen::Vector3d& point) {
  return std::visit(DistanceVisitor{point}, shape);
}

bool insideSolid(const Shape& shape, const Eigen::Vector3d& point) { return std::visit(InsideVisitor{point}, shape); }

double nearestSurfaceDistance(const Scene& scene, const Eigen::Vector3d& point) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Primitive& primitive : scene.primitives) {
    nearest = std::min(nearest, distanceToSurface(primitive.shape, point));
  }
  return nearest;
}

bool insideAnySolid(const Scene& scene, const Eigen::Vector3d& point) {
  return std::any_of(scene.primitives.begin(), scene.primitives.end(),
                     [&](const Primitive& primitive) { return insideSolid(primitive.shape, point); });
}

}  // namespace floodplane::synth
