// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The readers' errors as the apps print them: a std::runtime_error that names the reason, on
// one line.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace floodplane::test {

// Calls `read` expecting a std::runtime_error whose one-line message contains `reason`.
template <typename Read>
void expectOneLineError(Read&& read, const std::string& reason) {
  try {
    read();
    ADD_FAILURE() << "no error, expected '" << reason << "'";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(reason), std::string::npos)
        << "expected '" << reason << "' in: " << error.what();
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line: " << error.what();
  }
}

}  // namespace floodplane::test
