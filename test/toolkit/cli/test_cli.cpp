// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The help texts every app shares (cli/cli.h): --ascii, and how label images are drawn, said
// once for the three apps that write PCD files or label images.

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <string>

#include "cli/cli.h"

namespace floodplane::cli {
namespace {

TEST(Cli, AsciiFlagSaysWhichFilesItWritesAsText) {
  CLI::App app{"test", "test"};
  bool ascii = false;
  addAsciiFlag(app, ascii, "the PCDs");
  EXPECT_NE(app.help().find("Write the PCDs as text (default: binary compressed)"), std::string::npos) << app.help();
  app.parse(std::string("--ascii"), false);
  EXPECT_TRUE(ascii);
}

TEST(Cli, LabelImageHelpSaysHowPlanesAndUnlabelledPixelsAreDrawn) {
  const std::string help = labelImageHelp();
  EXPECT_EQ(help.find("a pixel per point: each plane in a colour of its own (label k always the same colour)"), 0u);
  EXPECT_EQ(help.substr(help.size() - std::string(kUnlabelledPixels).size()), kUnlabelledPixels);
  EXPECT_EQ(std::string(kUnlabelledPixels),
            "near-black where a point is on no plane, white where there is no point (no depth)");
}

}  // namespace
}  // namespace floodplane::cli
