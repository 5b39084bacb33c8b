// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace floodplane::io {
namespace {

std::string systemError() { return std::strerror(errno); }

// Creates an empty, uniquely named file next to `path` and returns its name. The name starts
// with a dot and ends in ".tmp.<pid>.<n>" so a leftover (after a crash) is easy to recognise,
// and O_EXCL makes sure two writers never share one temporary.
std::string createTemporaryNextTo(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.parent_path();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name =
        "." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    const std::string temporary = (directory / name).string();
    // 0666 and the process umask give the final file the permissions an ordinary write would.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return temporary;
    }
    if (errno != EEXIST) {
      throw std::runtime_error("cannot write '" + path + "': " + systemError());
    }
  }
  throw std::runtime_error("cannot write '" + path + "': no free temporary file name");
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(const std::string& temporary_path)>& write) {
  if (path.empty()) {
    throw std::invalid_argument("writeFileAtomically: empty path");
  }
  const std::string temporary = createTemporaryNextTo(path);
  try {
    write(temporary);
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      throw std::runtime_error("cannot write '" + path + "': rename failed: " + systemError());
    }
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

void writeBytesAtomically(const std::string& path, std::string_view bytes) {
  writeFileAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      throw std::runtime_error("cannot write '" + path + "': write failed");
    }
  });
}

}  // namespace floodplane::io
