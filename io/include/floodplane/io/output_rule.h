// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one rule every front end (pcd_segment, pcd_compare, Python's segment_file) applies to a
// run's outputs before writing any: an output may never be an input, nor another output of the
// same run.

#include <optional>
#include <string>
#include <vector>

namespace floodplane::io {

/// Why a run cannot write `outputs` (every file it would write, side outputs included), having
/// read `inputs` (every file it reads), or nothing if it can:
/// - "the output <output> would overwrite the input <input>" for an output that is the same
///   file as an input: by device and inode when both exist (another spelling, a symbolic or
///   hard link, a directory reached two ways), or by the same absolute path with "." and ".."
///   and links resolved;
/// - "the outputs <a> and <b> are one file" for two outputs that name one file in those ways
///   ("o/./s.pcd" and "o/s.pcd"), where the second would replace the first.
/// Inputs are checked first, in the order of `outputs`. Empty names are skipped; inputs that
/// cannot be examined (missing) are left to the reader's error. Checked before any write, so
/// that a refused run changes nothing.
std::optional<std::string> outputCollision(const std::vector<std::string>& outputs,
                                           const std::vector<std::string>& inputs);

}  // namespace floodplane::io
