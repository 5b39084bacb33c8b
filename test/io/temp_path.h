// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A temporary file path unique to the running test and process: ctest runs tests of one
// binary in parallel processes, so a fixed name lets one test overwrite another's file.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace floodplane::test {

inline std::filesystem::path uniqueTempPath(const std::string& extension) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string("floodplane_") + info->test_suite_name() + "_" + info->name() + "_" +
                     std::to_string(::getpid()) + extension;
  std::replace(name.begin(), name.end(), '/', '_');  // parameterized names contain '/'
  return std::filesystem::temp_directory_path() / name;
}

}  // namespace floodplane::test
