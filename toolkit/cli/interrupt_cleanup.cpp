// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli/interrupt_cleanup.h"

#include <pthread.h>
#include <unistd.h>

#include <csignal>
#include <thread>

#include "floodplane/io/atomic_file.h"

namespace floodplane::cli {
namespace {

[[noreturn]] void endBy(int signal_number, const std::string& program) {
  floodplane::io::abandonAtomicWrites();
  // "\r\033[K" first on a terminal: the line may hold pcd_segment's progress bar.
  const std::string line = std::string(::isatty(2) ? "\r\033[K" : "") + program + ": interrupted by " +
                           (signal_number == SIGINT ? "SIGINT" : "SIGTERM") + ": unfinished outputs removed\n";
  if (::write(2, line.data(), line.size()) < 0) {
    // Nothing more to say: stderr is gone.
  }
  // Die of the signal itself rather than exit(128 + n): a shell running this in a script then
  // knows that it was interrupted and stops too (for SIGINT, bash's "wait and cooperative exit").
  std::signal(signal_number, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal_number);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  std::raise(signal_number);
  ::_exit(128 + signal_number);
}

}  // namespace

void removeTemporariesOnInterrupt(const std::string& program) {
  sigset_t watched;
  sigemptyset(&watched);
  bool any = false;
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction current {};
    if (sigaction(signal_number, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    sigaddset(&watched, signal_number);
    any = true;
  }
  if (!any) return;
  pthread_sigmask(SIG_BLOCK, &watched, nullptr);
  std::thread([watched, program] {
    int signal_number = 0;
    while (sigwait(&watched, &signal_number) != 0) {
    }
    endBy(signal_number, program);
  }).detach();
}

}  // namespace floodplane::cli
