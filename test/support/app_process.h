// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An app's real binary started in the background, for a test that acts while it runs (sends
// it a signal as Ctrl-C would) and then waits for it, within a bound.

#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace floodplane::test {

class AppProcess {
 public:
  /// Starts `binary` with `arguments`, stdin from /dev/null, stdout and stderr into the files
  /// `out` and `err`, with SIGINT and SIGTERM at their defaults and no signal blocked (the test
  /// runner's own dispositions must not leak into the app). running() is false if it failed.
  AppProcess(const std::string& binary, const std::vector<std::string>& arguments, const std::filesystem::path& out,
             const std::filesystem::path& err) {
    std::vector<std::string> words = {binary};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    const int in_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (in_fd >= 0 && out_fd >= 0 && err_fd >= 0) pid_ = ::fork();
    if (pid_ == 0) {
      // The child: only async-signal-safe calls until exec.
      ::signal(SIGINT, SIG_DFL);
      ::signal(SIGTERM, SIG_DFL);
      sigset_t none;
      sigemptyset(&none);
      ::sigprocmask(SIG_SETMASK, &none, nullptr);
      ::dup2(in_fd, 0);
      ::dup2(out_fd, 1);
      ::dup2(err_fd, 2);
      ::execv(binary.c_str(), argv.data());
      ::_exit(127);
    }
    for (const int fd : {in_fd, out_fd, err_fd}) {
      if (fd >= 0) ::close(fd);
    }
  }
  AppProcess(const AppProcess&) = delete;
  AppProcess& operator=(const AppProcess&) = delete;
  /// A process still running at the end of a test (it failed) is killed, not left behind.
  ~AppProcess() {
    if (running()) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }

  bool running() {
    if (pid_ <= 0 || exit_code_) return false;
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      signalled_ = WIFSIGNALED(status);
      return false;
    }
    return true;
  }

  void signal(int signal_number) const {
    if (pid_ > 0) ::kill(pid_, signal_number);
  }

  /// Waits up to `timeout` for the process to end; its exit code as sh reports it (128 + the
  /// signal's number when a signal ended it), or std::nullopt if it is still running.
  std::optional<int> waitFor(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (running() && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return exit_code_;
  }

  /// Whether a signal, rather than exit(), ended the process (once waitFor returned a code).
  bool endedBySignal() const { return signalled_; }

 private:
  pid_t pid_ = -1;
  std::optional<int> exit_code_;
  bool signalled_ = false;
};

}  // namespace floodplane::test
