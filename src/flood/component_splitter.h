// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "util/union_find.h"

namespace floodplane {

/// The relabelling after Eq. 4 (Sec. III-B): when later floods take pixels from a segment,
/// what is left of it may fall apart. This splits the pixels labelled `label`, given as their runs,
/// into 4-connected components with the classic two-pass union-find labelling (as PCL's
/// OrganizedConnectedComponentSegmentation, [16]), over runs of pixels rather than pixels. The first component in
/// raster order keeps `label`; every other one gets the next label from `next_label`, which is advanced. Components of
/// fewer than `smallest_piece` pixels are released (label 0): crumbs that takeovers chipped off a segment are no plane
/// of their own, and as segments they would only slow the merging down (a cluttered Kinect frame has ten crumbs per
/// flood); segmentAndRefine gives their pixels back to a plane they fit. Returns the labels of the new components
/// (empty when the segment is still connected). Scratch memory is reused across calls.
class ComponentSplitter {
 public:
  /// A maximal horizontal run of the split segment's pixels, x_begin..x_end inclusive.
  struct Run {
    int y, x_begin, x_end;
    std::int32_t set;  ///< after split(): the label the run's pixels carry (0: released)
  };

  /// Splits segment `label`, given as `run_count` runs from `runs`: every maximal run of
  /// `label` in the image, in raster order, as RunsByLabel finds them.
  std::vector<std::int32_t> split(std::int32_t* labels, int width, const Run* runs, std::size_t run_count,
                                  std::int32_t label, std::int32_t& next_label, std::size_t smallest_piece = 1);
  /// Pixels released by the last split.
  std::size_t releasedPixels() const { return released_; }

  /// The runs of the last split, in raster order.
  const std::vector<Run>& runs() const { return runs_; }

 private:
  void uniteRuns();               // pass 1: the runs' sets, their sizes per set
  std::size_t sumSizesPerRoot();  // the sizes per root; returns how many roots
  std::vector<std::int32_t> relabel(std::int32_t* labels, int width, std::int32_t label, std::int32_t& next_label,
                                    std::size_t smallest_piece);  // pass 2

  std::vector<Run> runs_;
  std::vector<std::int32_t> final_label_;  // per set root: the label it receives
  std::vector<std::size_t> set_size_;      // pixels per set; per root after pass 1
  std::size_t released_ = 0;
  UnionFind sets_;
};

/// The maximal horizontal runs of the labels of a label image that are `wanted` (wanted[label]),
/// found in one pass over the image and grouped by label, each label's in raster order. The
/// relabelling splits a few hundred overlapping segments of a frame: one pass over the frame
/// instead of a scan of each segment's bounding box.
class RunsByLabel {
 public:
  void collect(const std::int32_t* labels, int width, int height, const std::vector<bool>& wanted);
  /// The runs of `label` (wanted when collected): count(label) of them from runs(label) on.
  const ComponentSplitter::Run* runs(std::int32_t label) const {
    return runs_.data() + first_[static_cast<std::size_t>(label)];
  }
  std::size_t count(std::int32_t label) const {
    return first_[static_cast<std::size_t>(label) + 1] - first_[static_cast<std::size_t>(label)];
  }

 private:
  std::vector<std::pair<std::int32_t, ComponentSplitter::Run>> found_;  // in raster order
  std::vector<ComponentSplitter::Run> runs_;                            // grouped by label
  std::vector<std::size_t> first_;                                      // per label: its first run in runs_
  std::vector<std::size_t> scratch_;
};

}  // namespace floodplane
