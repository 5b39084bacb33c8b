// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene as authored: a camera and a list of primitives, all in one world frame (metres).
// data/scenes/README.md describes the JSON form; scene_file.h reads it.

#include <Eigen/Geometry>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "synth/camera.h"

namespace floodplane::synth {

/// A scene that cannot be read or rendered. The message names the scene's source (its file)
/// and what is wrong, e.g. "scenes/x.json: primitives[2] (box \"crate\"): size must be
/// positive".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A flat rectangle: corners at center +- edge_u / 2 +- edge_v / 2. The edges must be
/// perpendicular. Seen from both sides. One ground-truth plane.
struct Rectangle {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d edge_u = Eigen::Vector3d::Zero();  ///< full edge vector, not half
  Eigen::Vector3d edge_v = Eigen::Vector3d::Zero();
};

/// A flat, simple (not self-intersecting) polygon, convex or not, given by its vertices in
/// order, optionally with holes (a wall with a door or a niche in it), each a simple polygon
/// inside the outline. All vertices must lie on one plane within 0.1 mm. A point is inside
/// when it is inside the outline and in no hole (the even-odd rule over all rings). Seen from
/// both sides. One ground-truth plane.
struct Polygon {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<Eigen::Vector3d>> holes;
};

/// A solid box with any pose: `rotation` turns the box's axes into world axes and `size`
/// holds its full extents along its own x, y and z. Six ground-truth planes, one per face, in
/// the order +x, -x, +y, -y, +z, -z of the box's own axes.
struct Box {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
};

/// A solid sphere. Not planar: its pixels carry label 0.
struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

/// A solid, capped, finite cylinder from `base` along `axis` for `height`. The curved side is
/// not planar (label 0); the two flat caps are ground-truth planes, top (at base + height *
/// axis) first, then bottom.
struct Cylinder {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  ///< any length; only the direction counts
  double radius = 0.0;
  double height = 0.0;
};

/// A solid prism: the flat polygon `base` (simple, convex or not, vertices in order) swept
/// along `extrusion`, which must not lie in the base's plane (it may be oblique). Every face is
/// a ground-truth plane: the base's copy at base + extrusion ("top") first, then the base
/// ("bottom"), then one side per base edge, "side 0" from vertex 0 to vertex 1 and so on.
/// Wedges, ramps, hexagonal blocks and roof-shaped blocks are prisms.
struct Prism {
  std::vector<Eigen::Vector3d> base;
  Eigen::Vector3d extrusion = Eigen::Vector3d::Zero();
};

using Shape = std::variant<Rectangle, Polygon, Box, Sphere, Cylinder, Prism>;

/// The name of a shape's type as written in scene files ("rectangle", "box", ...).
const char* shapeTypeName(const Shape& shape);

/// The shape moved by the rigid transform `pose` (points mapped, directions turned): how the
/// scene generators place objects built in their own frame.
Shape transformShape(const Shape& shape, const Eigen::Isometry3d& pose);

struct Primitive {
  std::string name;  ///< for messages and the ground-truth listing; may be empty
  Shape shape;
  /// The share of the light falling on the surface that it sends back, in (0, 1]: 1 for white
  /// matte, 0.2 for a dark surface. Only the scanner model uses it: dark surfaces return less.
  double albedo = 1.0;
};

/// How messages refer to a primitive: `primitives[3] (box "crate")`, index counted from 0 as
/// in the scene file's list; the name part is left out when `name` is empty.
std::string describePrimitive(std::size_t index, std::string_view type, std::string_view name);

struct Scene {
  std::string name;         ///< e.g. the scene file's stem; names the outputs
  std::string source;       ///< where the scene came from (a path), for error messages
  std::string description;  ///< free text, copied to the ground-truth listing
  CameraIntrinsics intrinsics;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  std::vector<Primitive> primitives;
};

}  // namespace floodplane::synth
