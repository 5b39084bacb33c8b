// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Writing scenes as JSON that parseScene reads back into the same scene, number for number:
// nlohmann::json prints the shortest decimal that reads back as the same double, and poses
// are written as matrices ("rotation": {"matrix": ...}) rather than angles, which would not
// survive the round trip exactly.

#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "synth/scene_file.h"

namespace floodplane::synth {
namespace {

using nlohmann::ordered_json;  // keeps keys in the order written, for human readers

ordered_json vector3(const Eigen::Vector3d& v) { return ordered_json::array({v.x(), v.y(), v.z()}); }

ordered_json vector3List(const std::vector<Eigen::Vector3d>& points) {
  ordered_json list = ordered_json::array();
  for (const auto& point : points) {
    list.push_back(vector3(point));
  }
  return list;
}

ordered_json rotationMatrix(const Eigen::Matrix3d& rotation) {
  ordered_json rows = ordered_json::array();
  for (Eigen::Index row = 0; row < 3; ++row) {
    rows.push_back(vector3(rotation.row(row).transpose()));
  }
  return {{"matrix", rows}};
}

// One primitive's keys after "type" and "name"; used with std::visit.
struct ShapeWriter {
  ordered_json& object;

  void operator()(const Rectangle& rectangle) const {
    object["center"] = vector3(rectangle.center);
    object["edge_u"] = vector3(rectangle.edge_u);
    object["edge_v"] = vector3(rectangle.edge_v);
  }
  void operator()(const Polygon& polygon) const {
    object["vertices"] = vector3List(polygon.vertices);
    if (!polygon.holes.empty()) {
      ordered_json holes = ordered_json::array();
      for (const auto& hole : polygon.holes) {
        holes.push_back(vector3List(hole));
      }
      object["holes"] = holes;
    }
  }
  void operator()(const Box& box) const {
    object["center"] = vector3(box.center);
    object["size"] = vector3(box.size);
    if (box.rotation != Eigen::Matrix3d::Identity()) {
      object["rotation"] = rotationMatrix(box.rotation);
    }
  }
  void operator()(const Sphere& sphere) const {
    object["center"] = vector3(sphere.center);
    object["radius"] = sphere.radius;
  }
  void operator()(const Cylinder& cylinder) const {
    object["base"] = vector3(cylinder.base);
    object["axis"] = vector3(cylinder.axis);
    object["radius"] = cylinder.radius;
    object["height"] = cylinder.height;
  }
  void operator()(const Prism& prism) const {
    object["base"] = vector3List(prism.base);
    object["extrusion"] = vector3(prism.extrusion);
  }
};

}  // namespace

std::string sceneJson(const Scene& scene) {
  const CameraIntrinsics& intrinsics = scene.intrinsics;
  ordered_json camera;
  camera["position"] = vector3(scene.world_from_camera.translation());
  camera["rotation"] = rotationMatrix(scene.world_from_camera.linear());
  camera["width"] = intrinsics.width;
  camera["height"] = intrinsics.height;
  camera["fx"] = intrinsics.fx;
  camera["fy"] = intrinsics.fy;
  camera["cx"] = intrinsics.cx;
  camera["cy"] = intrinsics.cy;

  // One primitive a line, as in the hand-written scene files.
  std::string text = "{\n  \"description\": " + ordered_json(scene.description).dump() + ",\n";
  text += "  \"camera\": " + camera.dump() + ",\n  \"primitives\": [";
  for (std::size_t i = 0; i < scene.primitives.size(); ++i) {
    const Primitive& primitive = scene.primitives[i];
    ordered_json object;
    object["type"] = shapeTypeName(primitive.shape);
    if (!primitive.name.empty()) {
      object["name"] = primitive.name;
    }
    std::visit(ShapeWriter{object}, primitive.shape);
    if (primitive.albedo != 1.0) {
      object["albedo"] = primitive.albedo;
    }
    text += (i == 0 ? "\n    " : ",\n    ") + object.dump();
  }
  return text + "\n  ]\n}\n";
}

}  // namespace floodplane::synth
