// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Which files a batch reads: the command line's files, and the input files in its directories.

#include "floodplane/io/input_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using floodplane::io::expandInputs;

class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "floodplane_input_files.XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr) path_ = pattern;
  }
  ~TempDir() {
    if (!path_.empty()) fs::remove_all(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

void touch(const fs::path& path) { std::ofstream(path) << "x"; }

TEST(ExpandInputs, ListsADirectorysPcdFilesSortedAndSkipsOthers) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  for (const char* name : {"c.pcd", "a.pcd", "b.pcd", "notes.txt", "d.pcd.bak"}) touch(dir.path() / name);
  fs::create_directory(dir.path() / "sub");
  const auto files = expandInputs({dir.path().string()});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0].path).filename(), "a.pcd");
  EXPECT_EQ(fs::path(files[1].path).filename(), "b.pcd");
  EXPECT_EQ(fs::path(files[2].path).filename(), "c.pcd");
  for (const auto& file : files) EXPECT_TRUE(file.error.empty());
}

// An entry named like an input that is not a file is not skipped without a word: it is an
// input with an error, in its sorted place. A link to a file is a file.
TEST(ExpandInputs, ReportsAnEntryNamedLikeAnInputThatIsNotAFile) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  touch(dir.path() / "a.pcd");
  fs::create_directory(dir.path() / "b.pcd");
  fs::create_symlink(dir.path() / "a.pcd", dir.path() / "c.pcd");
  fs::create_symlink(dir.path() / "missing.pcd", dir.path() / "d.pcd");
  const auto files = expandInputs({dir.path().string()});
  ASSERT_EQ(files.size(), 4u);
  EXPECT_TRUE(files[0].error.empty());
  EXPECT_EQ(fs::path(files[1].path).filename(), "b.pcd");
  EXPECT_EQ(files[1].error, "is a directory, not a file");
  EXPECT_TRUE(files[2].error.empty());
  EXPECT_EQ(fs::path(files[3].path).filename(), "d.pcd");
  EXPECT_EQ(files[3].error, "is a symbolic link to nothing");
}

// With no file to read at all, the directory says so too.
TEST(ExpandInputs, ADirectoryWhoseOnlyCandidateIsADirectorySaysBoth) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  fs::create_directory(dir.path() / "x.pcd");
  const auto files = expandInputs({dir.path().string()});
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].path, dir.path().string());
  EXPECT_EQ(files[0].error, "directory contains no .pcd files");
  EXPECT_EQ(files[1].error, "is a directory, not a file");
}

TEST(ExpandInputs, KeepsTheCommandLineOrderAndReportsBadInputsInPlace) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  touch(dir.path() / "z.pcd");
  fs::create_directory(dir.path() / "empty");
  const auto files = expandInputs(
      {(dir.path() / "z.pcd").string(), (dir.path() / "missing.pcd").string(), (dir.path() / "empty").string()});
  ASSERT_EQ(files.size(), 3u);
  EXPECT_TRUE(files[0].error.empty());
  EXPECT_NE(files[1].error.find("no such file"), std::string::npos);
  EXPECT_NE(files[2].error.find("no .pcd files"), std::string::npos);
}

TEST(ExpandInputs, KeepsAFileOfAnyExtensionThatIsNamedOnTheCommandLine) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  touch(dir.path() / "frame.bin");
  const auto files = expandInputs({(dir.path() / "frame.bin").string()});
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].path, (dir.path() / "frame.bin").string());
  EXPECT_TRUE(files[0].error.empty());
}

TEST(ExpandInputs, ListsTheExtensionsItIsGiven) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  for (const char* name : {"b.png", "a.pcd", "c.txt"}) touch(dir.path() / name);
  const auto files = expandInputs({dir.path().string()}, {".png", ".pcd"});
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(fs::path(files[0].path).filename(), "a.pcd");
  EXPECT_EQ(fs::path(files[1].path).filename(), "b.png");
  const auto none = expandInputs({dir.path().string()}, {".ply"});
  ASSERT_EQ(none.size(), 1u);
  EXPECT_EQ(none[0].error, "directory contains no .ply files");
}

// A directory whose only candidates are of a skipped extension says what they need, not just
// that it has no input files; one that holds an input file leaves the skipped files out.
TEST(ExpandInputs, NamesWhatTheSkippedFilesOfADirectoryWithoutInputsNeed) {
  TempDir dir;
  ASSERT_FALSE(dir.path().empty());
  fs::create_directory(dir.path() / "depth");
  for (const char* name : {"a.png", "b.png", "notes.txt"}) touch(dir.path() / "depth" / name);
  const std::vector<floodplane::io::SkippedExtension> skipped = {{".png", "depth images, which need --intrinsics"}};
  const auto files = expandInputs({(dir.path() / "depth").string()}, {".pcd"}, skipped);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].error,
            "directory contains no .pcd files; its 2 .png files are depth images, which need --intrinsics");
  EXPECT_TRUE(files[0].lacks_option);
  touch(dir.path() / "depth" / "c.pcd");
  const auto mixed = expandInputs({(dir.path() / "depth").string()}, {".pcd"}, skipped);
  ASSERT_EQ(mixed.size(), 1u);
  EXPECT_EQ(fs::path(mixed[0].path).filename(), "c.pcd");
  EXPECT_TRUE(mixed[0].error.empty());
  EXPECT_FALSE(mixed[0].lacks_option);
  // Without skipped files the error is the plain one.
  fs::create_directory(dir.path() / "text");
  touch(dir.path() / "text" / "notes.txt");
  const auto text = expandInputs({(dir.path() / "text").string()}, {".pcd"}, skipped);
  ASSERT_EQ(text.size(), 1u);
  EXPECT_EQ(text[0].error, "directory contains no .pcd files");
  EXPECT_FALSE(text[0].lacks_option);
}

}  // namespace
