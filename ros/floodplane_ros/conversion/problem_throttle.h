// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which input problems a node logs: each new problem at once, the same one again at most once
// a period, so that a misconfigured 30 Hz stream does not flood the log while a change of
// problem is never hidden.

#include <cstddef>
#include <string>

namespace floodplane::conversion {

class ProblemThrottle {
 public:
  explicit ProblemThrottle(double period_seconds = 1.0) : period_(period_seconds) {}

  /// Whether to log `problem` at time `now` (seconds, any monotonic clock). After true,
  /// suppressed() is the number of times this problem was not logged since it last was.
  bool shouldLog(const std::string& problem, double now) {
    if (problem == last_ && now - last_time_ < period_) {
      ++pending_;
      return false;
    }
    suppressed_ = problem == last_ ? pending_ : 0;
    pending_ = 0;
    last_ = problem;
    last_time_ = now;
    return true;
  }
  std::size_t suppressed() const { return suppressed_; }

 private:
  double period_;
  std::string last_;
  double last_time_ = 0.0;
  std::size_t pending_ = 0;
  std::size_t suppressed_ = 0;
};

}  // namespace floodplane::conversion
