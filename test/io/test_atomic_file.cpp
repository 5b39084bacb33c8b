// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/fs.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
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

// ---- a group of files: all or none -------------------------------------------------------

TEST_F(AtomicFile, AGroupPutsNothingInPlaceBeforeItsCommitAndEverythingAfter) {
  floodplane::io::AtomicFileGroup group;
  group.add((directory_ / "a.pcd").string(), "cloud");
  group.add((directory_ / "a.png").string(), "image");
  EXPECT_EQ(group.paths(),
            (std::vector<std::string>{(directory_ / "a.pcd").string(), (directory_ / "a.png").string()}));
  EXPECT_FALSE(fs::exists(directory_ / "a.pcd"));
  EXPECT_EQ(entries().size(), 2U) << "the two temporaries";
  group.commit();
  EXPECT_EQ(contents(directory_ / "a.pcd"), "cloud");
  EXPECT_EQ(contents(directory_ / "a.png"), "image");
  EXPECT_EQ(entries().size(), 2U);
  EXPECT_TRUE(group.paths().empty());
}

TEST_F(AtomicFile, AGroupDroppedBeforeItsCommitLeavesThePreviousFilesAndNoTemporary) {
  floodplane::io::writeBytesAtomically((directory_ / "a.pcd").string(), "previous");
  {
    floodplane::io::AtomicFileGroup group;
    group.add((directory_ / "a.pcd").string(), "new cloud");
    group.add((directory_ / "a.png").string(), "new image");
    // An error before the commit: the group goes out of scope.
  }
  EXPECT_EQ(entries(), std::vector<std::string>{"a.pcd"});
  EXPECT_EQ(contents(directory_ / "a.pcd"), "previous");
}

// A directory in the way of the second file: found before anything is renamed, so the first
// file's previous version is kept and neither new file appears.
TEST_F(AtomicFile, AGroupWithADirectoryInTheWayCommitsNothing) {
  floodplane::io::writeBytesAtomically((directory_ / "a.pcd").string(), "previous");
  fs::create_directory(directory_ / "a.png");
  floodplane::io::AtomicFileGroup group;
  group.add((directory_ / "a.pcd").string(), "new cloud");
  group.add((directory_ / "a.png").string(), "new image");
  try {
    group.commit();
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "cannot write '" + (directory_ / "a.png").string() + "': Is a directory");
  }
  EXPECT_EQ(contents(directory_ / "a.pcd"), "previous");
  EXPECT_TRUE(fs::is_directory(directory_ / "a.png"));
  EXPECT_EQ(entries().size(), 2U) << "no temporary left";
}

// Sets or clears a file's immutable flag (chattr +i / -i); false where that cannot be done
// (not root, a file system without the flag).
bool setImmutable(const fs::path& path, bool immutable) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  int flags = 0;
  bool done = ::ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
  if (done) {
    flags = immutable ? (flags | FS_IMMUTABLE_FL) : (flags & ~FS_IMMUTABLE_FL);
    done = ::ioctl(fd, FS_IOC_SETFLAGS, &flags) == 0;
  }
  ::close(fd);
  return done;
}

// An old file that cannot be replaced (immutable) behind one that can: the commit fails and
// every path keeps its previous file, the replaceable one included.
TEST_F(AtomicFile, AGroupThatCannotReplaceOneFileKeepsEveryPreviousFile) {
  floodplane::io::writeBytesAtomically((directory_ / "a.pcd").string(), "previous cloud");
  floodplane::io::writeBytesAtomically((directory_ / "a.objects.pcd").string(), "previous objects");
  if (!setImmutable(directory_ / "a.objects.pcd", true)) GTEST_SKIP() << "cannot make a file immutable here";
  floodplane::io::AtomicFileGroup group;
  group.add((directory_ / "a.pcd").string(), "new cloud");
  group.add((directory_ / "a.objects.pcd").string(), "new objects");
  group.add((directory_ / "a.json").string(), "new json");
  EXPECT_THROW(group.commit(), std::runtime_error);
  setImmutable(directory_ / "a.objects.pcd", false);
  EXPECT_EQ(contents(directory_ / "a.pcd"), "previous cloud");
  EXPECT_EQ(contents(directory_ / "a.objects.pcd"), "previous objects");
  EXPECT_FALSE(fs::exists(directory_ / "a.json"));
  EXPECT_EQ(entries().size(), 2U) << "no temporary nor kept copy left";
}

// A successful commit leaves only the new files: the previous ones kept aside are gone.
TEST_F(AtomicFile, AGroupCommittedOverPreviousFilesLeavesOnlyTheNewOnes) {
  floodplane::io::writeBytesAtomically((directory_ / "a.pcd").string(), "previous cloud");
  floodplane::io::AtomicFileGroup group;
  group.add((directory_ / "a.pcd").string(), "new cloud");
  group.add((directory_ / "a.json").string(), "new json");
  group.commit();
  EXPECT_EQ(contents(directory_ / "a.pcd"), "new cloud");
  EXPECT_EQ(contents(directory_ / "a.json"), "new json");
  EXPECT_EQ(entries().size(), 2U);
}

TEST_F(AtomicFile, AGroupRefusesAPathTwice) {
  floodplane::io::AtomicFileGroup group;
  group.add((directory_ / "a.pcd").string(), "one");
  EXPECT_THROW(group.add((directory_ / "a.pcd").string(), "two"), std::invalid_argument);
  EXPECT_THROW(group.add("", "x"), std::invalid_argument);
}

// abandonAtomicWrites never gives its lock back, so it runs in a child process: the
// temporaries of the writes under way there are removed, and it counts them.
TEST_F(AtomicFile, AbandoningRemovesTheTemporariesOfTheWritesUnderWay) {
  floodplane::io::writeBytesAtomically((directory_ / "done.txt").string(), "done");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    floodplane::io::AtomicFileGroup group;
    group.add((directory_ / "a.pcd").string(), "cloud");
    group.add((directory_ / "a.png").string(), "image");
    const bool temporaries_exist = std::distance(fs::directory_iterator(directory_), fs::directory_iterator()) == 3;
    const std::size_t removed = floodplane::io::abandonAtomicWrites();
    ::_exit(temporaries_exist ? static_cast<int>(removed) : 100);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_EQ(entries(), std::vector<std::string>{"done.txt"});
}

// A write that fails part-way says the system's reason. A file size limit (with SIGXFSZ
// ignored, writes past it fail with EFBIG) stands in for a full disk; set in a child process,
// so that it does not limit the test.
TEST_F(AtomicFile, NamesTheSystemsReasonWhenAWriteFailsAndLeavesNoTemporary) {
  const std::string target = (directory_ / "big.bin").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
    try {
      floodplane::io::writeBytesAtomically(target, std::string(100000, 'x'));
    } catch (const std::runtime_error& error) {
      ::_exit(std::string(error.what()) == "cannot write '" + target + "': " + std::strerror(EFBIG) ? 0 : 11);
    }
    ::_exit(12);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "10: no limit, 11: another message, 12: no error";
  EXPECT_TRUE(entries().empty());
}

}  // namespace
