// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Ending a program on Ctrl-C (SIGINT) or SIGTERM without leaving temporary files behind.

#include <string>

namespace floodplane::cli {

/// Makes SIGINT and SIGTERM end the program cleanly: the temporaries of the atomic writes under
/// way are removed and no output is renamed into place after that (io::abandonAtomicWrites),
/// "<program>: interrupted by SIGINT: unfinished outputs removed" is said on stderr, and the
/// program ends by that signal, which a shell reports as status 130 (SIGINT) or 143 (SIGTERM).
///
/// Call it first thing in main, before any thread starts: it blocks the two signals in the
/// calling thread, which every thread started later inherits, and one thread of its own waits
/// for them (sigwait). So the cleanup runs as ordinary code, not in a signal handler, where it
/// could neither take the lock that keeps worker threads from creating or renaming a temporary
/// while it removes them nor safely allocate. A signal the program was started ignoring (nohup,
/// a background job of a non-interactive shell) stays ignored.
void removeTemporariesOnInterrupt(const std::string& program);

}  // namespace floodplane::cli
