#pragma once
// Reading scenes from JSON (the format is described in data/scenes/README.md).

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

}  // namespace floodplane::synth
