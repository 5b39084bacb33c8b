// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/scene_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace floodplane::synth {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// One JSON object of a scene file, with the keys it may have and the words that locate it in
// error messages ("camera", "primitives[3] (box \"crate\")").
class SceneObject {
 public:
  SceneObject(const json& value, std::string context, const std::string& source,
              std::initializer_list<const char*> allowed_keys)
      : value_(value), context_(std::move(context)), source_(source) {
    if (!value_.is_object()) {
      fail("must be a JSON object");
    }
    for (const auto& item : value_.items()) {
      bool allowed = false;
      for (const char* key : allowed_keys) {
        allowed = allowed || item.key() == key;
      }
      if (!allowed) {
        std::string expected;
        for (const char* key : allowed_keys) {
          expected += std::string(expected.empty() ? "" : ", ") + "\"" + key + "\"";
        }
        fail("unknown key \"" + item.key() + "\" (expected " + expected + ")");
      }
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError(source_ + ": " + (context_.empty() ? "" : context_ + ": ") + what);
  }

  bool has(const char* key) const { return value_.contains(key); }

  const json& required(const char* key) const {
    if (!has(key)) {
      fail(std::string("missing \"") + key + "\"");
    }
    return value_.at(key);
  }

  double number(const char* key) const { return toNumber(required(key), key); }

  double number(const char* key, double fallback) const { return has(key) ? number(key) : fallback; }

  int integer(const char* key, int fallback) const {
    if (!has(key)) {
      return fallback;
    }
    const json& value = value_.at(key);
    if (!value.is_number_integer()) {
      fail(std::string("\"") + key + "\" must be a whole number");
    }
    return value.get<int>();
  }

  std::string string(const char* key, const std::string& fallback) const {
    if (!has(key)) {
      return fallback;
    }
    const json& value = value_.at(key);
    if (!value.is_string()) {
      fail(std::string("\"") + key + "\" must be a string");
    }
    return value.get<std::string>();
  }

  Eigen::Vector3d vector3(const char* key) const { return toVector3(required(key), key); }

  Eigen::Vector3d vector3(const char* key, const Eigen::Vector3d& fallback) const {
    return has(key) ? vector3(key) : fallback;
  }

  // A list of 3-vectors, e.g. a polygon's vertices.
  std::vector<Eigen::Vector3d> vector3List(const char* key) const { return toVector3List(required(key), key); }

  // A list of lists of 3-vectors, e.g. a polygon's holes; empty when the key is missing.
  std::vector<std::vector<Eigen::Vector3d>> vector3Lists(const char* key) const {
    std::vector<std::vector<Eigen::Vector3d>> lists;
    if (!has(key)) {
      return lists;
    }
    const json& value = value_.at(key);
    if (!value.is_array()) {
      fail(std::string("\"") + key + "\" must be an array of lists of [x, y, z] points");
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      lists.push_back(toVector3List(value[i], std::string(key) + "[" + std::to_string(i) + "]"));
    }
    return lists;
  }

  // A 3x3 matrix given as three rows of 3 numbers.
  Eigen::Matrix3d matrix3(const char* key) const {
    const json& value = required(key);
    if (!value.is_array() || value.size() != 3) {
      fail(std::string("\"") + key + "\" must be an array of 3 rows of 3 numbers");
    }
    Eigen::Matrix3d matrix;
    for (Eigen::Index row = 0; row < 3; ++row) {
      const std::string name = std::string(key) + "[" + std::to_string(row) + "]";
      matrix.row(row) = toVector3(value[static_cast<std::size_t>(row)], name).transpose();
    }
    return matrix;
  }

  SceneObject object(const char* key, std::initializer_list<const char*> allowed_keys) const {
    return SceneObject(required(key), context_.empty() ? key : context_ + "." + key, source_, allowed_keys);
  }

 private:
  double toNumber(const json& value, const std::string& name) const {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      fail("\"" + name + "\" must be a finite number");
    }
    return value.get<double>();
  }

