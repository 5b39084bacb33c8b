// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/input_files.h"

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

// The directory's input files, sorted; an error message instead when there are none.
std::vector<InputFile> listDirectory(const std::string& directory, const std::vector<std::string>& extensions) {
  std::vector<std::string> found;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    // is_directory follows symlinks, so a link to an input file counts as a file.
    if (hasExtension(it->path(), extensions) && !fs::is_directory(it->path())) {
      found.push_back(it->path().string());
    }
  }
  if (error) return {{directory, "cannot list directory: " + error.message()}};
  if (found.empty()) return {{directory, "directory contains no " + extensionList(extensions) + " files"}};
  std::sort(found.begin(), found.end());
  std::vector<InputFile> files;
  for (std::string& path : found) files.push_back({std::move(path), ""});
  return files;
}

}  // namespace

std::vector<InputFile> expandInputs(const std::vector<std::string>& arguments,
                                    const std::vector<std::string>& extensions) {
  std::vector<InputFile> files;
  for (const std::string& argument : arguments) {
    std::error_code error;
    const fs::file_status status = fs::status(argument, error);
    if (!fs::exists(status)) {
      files.push_back({argument, "no such file or directory"});
    } else if (!fs::is_directory(status)) {
      files.push_back({argument, ""});
    } else {
      const std::vector<InputFile> listed = listDirectory(argument, extensions);
      files.insert(files.end(), listed.begin(), listed.end());
    }
  }
  return files;
}

}  // namespace floodplane::io
