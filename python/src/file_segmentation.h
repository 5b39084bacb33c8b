// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One input file to one label file, as pcd_segment does it: the same reader, the same
// segmentation (with refinement, the sensor moved to the origin), the same output file
// (x y z [rgb] label, binary compressed, the input's grid and pose), written atomically.

#include <optional>
#include <stdexcept>
#include <string>

#include "floodplane/io/depth_camera.h"
#include "floodplane/segmenter.h"

namespace floodplane::python {

struct FileSummary {
  int width = 0;
  int height = 0;
  std::size_t planes = 0;
  double ms = 0.0;                     ///< the segmentation call alone
  std::optional<std::size_t> objects;  ///< the objects found, when asked for
};

/// How to read a depth image: its camera and, when known, the image size it was made for.
struct DepthInput {
  io::DepthCamera camera;
  std::optional<int> width;
  std::optional<int> height;
};

/// The input file cannot be read as a frame (the reason, without the path).
struct InputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// The output file cannot be written.
struct OutputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads `input` (PCD, or a depth PNG with `depth`), segments it with `segmenter` and writes
/// `output`, and with a non-empty `objects_output` the objects on the planes there
/// (x y z label, as pcd_segment --objects). Plain C++ (no Python), so that it runs without the GIL. Throws
/// InputFileError (also for a depth image of another size than `depth` was made for), OutputFileError,
/// std::invalid_argument for a camera with a problem().
FileSummary segmentFile(Segmenter& segmenter, const std::string& input, const std::string& output,
                        const std::optional<DepthInput>& depth, const std::string& objects_output = "");

}  // namespace floodplane::python
