#pragma once
// The side-by-side picture of one scene: ground truth | ransac | omps | floodplane.

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/rgb_image.h"

namespace pcd_compare {

struct Panel {
  std::string title;
  /// Row-major labels to colour with floodplane::io::labelColor.
  std::vector<std::uint32_t> colour_labels;
  /// The method's own labels, one segment each (the 3-D panels draw a normal per segment);
  /// empty when they are the colour labels (the ground truth).
  std::vector<std::uint32_t> segment_labels;
};

/// Labels that give `predicted` colours comparable with the ground truth's. Separate
/// segmentations number their planes arbitrarily, so coloured by their own labels the same
/// wall would get a different colour in every panel. Instead each predicted segment takes
/// the label of the ground-truth plane it overlaps most (over valid pixels), and segments on
/// no plane keep their own label, shifted past any plausible ground-truth label so that they
/// do not borrow a plane's colour. Label 0 stays 0. Without ground truth (empty vector) the
/// labels are returned as they are.
std::vector<std::uint32_t> coloursMatchedToGroundTruth(const std::vector<std::uint32_t>& predicted,
                                                       const std::vector<std::uint32_t>& ground_truth,
                                                       const std::vector<std::uint8_t>& valid);

/// The panels side by side, each width x height with its title in a strip above.
floodplane::io::RgbImage comparisonImage(const std::vector<Panel>& panels, std::size_t width, std::size_t height);

/// Images of one size side by side, each with its title in a strip above (the layout of
/// comparisonImage; the titles drawn by cairo in a sans font). Throws std::invalid_argument if
/// there are none or their sizes differ, std::runtime_error if cairo cannot draw the titles.
floodplane::io::RgbImage titledImages(const std::vector<std::pair<std::string, floodplane::io::RgbImage>>& images);

}  // namespace pcd_compare