  std::vector<Eigen::Vector3d> toVector3List(const json& value, const std::string& name) const {
    if (!value.is_array()) {
      fail("\"" + name + "\" must be an array of [x, y, z] points");
    }
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i < value.size(); ++i) {
      points.push_back(toVector3(value[i], name + "[" + std::to_string(i) + "]"));
    }
    return points;
  }

  Eigen::Vector3d toVector3(const json& value, const std::string& name) const {
    if (!value.is_array() || value.size() != 3) {
      fail("\"" + name + "\" must be an array of 3 numbers");
    }
    return {toNumber(value[0], name), toNumber(value[1], name), toNumber(value[2], name)};
  }

  const json& value_;
  std::string context_;
  const std::string& source_;
};

double degreesToRadians(double degrees) { return degrees * kPi / 180.0; }

// "rotation": {"rpy_deg": [roll, pitch, yaw]} turns about the world's x by roll, then y by
// pitch, then z by yaw (R = Rz(yaw) Ry(pitch) Rx(roll)); {"axis": [x, y, z], "angle_deg": a}
// turns by a about the axis; {"matrix": [[r00, r01, r02], [r10, ...], [r20, ...]]} gives R by
// its rows (exact: the scene writer uses it). Whether a matrix is a rotation is checked where
// it is used.
Eigen::Matrix3d parseRotation(const SceneObject& parent) {
  if (!parent.has("rotation")) {
    return Eigen::Matrix3d::Identity();
  }
  const SceneObject rotation = parent.object("rotation", {"rpy_deg", "axis", "angle_deg", "matrix"});
  const int forms =
      (rotation.has("rpy_deg") ? 1 : 0) + (rotation.has("axis") ? 1 : 0) + (rotation.has("matrix") ? 1 : 0);
  if (forms != 1) {
    rotation.fail("give one of \"rpy_deg\", \"axis\" with \"angle_deg\", or \"matrix\"");
  }
  if (rotation.has("angle_deg") && !rotation.has("axis")) {
    rotation.fail("\"angle_deg\" belongs with \"axis\"");
  }
  if (rotation.has("matrix")) {
    return rotation.matrix3("matrix");
  }
  if (rotation.has("rpy_deg")) {
    const Eigen::Vector3d rpy = rotation.vector3("rpy_deg");
    return (Eigen::AngleAxisd(degreesToRadians(rpy.z()), Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(degreesToRadians(rpy.y()), Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(degreesToRadians(rpy.x()), Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
  }
  const Eigen::Vector3d axis = rotation.vector3("axis");
  if (axis.norm() < 1e-12) {
    rotation.fail("\"axis\" must not be zero");
  }
  return Eigen::AngleAxisd(degreesToRadians(rotation.number("angle_deg")), axis.normalized()).toRotationMatrix();
}

Shape parseShape(const json& value, const std::string& context, const std::string& source) {
  if (!value.is_object() || !value.contains("type") || !value.at("type").is_string()) {
    throw SceneError(source + ": " + context +
                     ": needs \"type\": \"rectangle\", \"polygon\", \"box\", \"sphere\", \"cylinder\" or "
                     "\"prism\"");
  }
  const std::string type = value.at("type").get<std::string>();
  if (type == "rectangle") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "center", "edge_u", "edge_v"});
    return Rectangle{object.vector3("center"), object.vector3("edge_u"), object.vector3("edge_v")};
  }
  if (type == "polygon") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "vertices", "holes"});
    return Polygon{object.vector3List("vertices"), object.vector3Lists("holes")};
  }
  if (type == "box") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "center", "size", "rotation"});
    return Box{object.vector3("center"), object.vector3("size"), parseRotation(object)};
  }
  if (type == "sphere") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "center", "radius"});
    return Sphere{object.vector3("center"), object.number("radius")};
  }
  if (type == "cylinder") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "base", "axis", "radius", "height"});
    return Cylinder{object.vector3("base"), object.vector3("axis", Eigen::Vector3d::UnitZ()), object.number("radius"),
                    object.number("height")};
  }
  if (type == "prism") {
    const SceneObject object(value, context, source, {"type", "name", "albedo", "base", "extrusion"});
    return Prism{object.vector3List("base"), object.vector3("extrusion")};
  }
  throw SceneError(source + ": " + context + ": unknown type \"" + type +
                   "\" (expected rectangle, polygon, box, sphere, cylinder or prism)");
}

