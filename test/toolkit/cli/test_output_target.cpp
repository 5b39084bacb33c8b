// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The one rule by which every app's output options name a file or a directory.

#include "cli/output_target.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "floodplane/io/output_rule.h"
#include "support/app_run.h"

namespace floodplane::test {
namespace {

using cli::OutputKind;
using cli::outputKind;

class OutputTarget : public AppTest {};

OutputKind kindOf(const std::string& output) { return outputKind("-o", output, {".pcd"}, "-o names a .pcd file"); }

TEST_F(OutputTarget, IsAFileWhenItEndsInAnExtensionTheOptionWritesInAnyCase) {
  EXPECT_EQ(kindOf("res/scene.pcd"), OutputKind::file);
  EXPECT_EQ(kindOf("res/SCENE.PCD"), OutputKind::file);
}

TEST_F(OutputTarget, IsADirectoryWithoutExtensionWithATrailingSlashOrWhenItIsOne) {
  EXPECT_EQ(kindOf("res/out"), OutputKind::directory);
  EXPECT_EQ(kindOf("res/scene.pcd/"), OutputKind::directory);
  EXPECT_EQ(kindOf("res/results.v2/"), OutputKind::directory);
  EXPECT_EQ(kindOf("."), OutputKind::directory);
  EXPECT_EQ(kindOf(".."), OutputKind::directory);
  EXPECT_EQ(kindOf(".hidden"), OutputKind::directory);
  std::filesystem::create_directory(path("old.pcd"));
  EXPECT_EQ(kindOf(path("old.pcd").string()), OutputKind::directory);
}

TEST_F(OutputTarget, RefusesAnyOtherExtensionNamingTheFlagAndTheValue) {
  for (const std::string output : {"o/x.txt", "o/x.png", "o/results.v2"}) {
    try {
      kindOf(output);
      ADD_FAILURE() << output << " was accepted";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("-o " + output + " looks like a ", 0), 0u) << message;
      EXPECT_TRUE(contains(message, "-o names a .pcd file")) << message;
      EXPECT_TRUE(contains(message, "end a new directory's name with /")) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
  EXPECT_THROW(kindOf(""), std::invalid_argument);
}

TEST_F(OutputTarget, NamesDirectoriesOnlyWhenTheOptionWritesNoFile) {
  EXPECT_EQ(outputKind("--png", "pictures", {}, "--png names a directory"), OutputKind::directory);
  EXPECT_THROW(outputKind("--png", "pictures.png", {}, "--png names a directory"), std::invalid_argument);
}

// An output is an input when it is the same file, however it is named: the same path, another
// spelling of it, a symbolic or a hard link, a folder reached through a link. An output that
// does not exist yet, or another file, is none.
TEST_F(OutputTarget, FindsAnOutputThatIsAnInputByDeviceAndInode) {
  namespace fs = std::filesystem;
  fs::create_directory(path("in"));
  writeFile(path("in/a.pcd"), "a");
  writeFile(path("in/b.pcd"), "b");
  fs::create_hard_link(path("in/a.pcd"), path("hard.pcd"));
  fs::create_symlink(path("in/a.pcd"), path("soft.pcd"));
  fs::create_directory_symlink(path("in"), path("alias"));
  const std::vector<std::string> inputs = {path("in/b.pcd").string(), path("in/a.pcd").string()};
  const std::string a = path("in/a.pcd").string();
  for (const std::string& output : {a, path("in/../in/a.pcd").string(), path("hard.pcd").string(),
                                    path("soft.pcd").string(), path("alias/a.pcd").string()}) {
    EXPECT_EQ(io::outputCollision({path("new.pcd").string(), output}, inputs),
              "the output " + output + " would overwrite the input " + a);
  }
  EXPECT_EQ(io::outputCollision({path("new.pcd").string(), path("in/c.pcd").string()}, inputs), std::nullopt);
  EXPECT_EQ(io::outputCollision({a}, {path("missing.pcd").string()}), std::nullopt);
  EXPECT_EQ(io::outputCollision({}, inputs), std::nullopt);
}

// Two outputs of one run that name one file, however spelled, or a link to one that exists:
// the second would silently replace the first.
TEST_F(OutputTarget, FindsTwoOutputsThatAreOneFile) {
  namespace fs = std::filesystem;
  fs::create_directory(path("o2"));
  writeFile(path("in.pcd"), "in");
  writeFile(path("o2/old.pcd"), "old");
  fs::create_symlink(path("o2/old.pcd"), path("link.pcd"));
  const std::vector<std::string> inputs = {path("in.pcd").string()};
  const std::string s = path("o2/s.pcd").string();
  for (const std::string& other : {s, path("o2/./s.pcd").string(), path("o2/../o2/s.pcd").string()}) {
    EXPECT_EQ(io::outputCollision({s, other}, inputs), "the outputs " + s + " and " + other + " are one file");
  }
  EXPECT_EQ(io::outputCollision({path("o2/old.pcd").string(), path("link.pcd").string()}, inputs),
            "the outputs " + path("o2/old.pcd").string() + " and " + path("link.pcd").string() + " are one file");
  EXPECT_EQ(io::outputCollision({s, path("o2/s.objects.pcd").string(), ""}, inputs), std::nullopt);
  // A missing directory on the way is no problem of this rule (the write reports it).
  EXPECT_EQ(io::outputCollision({s, path("nodir/s.pcd").string()}, inputs), std::nullopt);
  // An input not written yet by spelling: the rule compares paths too.
  EXPECT_EQ(io::outputCollision({path("./in.pcd").string()}, inputs),
            "the output " + path("./in.pcd").string() + " would overwrite the input " + path("in.pcd").string());
}

}  // namespace
}  // namespace floodplane::test
