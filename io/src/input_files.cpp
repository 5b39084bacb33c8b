// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/input_files.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace floodplane::io {
namespace {

namespace fs = std::filesystem;

bool hasExtension(const fs::path& path, const std::vector<std::string>& extensions) {
  return std::find(extensions.begin(), extensions.end(), path.extension().string()) != extensions.end();
}

std::string extensionList(const std::vector<std::string>& extensions) {
  std::string list;
  for (const std::string& extension : extensions) list += (list.empty() ? "" : " or ") + extension;
  return list;
}

// The error of a directory without input files: what it holds instead, when that is files of
// a skipped extension.
InputFile withoutInputs(const std::string& directory, const std::vector<std::string>& extensions,
                        const std::vector<SkippedExtension>& skipped, const std::vector<std::size_t>& skipped_counts) {
  const std::string none = "directory contains no " + extensionList(extensions) + " files";
  for (std::size_t k = 0; k < skipped.size(); ++k) {
    if (skipped_counts[k] == 0) continue;
    const std::size_t count = skipped_counts[k];
    return {directory,
            none + "; its " + std::to_string(count) + " " + skipped[k].extension +
                (count == 1 ? " file is " : " files are ") + skipped[k].needs,
            true};
  }
  return {directory, none};
}

// Why an entry named like an input file cannot be read as one (`status` follows symbolic links).
std::string notAFile(const fs::file_status& status) {
  switch (status.type()) {
    case fs::file_type::directory:
      return "is a directory, not a file";
    case fs::file_type::not_found:
      return "is a symbolic link to nothing";
    case fs::file_type::fifo:
      return "is a named pipe, not a file";
    case fs::file_type::socket:
      return "is a socket, not a file";
    default:
      return "is not a regular file";
  }
}

// The directory's input files, sorted; an error message instead when there are none. An entry
// named like an input file that is not a regular file (a directory "x.pcd", a dangling link, a
// named pipe, which would block the reader) is kept, in its place, with an error: a batch says
// what it skipped.
std::vector<InputFile> listDirectory(const std::string& directory, const std::vector<std::string>& extensions,
                                     const std::vector<SkippedExtension>& skipped) {
  std::vector<InputFile> found;
  bool any_file = false;
  std::vector<std::size_t> skipped_counts(skipped.size(), 0);
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    // status follows symbolic links, so a link to an input file counts as a file.
    std::error_code status_error;
    const fs::file_status status = fs::status(it->path(), status_error);
    const bool regular = fs::is_regular_file(status);
    if (hasExtension(it->path(), extensions)) {
      found.push_back({it->path().string(), regular ? "" : notAFile(status)});
      any_file = any_file || regular;
      continue;
    }
    for (std::size_t k = 0; k < skipped.size(); ++k) {
      if (regular && it->path().extension() == skipped[k].extension) ++skipped_counts[k];
    }
  }
  if (error) return {{directory, "cannot list directory: " + error.message()}};
  std::sort(found.begin(), found.end(), [](const InputFile& a, const InputFile& b) { return a.path < b.path; });
  if (!any_file) found.insert(found.begin(), withoutInputs(directory, extensions, skipped, skipped_counts));
  return found;
}

}  // namespace

std::vector<InputFile> expandInputs(const std::vector<std::string>& arguments,
                                    const std::vector<std::string>& extensions,
                                    const std::vector<SkippedExtension>& skipped) {
  std::vector<InputFile> files;
  for (const std::string& argument : arguments) {
    std::error_code error;
    const fs::file_status status = fs::status(argument, error);
    if (!fs::exists(status)) {
      files.push_back({argument, "no such file or directory"});
    } else if (!fs::is_directory(status)) {
      files.push_back({argument, ""});
    } else {
      const std::vector<InputFile> listed = listDirectory(argument, extensions, skipped);
      files.insert(files.end(), listed.begin(), listed.end());
    }
  }
  return files;
}

}  // namespace floodplane::io
