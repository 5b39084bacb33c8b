// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading and writing scenes as JSON (the format is described in data/scenes/README.md).

#include <string>
#include <string_view>

#include "synth/scene.h"

namespace floodplane::synth {

/// Parses a scene from JSON text; `//` and `/* */` comments are allowed. `source` names the
/// text in error messages, and its file stem becomes the scene's name.
/// Throws SceneError ("<source>: <where>: <what is wrong>") for invalid JSON, missing or
/// unknown keys, and values of the wrong type or length. Geometric problems (a non-planar
/// polygon, a camera inside a box) are found when the scene is rendered (see RayCaster).
Scene parseScene(std::string_view json_text, const std::string& source);

/// Reads and parses the scene file at `path`; throws SceneError naming `path` if it cannot be
/// read or is not a valid scene.
Scene loadScene(const std::string& path);

/// The scene as JSON text that parseScene reads back into the same primitives, camera pose
/// and intrinsics, bit for bit (a generated scene saved for a closer look renders the same).
/// The camera is written with "rotation" instead of "look_at", box rotations as matrices.
std::string sceneJson(const Scene& scene);

}  // namespace floodplane::synth
