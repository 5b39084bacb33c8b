// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The command-line handling every floodplane app shares: --version, and what --help, --version
// and a bad command line print and exit with. A usage error is one line on stderr,
// "<app>: error: <what is wrong, naming the flag> (see --help)", and exit code 2: the whole
// help after every typo buried the one line that mattered.

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace floodplane::cli {

/// The exit code of a usage error: a command line that does not parse, or options refused
/// before any work.
inline constexpr int kUsageExitCode = 2;

/// What an app says, as a note on stderr after the input's name, of a frame with no finite point
/// (all NaN, or a depth image of zeros). Such a frame is valid: segmented and written as any
/// other, with no planes, not an error (the rule of the Python module and the ROS node too).
inline constexpr const char* kEmptyFrameNote =
    "no point has a finite x y z (all NaN, or no depth): a frame with no planes";

/// Adds --version, which prints the library's version.
void addVersionFlag(CLI::App& app);

/// Parses the command line into `app`'s options. Returns the exit code when the program is
/// done: 0 after --help or --version (printed on stdout), kUsageExitCode after a bad command
/// line, which CLI11 reports (App::exit) in the one-line form of usageError. std::nullopt when
/// the program goes on.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv);

/// How the apps draw a pixel on no plane and one without a point in every label image, for the
/// help of the options that write them.
inline constexpr const char* kUnlabelledPixels =
    "near-black where a point is on no plane, white where there is no point (no depth)";

/// How the apps draw label images (floodplane/io/label_palette.h's colours), for the help of the options
/// that write them (--png): a pixel per point, each plane in a colour of its own (label k
/// always the same colour), then kUnlabelledPixels.
std::string labelImageHelp();

/// Adds --ascii, which writes `files` ("the label PCD") as text instead of binary compressed.
void addAsciiFlag(CLI::App& app, bool& ascii, const std::string& files);

/// Reports `message` as a usage error through CLI11, in the same form as the errors it finds
/// itself, and returns kUsageExitCode. For options that parse but are refused later (a value
/// the library rejects, options that contradict each other); `message` names the flag.
int usageError(CLI::App& app, const std::string& message);

}  // namespace floodplane::cli
