// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "output_paths.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace pcd_segment {

namespace fs = std::filesystem;

std::string outputName(const std::string& input_path) {
  const fs::path path(input_path);
  return path.extension() == ".pcd" || path.extension() == ".png" ? path.stem().string() : path.filename().string();
}

bool namesLabelImage(const std::string& output) {
  std::string extension = fs::path(output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return extension == ".png";
}

OutputPaths outputPaths(const std::string& input_path, const std::string& output, bool single_file) {
  if (single_file) {
    // "out/scene.pcd" -> "out/scene.png", "out/scene.json": the name the user chose.
    const std::string stem = output.substr(0, output.size() - 4);
    if (namesLabelImage(output)) {
      return {"", output, stem + ".json", stem + ".overlay.png", stem + ".snapshot.png", stem + ".objects.pcd"};
    }
    return {
        output, stem + ".png", stem + ".json", stem + ".overlay.png", stem + ".snapshot.png", stem + ".objects.pcd"};
  }
  const std::string base = (fs::path(output) / outputName(input_path)).string();
  return {base + ".labels.pcd",  base + ".labels.png",   base + ".planes.json",
          base + ".overlay.png", base + ".snapshot.png", base + ".objects.pcd"};
}

std::string tracksPath(const std::string& output, bool single_file) {
  if (single_file) return output.substr(0, output.size() - 4) + ".tracks.json";
  return (fs::path(output) / "tracks.json").string();
}

}  // namespace pcd_segment
