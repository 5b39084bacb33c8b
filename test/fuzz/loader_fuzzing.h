// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the file-loader fuzz targets share: the readers take a path, so each input is written
// to one scratch file per process (in memory where /dev/shm exists), and a violated
// invariant aborts so that libFuzzer reports the input.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace floodplane::fuzz {

[[noreturn]] inline void fail(const char* what) {
  std::fprintf(stderr, "invariant violated: %s\n", what);
  std::abort();
}

/// Writes the input to this process's scratch file, named with `extension`, and returns its path.
inline const std::string& scratchFile(const std::uint8_t* data, std::size_t size, const char* extension) {
  static const std::string path = [extension] {
    const std::filesystem::path folder =
        std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    return (folder / ("floodplane_fuzz_" + std::to_string(::getpid()) + extension)).string();
  }();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) fail("cannot write the scratch file");
  return path;
}

}  // namespace floodplane::fuzz
