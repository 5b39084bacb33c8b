// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// A fresh, empty directory per test, removed afterwards.
class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    directory_ = fs::temp_directory_path() /
                 (std::string("floodplane_atomic_file_") + info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

  static std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  fs::path directory_;
};

TEST_F(AtomicFile, WritesTheBytesUnderTheRequestedNameAndNothingElse) {
  const fs::path target = directory_ / "out.txt";
  floodplane::io::writeBytesAtomically(target.string(), "hello\n");
  EXPECT_EQ(contents(target), "hello\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
  const fs::path target = directory_ / "out.txt";
  floodplane::io::writeBytesAtomically(target.string(), "old contents, longer than the new");
  floodplane::io::writeBytesAtomically(target.string(), "new");
  EXPECT_EQ(contents(target), "new");
  EXPECT_EQ(entries().size(), 1U);
}

TEST_F(AtomicFile, LeavesNoPartialFileWhenTheWriterFails) {
  const fs::path target = directory_ / "out.pcd";
  EXPECT_THROW(floodplane::io::writeFileAtomically(target.string(),
                                                   [](const std::string& temporary) {
                                                     std::ofstream(temporary) << "half a file";
                                                     throw std::runtime_error("disk full");
                                                   }),
               std::runtime_error);
  EXPECT_TRUE(entries().empty());
}

TEST_F(AtomicFile, KeepsThePreviousFileWhenTheWriterFails) {
  const fs::path target = directory_ / "out.txt";
  floodplane::io::writeBytesAtomically(target.string(), "complete");
  EXPECT_THROW(floodplane::io::writeFileAtomically(target.string(),
                                                   [](const std::string& temporary) {
                                                     std::ofstream(temporary) << "trunc";
                                                     throw std::runtime_error("interrupted");
                                                   }),
               std::runtime_error);
  EXPECT_EQ(contents(target), "complete");
  EXPECT_EQ(entries(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFile, NamesThePathWhenTheDirectoryDoesNotExist) {
  const std::string target = (directory_ / "missing" / "out.txt").string();
  try {
    floodplane::io::writeBytesAtomically(target, "x");
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(target), std::string::npos) << error.what();
  }
}

}  // namespace
