// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "progress.h"

#include <string>

namespace pcd_segment {

ProgressBar::ProgressBar(std::size_t total, bool enabled, std::FILE* stream)
    : total_(total), enabled_(enabled && total > 0), stream_(stream), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::show(std::size_t done) {
  if (!enabled_) return;
  constexpr std::size_t kBarWidth = 30;
  const std::size_t filled = kBarWidth * done / total_;
  std::string bar(filled, '=');
  if (filled < kBarWidth) bar += '>';
  bar.resize(kBarWidth, ' ');
  std::string left = "estimating time left";
  if (done > 0) {
    // The files so far predict the rest: batches are usually frames of one sensor.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double remaining = elapsed / static_cast<double>(done) * static_cast<double>(total_ - done);
    left = "about " + std::to_string(static_cast<long>(remaining + 0.5)) + " s left";
  }
  std::fprintf(stream_, "\r\033[K[%s] %zu/%zu files, %s", bar.c_str(), done, total_, left.c_str());
  std::fflush(stream_);
}

void ProgressBar::clear() {
  if (!enabled_) return;
  std::fputs("\r\033[K", stream_);
  std::fflush(stream_);
}

}  // namespace pcd_segment
