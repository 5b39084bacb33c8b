// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Running an app's real binary from a test as a user would from a shell: its exit code and all
// it says on stdout and stderr, with a fresh directory per test for its inputs and outputs.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support/files.h"

namespace floodplane::test {

struct Result {
  int exit_code = -1;  ///< 128 + the signal's number when a signal ended the app, as sh says
  std::string out;
  std::string err;
};

// `word` in single quotes for sh, single quotes in it included.
inline std::string quote(const std::string& word) {
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// `binary` and `arguments` as shell text that passes each argument unchanged.
inline std::string commandLine(const std::string& binary, const std::vector<std::string>& arguments) {
  std::string command = quote(binary);
  for (const std::string& argument : arguments) command += " " + quote(argument);
  return command;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline std::size_t lineCount(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// A usage error as every floodplane app reports it: exit code 2 and one line on stderr,
// "<app>: error: <message naming what is wrong> (see --help)", without the usage after it.
inline void expectUsageError(const Result& result, const std::string& app, const std::string& part) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(lineCount(result.err), 1u) << result.err;
  EXPECT_EQ(result.err.rfind(app + ": error: ", 0), 0u) << result.err;
  EXPECT_TRUE(contains(result.err, part)) << "expected '" << part << "' in: " << result.err;
  const std::string end = " (see --help)\n";
  EXPECT_TRUE(result.err.size() >= end.size() &&
              result.err.compare(result.err.size() - end.size(), end.size(), end) == 0)
      << result.err;
}

// xvfb-run on a display of its own. With -a alone, xvfb-run instances started at the same
// moment (parallel tests, other builds on the machine) all try display 99 first and trip over
// each other; each starts its search from a number of its own here. -noreset: otherwise the
// server resets as the last client leaves, while xvfb-run removes its temporary directory,
// which then fails now and then (exit 5, "problem while cleaning up temporary directory").
inline std::string xvfbRun() { return "xvfb-run -a -n " + std::to_string(1000 + ::getpid() % 30000) + " -s -noreset "; }

// A test with a fresh directory of its own, dir_, removed after it: ctest runs the tests of one
// binary in parallel processes, which must not see each other's files.
class AppTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string suite = ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name();
    std::string pattern = (std::filesystem::temp_directory_path() / ("floodplane_" + suite + ".XXXXXX")).string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path path(const std::string& name) const { return dir_ / name; }

  // Runs the shell text `command` (commandLine, after a prefix such as "exec ", "ulimit -f 1; "
  // or xvfbRun()) under sh -c with no input; stdout and stderr go through files in dir_.
  Result runShell(const std::string& command) const {
    const std::filesystem::path out = dir_ / ".stdout";
    const std::filesystem::path err = dir_ / ".stderr";
    const std::string redirected = command + " >" + quote(out.string()) + " 2>" + quote(err.string()) + " </dev/null";
    const int status = std::system(("sh -c " + quote(redirected)).c_str());
    Result result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = readFile(out);
    result.err = readFile(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
  }

  std::filesystem::path dir_;
};

}  // namespace floodplane::test
