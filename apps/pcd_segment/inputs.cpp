#include "inputs.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace pcd_segment {
namespace {

namespace fs = std::filesystem;

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::vector<InputFile> expandInputs(const std::vector<std::string>& arguments) {
  std::vector<InputFile> files;
  for (const std::string& argument : arguments) {
    std::error_code error;
    const fs::file_status status = fs::status(argument, error);
    if (!fs::exists(status)) {
      files.push_back({argument, "no such file or directory"});
      continue;
    }
    if (!fs::is_directory(status)) {
      files.push_back({argument, ""});
      continue;
    }
    std::vector<std::string> found;
    for (fs::directory_iterator it(argument, error), end; !error && it != end; it.increment(error)) {
      // is_directory follows symlinks, so a link to a PCD file counts as a file.
      if (it->path().extension() == ".pcd" && !fs::is_directory(it->path())) {
        found.push_back(it->path().string());
      }
    }
    if (error) {
      files.push_back({argument, "cannot list directory: " + error.message()});
      continue;
    }
    if (found.empty()) {
      files.push_back({argument, "directory contains no .pcd files"});
      continue;
    }
    std::sort(found.begin(), found.end());
    for (std::string& path : found) files.push_back({std::move(path), ""});
  }
  return files;
}

std::string outputName(const std::string& input_path) {
  const fs::path path(input_path);
  return path.extension() == ".pcd" ? path.stem().string() : path.filename().string();
}

bool namesPcdFile(const std::string& output) { return endsWith(output, ".pcd"); }

OutputPaths outputPaths(const std::string& input_path, const std::string& output,
                        bool single_file) {
  if (single_file) {
    // "out/scene.pcd" -> "out/scene.png", "out/scene.json": the name the user chose.
    const std::string stem = output.substr(0, output.size() - 4);
    return {output, stem + ".png", stem + ".json"};
  }
  const std::string base = (fs::path(output) / outputName(input_path)).string();
  return {base + ".labels.pcd", base + ".labels.png", base + ".planes.json"};
}

}  // namespace pcd_segment
