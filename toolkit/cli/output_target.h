// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What an output option (-o, --png DIR, ...) names, by the one rule every app follows, so that
// "-o out/x.txt" is never silently a directory called x.txt:
//   1. ending in / or naming an existing directory: a directory;
//   2. otherwise ending in an extension the option writes (".pcd" for pcd_segment's -o): a file;
//   3. otherwise ending in any other extension: refused, it looks like a file the option does
//      not write (a new directory whose name has a dot is given with a trailing /);
//   4. otherwise: a directory, created if missing.

#include <optional>
#include <string>
#include <vector>

namespace floodplane::cli {

enum class OutputKind { file, directory };

/// The kind of `output`, the value of `flag`, by the rule above. `file_extensions` are the
/// extensions a file output of `flag` may have (compared without regard to case; empty: the
/// option names directories only); `meaning` says what `flag` names, for the message of a
/// refused value. Throws std::invalid_argument with a one-line message naming `flag`.
OutputKind outputKind(const std::string& flag, const std::string& output,
                      const std::vector<std::string>& file_extensions, const std::string& meaning);

}  // namespace floodplane::cli
