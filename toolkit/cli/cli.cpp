// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli/cli.h"

#include <CLI/CLI.hpp>

#include <algorithm>

#include "floodplane/version.h"

namespace floodplane::cli {
namespace {

// CLI11's failure message, one line: CLI11's own default adds a second ("Run with --help for
// more information."), and an error that spans lines is joined so that it stays one.
std::string oneLineFailure(const CLI::App* app, const CLI::Error& error) {
  std::string message = error.what();
  std::replace(message.begin(), message.end(), '\n', ' ');
  return app->get_name() + ": error: " + message + " (see --help)\n";
}

}  // namespace

void addVersionFlag(CLI::App& app) { app.set_version_flag("--version", FLOODPLANE_VERSION_STRING); }

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
  app.failure_message(oneLineFailure);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive here too, as exit code 0 (CLI::Success).
    return app.exit(e) == 0 ? 0 : kUsageExitCode;
  }
  return std::nullopt;
}

std::string labelImageHelp() {
  return std::string("a pixel per point: each plane in a colour of its own (label k always the same colour), ") +
         kUnlabelledPixels;
}

void addAsciiFlag(CLI::App& app, bool& ascii, const std::string& files) {
  app.add_flag("--ascii", ascii, "Write " + files + " as text (default: binary compressed)");
}

int usageError(CLI::App& app, const std::string& message) {
  app.failure_message(oneLineFailure);
  app.exit(CLI::ValidationError(message));
  return kUsageExitCode;
}

}  // namespace floodplane::cli
