// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The inputs of the apps that read frames (pcd_segment, pcd_compare): organized PCD files and,
// with the camera's intrinsics, 16-bit depth PNG images; the options that describe the depth
// camera, and which files a command line's inputs come to.

#include <optional>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/io/input_files.h"

namespace CLI {
class App;
}

namespace floodplane::cli {

/// The depth camera as the command line gives it.
struct DepthInputOptions {
  std::vector<double> intrinsics;  ///< fx fy cx cy [pixels], or empty
  double depth_scale = 1000.0;     ///< depth units per metre
};

/// Adds --intrinsics fx,fy,cx,cy and --depth-scale (which needs --intrinsics).
void addDepthInputOptions(CLI::App& app, DepthInputOptions& options);

/// The depth camera of `options`, when --intrinsics is given. Throws std::invalid_argument
/// naming the flag (--intrinsics or --depth-scale) of a value the back-projection cannot use.
std::optional<io::DepthCamera> depthCamera(const DepthInputOptions& options);

/// The command line's inputs as files (io::expandInputs): a directory gives its .pcd files,
/// and its .png files when there is a camera (`with_camera`); without one a directory of PNG
/// files only is an entry whose error says that --intrinsics is missing (lacks_option).
std::vector<io::InputFile> expandFrameInputs(const std::vector<std::string>& inputs, bool with_camera);

/// The usage error of depth images without a camera: the first input that is a depth image,
/// or a directory of them, while `with_camera` is false, said once before any work.
std::optional<std::string> missingCamera(const std::vector<io::InputFile>& files, bool with_camera);

}  // namespace floodplane::cli
