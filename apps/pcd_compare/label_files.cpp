// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "label_files.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "floodplane/io/label_file.h"

namespace pcd_compare {

namespace fs = std::filesystem;

LabelSource parseLabelSource(const std::string& text) {
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) {
    throw std::invalid_argument("--labels " + text +
                                ": give NAME=DIR (the method's name, the directory of its labels)");
  }
  LabelSource source{text.substr(0, equals), text.substr(equals + 1)};
  if (source.name.empty() || source.name.find_first_of(" \t|") != std::string::npos) {
    throw std::invalid_argument("--labels " + text + ": the name must be one word without '|'");
  }
  if (source.directory.empty()) throw std::invalid_argument("--labels " + text + ": no directory after '='");
  return source;
}

std::string labelFileOf(const std::string& directory, const InputCloud& input, const std::string& pcd_suffix) {
  const fs::path pcd = fs::path(directory) / (input.name + pcd_suffix);
  const fs::path png = fs::path(directory) / (input.name + ".png");
  std::error_code error;
  // Something other than a file under a label file's name (a directory) is named as such,
  // rather than reported missing.
  for (const fs::path& candidate : {pcd, png}) {
    if (fs::exists(candidate, error) && !fs::is_regular_file(candidate, error)) {
      throw std::runtime_error(candidate.string() + " is " +
                               (fs::is_directory(candidate, error) ? "a directory" : "not a regular file") +
                               ", not a label file");
    }
  }
  const bool has_pcd = fs::is_regular_file(pcd, error);
  const bool has_png = fs::is_regular_file(png, error);
  if (has_pcd && has_png) {
    throw std::runtime_error("both " + pcd.string() + " and " + png.string() + " exist; keep one");
  }
  if (!has_pcd && !has_png) throw std::runtime_error("no " + pcd.string() + " or " + png.string());
  const fs::path file = has_pcd ? pcd : png;
  if (fs::equivalent(file, input.path, error)) {
    throw std::runtime_error(file.string() + " is the input itself, not its labels");
  }
  return file.string();
}

std::vector<std::uint32_t> labelsFromDirectory(const std::string& directory, const InputCloud& input,
                                               const std::string& pcd_suffix) {
  const std::string file = labelFileOf(directory, input, pcd_suffix);
  floodplane::io::LabelGrid grid;
  try {
    grid = floodplane::io::readLabelFile(file);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(file + ": " + error.what());
  }
  if (grid.width != input.cloud->width || grid.height != input.cloud->height) {
    throw std::runtime_error(file + ": " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                             " labels for the input's " + std::to_string(input.cloud->width) + "x" +
                             std::to_string(input.cloud->height) + " grid");
  }
  return std::move(grid.labels);
}

}  // namespace pcd_compare
