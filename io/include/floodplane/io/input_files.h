// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which files a batch tool reads: the command line's files, and the input files inside the
// directories it names. Plain paths, no PCL, so the rules can be tested without reading a file.

#include <string>
#include <vector>

namespace floodplane::io {

/// One command-line input after expansion: a file to read, or an input that could not be
/// expanded (missing, or a directory without input files), kept so that it is reported in the
/// order the user gave it.
struct InputFile {
  std::string path;
  std::string error;  ///< empty for a file to read
  /// A directory whose only input files are of a skipped extension (SkippedExtension): what
  /// the command line lacks, not what the directory holds, is wrong.
  bool lacks_option = false;
};

/// Files a directory listing leaves out for now, and what would make them inputs: a
/// directory that holds such files and no file to read says so instead of "no .pcd files".
struct SkippedExtension {
  std::string extension;  ///< ".png"
  std::string needs;      ///< "depth images, which need --intrinsics fx,fy,cx,cy"
};

/// Expands the command-line inputs: a file stays itself (whatever its extension: the reader
/// decides whether it can read it), a directory becomes its files whose extension is one of
/// `extensions` (not recursive), sorted by path so that batches run in a reproducible order.
/// A missing input, a directory that cannot be listed and a directory without such files each
/// become one entry with an error; a directory whose only candidates have an extension of
/// `skipped` gets an error that names the files and what they need, and lacks_option. An entry
/// of a directory with one of `extensions` that is not a regular file (a directory "x.pcd", a
/// symbolic link to nothing, a named pipe) is an entry with an error, in its sorted place.
std::vector<InputFile> expandInputs(const std::vector<std::string>& arguments,
                                    const std::vector<std::string>& extensions = {".pcd"},
                                    const std::vector<SkippedExtension>& skipped = {});

}  // namespace floodplane::io