// The camera's pose: "look_at" (and "up") aims it; "rotation" gives its axes instead (the
// columns of world_from_camera: right, down, forward), as the scene writer does.
void parseCamera(const SceneObject& root, Scene& scene) {
  const SceneObject camera =
      root.object("camera", {"position", "look_at", "up", "rotation", "width", "height", "fx", "fy", "cx", "cy"});
  CameraIntrinsics& intrinsics = scene.intrinsics;
  intrinsics.width = camera.integer("width", intrinsics.width);
  intrinsics.height = camera.integer("height", intrinsics.height);
  intrinsics.fx = camera.number("fx", intrinsics.fx);
  intrinsics.fy = camera.number("fy", intrinsics.fy);
  // The default principal point is the image centre of whatever resolution was given.
  intrinsics.cx = camera.number("cx", (intrinsics.width - 1) / 2.0);
  intrinsics.cy = camera.number("cy", (intrinsics.height - 1) / 2.0);
  if (camera.has("rotation")) {
    if (camera.has("look_at") || camera.has("up")) {
      camera.fail("give either \"look_at\" (and \"up\") or \"rotation\", not both");
    }
    const Eigen::Matrix3d rotation = parseRotation(camera);
    if (!(rotation.transpose() * rotation).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
        rotation.determinant() <= 0.0) {
      camera.fail("rotation is not a rotation matrix");
    }
    scene.world_from_camera = Eigen::Isometry3d::Identity();
    scene.world_from_camera.linear() = rotation;
    scene.world_from_camera.translation() = camera.vector3("position");
    return;
  }
  try {
    scene.world_from_camera =
        lookAt(camera.vector3("position"), camera.vector3("look_at"), camera.vector3("up", Eigen::Vector3d::UnitZ()));
  } catch (const std::invalid_argument& error) {
    camera.fail(error.what());
  }
}

// nlohmann's messages start with "[json.exception.parse_error.101] "; the rest is the part
// a scene author needs (line, column, what was expected).
std::string withoutExceptionId(const std::string& message) {
  const auto end_of_id = message.find("] ");
  return end_of_id == std::string::npos ? message : message.substr(end_of_id + 2);
}

}  // namespace

Scene parseScene(std::string_view json_text, const std::string& source) {
  json document;
  try {
    document = json::parse(json_text, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& error) {
    throw SceneError(source + ": not valid JSON: " + withoutExceptionId(error.what()));
  }
  const SceneObject root(document, "", source, {"description", "camera", "primitives"});
  Scene scene;
  scene.name = std::filesystem::path(source).stem().string();
  scene.source = source;
  scene.description = root.string("description", "");
  parseCamera(root, scene);

  const json& primitives = root.required("primitives");
  if (!primitives.is_array()) {
    root.fail("\"primitives\" must be an array");
  }
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const json& value = primitives[i];
    Primitive primitive;
    const std::string context = "primitives[" + std::to_string(i) + "]";
    if (value.is_object() && value.contains("name")) {
      if (!value.at("name").is_string()) {
        throw SceneError(source + ": " + context + ": \"name\" must be a string");
      }
      primitive.name = value.at("name").get<std::string>();
    }
    std::string described = context;
    if (value.is_object() && value.contains("type") && value.at("type").is_string()) {
      described = describePrimitive(i, value.at("type").get<std::string>(), primitive.name);
    }
    primitive.shape = parseShape(value, described, source);
    if (value.contains("albedo")) {
      const json& albedo = value.at("albedo");
      if (!albedo.is_number() || !(albedo.get<double>() > 0.0 && albedo.get<double>() <= 1.0)) {
        throw SceneError(source + ": " + described + ": \"albedo\" must be a number above 0 and at most 1");
      }
      primitive.albedo = albedo.get<double>();
    }
    scene.primitives.push_back(std::move(primitive));
  }
  return scene;
}

Scene loadScene(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(path + ": cannot open the scene file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw SceneError(path + ": cannot read the scene file");
  }
  return parseScene(text.str(), path);
}

}  // namespace floodplane::synth
