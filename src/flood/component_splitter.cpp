// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "flood/component_splitter.h"

#include <cstddef>

#include "util/row_search.h"

namespace floodplane {

std::vector<std::int32_t> ComponentSplitter::split(std::int32_t* labels, int width, const Run* runs,
                                                   std::size_t run_count, std::int32_t label, std::int32_t& next_label,
                                                   std::size_t smallest_piece) {
  runs_.assign(runs, runs + run_count);
  for (Run& run : runs_) run.set = -1;
  sets_.reset(0);
  set_size_.clear();
  released_ = 0;
  uniteRuns();
  // A segment still in one piece (the common case) needs no second pass.
  const std::size_t roots = sumSizesPerRoot();
  if (roots == 0) return {};
  if (roots == 1 && set_size_[static_cast<std::size_t>(sets_.find(0))] >= smallest_piece) {
    for (Run& run : runs_) run.set = label;
    return {};
  }
  return relabel(labels, width, label, next_label, smallest_piece);
}

void ComponentSplitter::uniteRuns() {
  // Pass 1 over runs, not pixels: each run is united with the runs of the row above it
  // overlaps (4-connectivity: they share a column). A segment is a few long runs per row, so
  // the union-find work is per run.
  std::size_t above_begin = 0, above_end = 0;  // the runs of the row above in runs_
  std::size_t above = 0;
  std::size_t row_begin = 0;
  int current_row = -2;  // the row of the runs from row_begin on
  for (std::size_t r = 0; r < runs_.size(); ++r) {
    Run& run = runs_[r];
    if (run.y != current_row) {
      // The previous row's runs are above this row only if it is the row just above.
      above_begin = run.y == current_row + 1 ? row_begin : r;
      above_end = r;
      above = above_begin;
      current_row = run.y;
      row_begin = r;
    }
    // Runs above that end before this one starts cannot overlap it or any later run.
    while (above < above_end && runs_[above].x_end < run.x_begin) ++above;
    for (std::size_t a = above; a < above_end && runs_[a].x_begin <= run.x_end; ++a) {
      run.set = run.set < 0 ? runs_[a].set : sets_.unite(run.set, runs_[a].set);
    }
    if (run.set < 0) {
      run.set = sets_.add();
      set_size_.push_back(0);
    }
    set_size_[static_cast<std::size_t>(run.set)] += static_cast<std::size_t>(run.x_end - run.x_begin + 1);
  }
}

std::size_t ComponentSplitter::sumSizesPerRoot() {
  std::size_t roots = 0;
  for (std::size_t set = 0; set < set_size_.size(); ++set) {
    const std::int32_t root = sets_.find(static_cast<std::int32_t>(set));
    if (root == static_cast<std::int32_t>(set)) {
      ++roots;
    } else {
      set_size_[static_cast<std::size_t>(root)] += set_size_[set];
    }
  }
  return roots;
}

std::vector<std::int32_t> ComponentSplitter::relabel(std::int32_t* labels, int width, std::int32_t label,
                                                     std::int32_t& next_label, std::size_t smallest_piece) {
  // Pass 2 over the runs: one label per root, in raster order of first appearance; crumbs
  // get 0. Afterwards each run's `set` holds the label its pixels received.
  std::vector<std::int32_t> created;
  final_label_.assign(set_size_.size(), -1);
  bool first = true;
  for (Run& run : runs_) {
    const std::int32_t root = sets_.find(run.set);
    if (final_label_[root] < 0) {
      if (set_size_[static_cast<std::size_t>(root)] < smallest_piece) {
        final_label_[root] = 0;
        released_ += set_size_[static_cast<std::size_t>(root)];
      } else if (first) {
        final_label_[root] = label;
        first = false;
      } else {
        final_label_[root] = next_label++;
        created.push_back(final_label_[root]);
      }
    }
    run.set = final_label_[root];
    if (run.set == label) continue;
    std::int32_t* row = labels + static_cast<std::size_t>(run.y) * width;
    for (int x = run.x_begin; x <= run.x_end; ++x) row[x] = run.set;
  }
  return created;
}

void RunsByLabel::collect(const std::int32_t* labels, int width, int height, const std::vector<bool>& wanted) {
  found_.clear();
  first_.assign(wanted.size() + 1, 0);
  for (int y = 0; y < height; ++y) {
    const std::int32_t* row = labels + static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    forEachRunInRow(row, 0, width - 1, [&](std::int32_t label, int begin, int end) {
      if (label > 0 && static_cast<std::size_t>(label) < wanted.size() && wanted[static_cast<std::size_t>(label)]) {
        found_.push_back({label, {y, begin, end - 1, -1}});
        ++first_[static_cast<std::size_t>(label) + 1];
      }
    });
  }
  // Grouped by label (a counting sort, which keeps the raster order within a label).
  for (std::size_t label = 1; label < first_.size(); ++label) first_[label] += first_[label - 1];
  runs_.resize(found_.size());
  std::vector<std::size_t>& next = scratch_;
  next.assign(first_.begin(), first_.end() - 1);
  for (const auto& [label, run] : found_) runs_[next[static_cast<std::size_t>(label)]++] = run;
}

}  // namespace floodplane
