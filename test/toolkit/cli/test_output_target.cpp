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
  using cli::outputOverwritingInput;
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
    EXPECT_EQ(outputOverwritingInput({path("new.pcd").string(), output}, inputs),
              "the output " + output + " would overwrite the input " + a);
  }
  EXPECT_EQ(outputOverwritingInput({path("new.pcd").string(), path("in/c.pcd").string()}, inputs), std::nullopt);
  EXPECT_EQ(outputOverwritingInput({a}, {path("missing.pcd").string()}), std::nullopt);
  EXPECT_EQ(outputOverwritingInput({}, inputs), std::nullopt);
}

}  // namespace
}  // namespace floodplane::test
