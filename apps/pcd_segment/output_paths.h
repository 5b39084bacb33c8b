// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where pcd_segment's outputs go. No PCL here: plain paths, so the rules can be tested
// without running a segmentation.

#include <string>

namespace pcd_segment {

/// The name outputs are derived from: the file name without its `.pcd` or `.png` extension.
std::string outputName(const std::string& input_path);

/// The files written for one input.
struct OutputPaths {
  std::string pcd;  ///< the labelled cloud; empty when -o names the label image instead
  std::string png;  ///< the label image
  std::string json;
  std::string overlay;   ///< --overlay: the labels over the input's colours
  std::string snapshot;  ///< the 3-D image of --snapshot given without a file name
  std::string objects;   ///< --objects: the object labels (x y z label, 0 = no object)
};

/// Whether the file `output` names is the label image (it ends in .png, in any case) rather
/// than the labelled cloud (.pcd).
bool namesLabelImage(const std::string& output);

/// The outputs for `input_path`. With `single_file` (one input and -o naming a file) that file
/// is `output` itself, the labelled cloud (.pcd) or the label image alone (.png: no cloud), and
/// the other outputs sit next to it with the same stem (<stem>.png, <stem>.json,
/// <stem>.overlay.png, <stem>.snapshot.png, <stem>.objects.pcd); otherwise `output` is a
/// directory receiving <name>.labels.pcd, <name>.labels.png, <name>.planes.json,
/// <name>.overlay.png, <name>.snapshot.png, <name>.objects.pcd.
OutputPaths outputPaths(const std::string& input_path, const std::string& output, bool single_file);

/// Where --track --json writes its summary of the tracks: OUT/tracks.json, or <stem>.tracks.json
/// next to a single output file.
std::string tracksPath(const std::string& output, bool single_file);

}  // namespace pcd_segment
