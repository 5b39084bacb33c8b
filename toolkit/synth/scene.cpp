// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/scene.h"

#include <array>
#include <string>

namespace floodplane::synth {

const char* shapeTypeName(const Shape& shape) {
  // In the order of the alternatives of Shape.
  static constexpr std::array<const char*, 6> names{"rectangle", "polygon", "box", "sphere", "cylinder", "prism"};
  static_assert(std::variant_size_v<Shape> == names.size());
  return names[shape.index()];
}

namespace {

struct ShapeTransformer {
  const Eigen::Isometry3d& pose;

  std::vector<Eigen::Vector3d> points(const std::vector<Eigen::Vector3d>& list) const {
    std::vector<Eigen::Vector3d> moved;
    moved.reserve(list.size());
    for (const auto& point : list) moved.push_back(pose * point);
    return moved;
  }
  Shape operator()(const Rectangle& r) const {
    return Rectangle{pose * r.center, pose.linear() * r.edge_u, pose.linear() * r.edge_v};
  }
  Shape operator()(const Polygon& polygon) const {
    Polygon moved{points(polygon.vertices), {}};
    for (const auto& hole : polygon.holes) moved.holes.push_back(points(hole));
    return moved;
  }
  Shape operator()(const Box& box) const { return Box{pose * box.center, box.size, pose.linear() * box.rotation}; }
  Shape operator()(const Sphere& sphere) const { return Sphere{pose * sphere.center, sphere.radius}; }
  Shape operator()(const Cylinder& c) const {
    return Cylinder{pose * c.base, pose.linear() * c.axis, c.radius, c.height};
  }
  Shape operator()(const Prism& prism) const { return Prism{points(prism.base), pose.linear() * prism.extrusion}; }
};

}  // namespace

Shape transformShape(const Shape& shape, const Eigen::Isometry3d& pose) {
  return std::visit(ShapeTransformer{pose}, shape);
}

std::string describePrimitive(std::size_t index, std::string_view type, std::string_view name) {
  std::string text = "primitives[" + std::to_string(index) + "] (" + std::string(type);
  if (!name.empty()) {
    text += " \"" + std::string(name) + "\"";
  }
  return text + ")";
}

}  // namespace floodplane::synth
