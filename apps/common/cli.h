// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The command-line handling every floodplane app shares: --version, and what --help, --version
// and a bad command line print and exit with.

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace floodplane::apps {

/// Adds --version, which prints the library's version.
void addVersionFlag(CLI::App& app);

/// Parses the command line into `app`'s options. Returns the exit code when the program is
/// done: 0 after --help or --version (printed on stdout), 2 after a bad command line (see
/// usageError). std::nullopt when the program goes on.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv);

/// Prints "<app name>: error: <message>", a blank line and the usage on stderr, and returns
/// 2, the exit code of a usage error. For options that parse but are refused later (a value
/// the library rejects, options that contradict each other).
int usageError(const CLI::App& app, const std::string& message);

}  // namespace floodplane::apps
