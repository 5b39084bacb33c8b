// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli/output_target.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace floodplane::cli {
namespace {

namespace fs = std::filesystem;

std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); });
  return text;
}

}  // namespace

OutputKind outputKind(const std::string& flag, const std::string& output,
                      const std::vector<std::string>& file_extensions, const std::string& meaning) {
  if (output.empty()) throw std::invalid_argument(flag + " needs a name: " + meaning);
  std::error_code error;
  if (output.back() == '/' || fs::is_directory(output, error)) return OutputKind::directory;
  const std::string extension = lowerCase(fs::path(output).extension().string());
  if (extension.empty()) return OutputKind::directory;
  for (const std::string& known : file_extensions) {
    if (extension == lowerCase(known)) return OutputKind::file;
  }
  throw std::invalid_argument(flag + " " + output + " looks like a " + extension + " file, but " + meaning +
                              "; end a new directory's name with / if it has a dot");
}

}  // namespace floodplane::cli
