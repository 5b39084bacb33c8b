// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs the items of a batch on several threads and reports their results on the calling
// thread in item order, so that a parallel run prints, and fails, exactly as a serial one.

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace pcd_segment {

/// The number of threads `-j` means by default: one per core the machine reports, at least 1.
inline unsigned defaultJobs() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Calls `work(worker, i)` for every i in [0, count) on up to `jobs` threads, and
/// `report(i, result)` on the calling thread for i = 0, 1, ... in order, each as soon as item i
/// is done. Every thread makes its own worker with `make_worker()` (a segmenter with its
/// buffers, say), so work on different items shares nothing. With jobs <= 1 everything runs on
/// the calling thread, one item after another.
///
/// At most 2 * jobs results wait to be reported: a slow item holds the others back rather
/// than letting finished results pile up in memory. `make_worker` and `work` must not throw
/// (put an item's error into its result); `report` may not throw either while threads run.
template <typename MakeWorker, typename Work, typename Report>
void runInOrder(std::size_t count, unsigned jobs, MakeWorker make_worker, Work work, Report report) {
  using Worker = decltype(make_worker());
  using Result = decltype(work(std::declval<Worker&>(), std::size_t{0}));
  if (jobs <= 1 || count <= 1) {
    Worker worker = make_worker();
    for (std::size_t i = 0; i < count; ++i) {
      Result result = work(worker, i);
      report(i, result);
    }
    return;
  }

  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::optional<Result>> finished(count);
  std::size_t next = 0;      // the next item a thread takes
  std::size_t reported = 0;  // items reported so far
  const std::size_t window = 2 * static_cast<std::size_t>(jobs);

  const auto run = [&]() {
    Worker worker = make_worker();
    for (;;) {
      std::size_t item = 0;
      {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return next >= count || next < reported + window; });
        if (next >= count) return;
        item = next++;
      }
      Result result = work(worker, item);
      {
        std::lock_guard<std::mutex> lock(mutex);
        finished[item] = std::move(result);
      }
      changed.notify_all();
    }
  };
  std::vector<std::thread> threads;
  const std::size_t thread_count = std::min(count, static_cast<std::size_t>(jobs));
  threads.reserve(thread_count);
  for (std::size_t t = 0; t < thread_count; ++t) threads.emplace_back(run);

  for (std::size_t i = 0; i < count; ++i) {
    std::optional<Result> result;
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [&] { return finished[i].has_value(); });
      result = std::move(finished[i]);
      finished[i].reset();
    }
    report(i, *result);
    {
      std::lock_guard<std::mutex> lock(mutex);
      reported = i + 1;
    }
    changed.notify_all();
  }
  for (std::thread& thread : threads) thread.join();
}

}  // namespace pcd_segment
