// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Labels that other programs wrote, one file per input in a directory: the rows of --labels
// NAME=DIR (any method in the tables) and the ground truth of --ground-truth DIR.
//
// The naming rule: for the input <stem>.pcd or <stem>.png, DIR holds exactly one of
//   <stem>.labels.pcd  a PCD with x y z and a 32-bit unsigned `label` field on the input's grid
//                      (what pcd_segment -o DIR writes), or
//   <stem>.png         a grey PNG of 8 or 16 bits, the input's size, each pixel's value its label;
// label 0 is "no plane". Under --objects, a method's objects are <stem>.objects.pcd (what
// pcd_segment --objects and pcd_compare --write-objects write) in place of <stem>.labels.pcd.

#include <cstdint>
#include <string>
#include <vector>

#include "input_cloud.h"

namespace pcd_compare {

/// A method whose labels come from files: --labels NAME=DIR.
struct LabelSource {
  std::string name;
  std::string directory;
};

/// Parses "NAME=DIR". Throws std::invalid_argument naming --labels when there is no '=', the
/// name is empty or holds a space or '|' (it is a Markdown table's cell), or DIR is empty.
LabelSource parseLabelSource(const std::string& text);

/// The label file of `input` in `directory` by the naming rule, <stem><pcd_suffix> or
/// <stem>.png. Throws std::runtime_error naming the files looked for when there is none, or
/// both, or when the file is the input.
std::string labelFileOf(const std::string& directory, const InputCloud& input,
                        const std::string& pcd_suffix = ".labels.pcd");

/// The labels of `input` from `directory` (labelFileOf, io::readLabelFile), one per pixel of
/// its grid. Throws std::runtime_error naming the file: none found, unreadable, or of another
/// size than the input.
std::vector<std::uint32_t> labelsFromDirectory(const std::string& directory, const InputCloud& input,
                                               const std::string& pcd_suffix = ".labels.pcd");

}  // namespace pcd_compare
