// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "common/cli.h"

#include <CLI/CLI.hpp>

#include <iostream>

#include "floodplane/version.h"

namespace floodplane::apps {

void addVersionFlag(CLI::App& app) { app.set_version_flag("--version", FLOODPLANE_VERSION_STRING); }

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return usageError(app, e.what());
  }
  return std::nullopt;
}

int usageError(const CLI::App& app, const std::string& message) {
  std::cerr << app.get_name() << ": error: " << message << "\n\n" << app.help();
  return 2;
}

}  // namespace floodplane::apps
