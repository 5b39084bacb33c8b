// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli/depth_input.h"

#include <CLI/CLI.hpp>

#include <stdexcept>

#include "floodplane/io/input_frame.h"

namespace floodplane::cli {
namespace {

constexpr const char* kIntrinsicsNeeded = "--intrinsics fx,fy,cx,cy (and --depth-scale unless in millimetres)";

}  // namespace

void addDepthInputOptions(CLI::App& app, DepthInputOptions& options) {
  CLI::Option* intrinsics = app.add_option("--intrinsics", options.intrinsics,
                                           "fx,fy,cx,cy [pixels] of the depth camera; needed for depth PNG input")
                                ->delimiter(',')
                                ->expected(4);
  app.add_option("--depth-scale", options.depth_scale,
                 "Depth PNG units per metre (1000: millimetres; 5000: the TUM RGB-D benchmark)")
      ->capture_default_str()
      ->needs(intrinsics);
}

std::optional<io::DepthCamera> depthCamera(const DepthInputOptions& options) {
  if (options.intrinsics.empty()) return std::nullopt;
  const std::vector<double>& k = options.intrinsics;
  const io::DepthCamera camera{k.at(0), k.at(1), k.at(2), k.at(3), options.depth_scale};
  const std::string problem = camera.problem();
  if (problem.empty()) return camera;
  // DepthCamera's message names its field: depth_scale is --depth-scale, the rest --intrinsics.
  const std::string scale_field = "depth_scale";
  if (problem.rfind(scale_field, 0) == 0)
    throw std::invalid_argument("--depth-scale" + problem.substr(scale_field.size()));
  throw std::invalid_argument("--intrinsics fx,fy,cx,cy: " + problem);
  return camera;
}

std::vector<io::InputFile> expandFrameInputs(const std::vector<std::string>& inputs, bool with_camera) {
  if (with_camera) return io::expandInputs(inputs, {".pcd", io::kDepthImageExtension});
  // Without a camera a directory's PNG files are not inputs: they may be colour images or
  // label images beside the clouds (pcd_synth --png, pcd_segment --png write such).
  return io::expandInputs(inputs, {".pcd"},
                          {{io::kDepthImageExtension, std::string("read as depth images only with ") +
                                                          kIntrinsicsNeeded + ": --intrinsics is missing"}});
}

std::optional<std::string> missingCamera(const std::vector<io::InputFile>& files, bool with_camera) {
  if (with_camera) return std::nullopt;
  for (const io::InputFile& file : files) {
    if (file.lacks_option) return file.path + ": " + file.error;
    if (file.error.empty() && io::isDepthImagePath(file.path)) {
      return "depth image " + file.path + " needs " + kIntrinsicsNeeded;
    }
  }
  return std::nullopt;
}

}  // namespace floodplane::cli
