// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs the items of a batch on several threads and reports their results one at a time in
// item order, so that a parallel run prints, and fails, exactly as a serial one. The ordering
// and the bound on waiting results are TBB's parallel_pipeline: a parallel filter does the
// work, a serial_in_order filter the reports.

#include <oneapi/tbb/enumerable_thread_specific.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_pipeline.h>
#include <oneapi/tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <thread>
#include <utility>

namespace pcd_segment {

/// The number of threads `-j` means by default: one per core the machine reports, at least 1.
inline unsigned defaultJobs() { return std::max(1u, std::thread::hardware_concurrency()); }

/// Calls `work(worker, i)` for every i in [0, count), up to `jobs` items at once on as many
/// threads (more than the machine's cores if asked: -j means items at once), and
/// `report(i, result)` for i = 0, 1, ... in order, one at a time, each as soon as item i and
/// those before it are done. Every thread that works makes its own worker with
/// `make_worker()` (a segmenter with its buffers, say) the first time, so work on different
/// items shares nothing. With jobs <= 1 everything runs on the calling thread, one item after
/// another; otherwise the calling thread takes part and reports may run on any of the threads.
///
/// At most 2 * jobs items are under way (being worked on, or done and waiting for their
/// report): a slow item holds the others back rather than letting finished results pile up in
/// memory. Put an item's error into its result: an exception from `make_worker`, `work` or
/// `report` stops the batch and propagates.
template <typename MakeWorker, typename Work, typename Report>
void runInOrder(std::size_t count, unsigned jobs, MakeWorker make_worker, Work work, Report report) {
  using Worker = decltype(make_worker());
  using Result = decltype(work(std::declval<Worker&>(), std::size_t{0}));
  using Done = std::pair<std::size_t, Result>;
  if (jobs <= 1 || count <= 1) {
    Worker worker = make_worker();
    for (std::size_t i = 0; i < count; ++i) {
      Result result = work(worker, i);
      report(i, result);
    }
    return;
  }

  // TBB sizes its thread pool to the cores; -j asks for `jobs` threads whatever their number.
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, jobs);
  tbb::task_arena arena(static_cast<int>(jobs));
  tbb::enumerable_thread_specific<Worker> workers([&make_worker] { return make_worker(); });
  std::size_t next = 0;
  const auto items = tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                                         [&next, count](tbb::flow_control& control) {
                                                           if (next == count) {
                                                             control.stop();
                                                             return count;
                                                           }
                                                           return next++;
                                                         });
  const auto working = tbb::make_filter<std::size_t, Done>(
      tbb::filter_mode::parallel, [&](std::size_t i) { return Done(i, work(workers.local(), i)); });
  const auto reporting = tbb::make_filter<Done, void>(tbb::filter_mode::serial_in_order,
                                                      [&report](Done done) { report(done.first, done.second); });
  arena.execute([&] { tbb::parallel_pipeline(2 * static_cast<std::size_t>(jobs), items & working & reporting); });
}

}  // namespace pcd_segment
