// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "frame_segmenter.h"

#include "cloud_points.h"

namespace floodplane::conversion {

std::optional<double> lengthOrDerived(double metres) {
  if (metres > 0.0) return metres;
  return std::nullopt;
}

FrameSegmenter::FrameSegmenter(const SegmentationSettings& settings)
    : settings_(settings), segmenter_(settings.params) {}

void FrameSegmenter::setSettings(const SegmentationSettings& settings) {
  segmenter_.setParams(settings.params);  // throws before anything changes
  if (settings.tracking && !settings_.tracking) tracker_.reset();
  settings_ = settings;
}

const Segmentation& FrameSegmenter::segment(const PointGrid& grid) {
  const Segmentation* segmentation = &empty_;
  if (hasFinitePoint(grid)) {
    Segmenter::Options options;
    options.head_start = settings_.head_start;
    segmentation = &segmenter_.segment(grid, options);
  } else {
    empty_.width = grid.width;
    empty_.height = grid.height;
    empty_.labels.assign(grid.size(), 0);
  }
  track_ids_.clear();
  if (settings_.tracking) track_ids_ = tracker_.update(*segmentation);
  return *segmentation;
}

}  // namespace floodplane::conversion
