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

/// The refusal of a run whose output would overwrite one of its inputs: "the output <output>
/// would overwrite the input <input>" for the first of `outputs` (every file the run would
/// write, side outputs included) that is the same file as one of `inputs` (every file it reads),
/// found by device and inode (links followed: another name, a symbolic or hard link, a
/// directory reached two ways), or nothing. An output that does not exist yet is no input;
/// inputs that cannot be examined (missing) are left to the reader's error. Checked before any
/// write, so that a refused run changes nothing.
std::optional<std::string> outputOverwritingInput(const std::vector<std::string>& outputs,
                                                  const std::vector<std::string>& inputs);

}  // namespace floodplane::cli
