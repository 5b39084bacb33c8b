// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A one-line progress bar for batches: "[=====>    ] 12/40 files, about 35 s left".

#include <chrono>
#include <cstddef>
#include <cstdio>

namespace pcd_segment {

class ProgressBar {
 public:
  /// Draws on `stream` only when `enabled`; otherwise every call does nothing.
  ProgressBar(std::size_t total, bool enabled, std::FILE* stream = stderr);
  /// Redraws the bar after `done` of the files are finished.
  void show(std::size_t done);
  /// Erases the bar so that other output can take its line; show() draws it again.
  void clear();

 private:
  std::size_t total_;
  bool enabled_;
  std::FILE* stream_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace pcd_segment
