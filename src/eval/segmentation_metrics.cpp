#include "eval/segmentation_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace floodplane::eval {

namespace {

// A region (ground-truth plane or predicted segment) that passed the size rule.
struct Region {
  std::uint32_t label = 0;
  std::size_t pixels = 0;
  bool classified = false;
};

// Pixel counts per label over the valid pixels, for labels > 0.
std::map<std::uint32_t, std::size_t> countLabels(const std::vector<std::uint32_t>& labels,
                                                 const std::vector<std::uint8_t>& valid) {
  std::map<std::uint32_t, std::size_t> counts;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (valid[i] != 0 && labels[i] != 0) {
      ++counts[labels[i]];
    }
  }
  return counts;
}

// The regions at least `min_points` large, by ascending label, and each kept label's index.
std::vector<Region> keptRegions(const std::map<std::uint32_t, std::size_t>& counts,
                                std::uint32_t min_points,
                                std::unordered_map<std::uint32_t, std::size_t>& index_of) {
  std::vector<Region> regions;
  for (const auto& [label, pixels] : counts) {
    if (pixels >= min_points) {
      index_of.emplace(label, regions.size());
      regions.push_back({label, pixels, false});
    }
  }
  return regions;
}

// O(g, p) for one pair of kept regions.
struct Overlap {
  std::size_t other = 0;  // index of the region on the other side
  std::size_t pixels = 0;
};

}  // namespace

std::uint32_t defaultMinPoints(std::size_t width, std::size_t height) {
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  return static_cast<std::uint32_t>(std::lround(500.0 * pixels / (640.0 * 480.0)));
}

SegmentationScores evaluateSegmentation(const std::vector<std::uint32_t>& ground_truth,
                                        const std::vector<std::uint32_t>& predicted,
                                        const std::vector<std::uint8_t>& valid,
                                        const MetricsOptions& options) {
  if (predicted.size() != ground_truth.size() || valid.size() != ground_truth.size()) {
    throw std::invalid_argument(
        "evaluateSegmentation: ground_truth, predicted and valid must have one size (got " +
        std::to_string(ground_truth.size()) + ", " + std::to_string(predicted.size()) + ", " +
        std::to_string(valid.size()) + ")");
  }
  if (!(options.tolerance > 0.5 && options.tolerance <= 1.0)) {
    throw std::invalid_argument("evaluateSegmentation: tolerance must be in (0.5, 1], got " +
                                std::to_string(options.tolerance));
  }
  const double tolerance = options.tolerance;

  std::unordered_map<std::uint32_t, std::size_t> gt_index;
  std::unordered_map<std::uint32_t, std::size_t> segment_index;
  std::vector<Region> gt =
      keptRegions(countLabels(ground_truth, valid), options.min_points, gt_index);
  std::vector<Region> segments =
      keptRegions(countLabels(predicted, valid), options.min_points, segment_index);

  // Overlaps between kept regions only: ignored regions take part in nothing, but their
  // pixels still count in the sizes |g| and |p| of the kept ones.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> overlap_pixels;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    if (valid[i] == 0) {
      continue;
    }
    const auto g = gt_index.find(ground_truth[i]);
    const auto p = segment_index.find(predicted[i]);
    if (g != gt_index.end() && p != segment_index.end()) {
      ++overlap_pixels[{g->second, p->second}];
    }
  }
  // Both directions, each list by ascending index of the other side (the map's order).
  std::vector<std::vector<Overlap>> overlaps_of_gt(gt.size());
  std::vector<std::vector<Overlap>> overlaps_of_segment(segments.size());
  for (const auto& [pair, pixels] : overlap_pixels) {
    overlaps_of_gt[pair.first].push_back({pair.second, pixels});
    overlaps_of_segment[pair.second].push_back({pair.first, pixels});
  }

  SegmentationScores scores;
  scores.predicted_segments = segments.size();
  scores.planes.resize(gt.size());

  // IoU (Table I): the best-matching kept segment of each kept plane.
  double iou_sum = 0.0;
  double weighted_sum = 0.0;
  double weight_total = 0.0;
  for (std::size_t g = 0; g < gt.size(); ++g) {
    PlaneScore& plane = scores.planes[g];
    plane.label = gt[g].label;
    plane.pixels = gt[g].pixels;
    for (const Overlap& overlap : overlaps_of_gt[g]) {
      const double intersection = static_cast<double>(overlap.pixels);
      const double united = static_cast<double>(gt[g].pixels + segments[overlap.other].pixels) -
                            intersection;
      const double iou = intersection / united;
      // Strictly greater: ties go to the lower predicted label, so results are reproducible.
      if (iou > plane.iou) {
        plane.iou = iou;
        plane.best_segment = segments[overlap.other].label;
      }
    }
    iou_sum += plane.iou;
    weighted_sum += plane.iou * static_cast<double>(plane.pixels);
    weight_total += static_cast<double>(plane.pixels);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  scores.mean_iou = gt.empty() ? nan : iou_sum / static_cast<double>(gt.size());
  scores.weighted_iou = gt.empty() ? nan : weighted_sum / weight_total;

  // Hoover: correct detections first. With T > 0.5 a plane has at most one segment that
  // covers more than T of it, so the pairs found here cannot compete.
  const auto covers = [tolerance](std::size_t overlap, std::size_t size) {
    return static_cast<double>(overlap) >= tolerance * static_cast<double>(size);
  };
  for (std::size_t g = 0; g < gt.size(); ++g) {
    for (const Overlap& overlap : overlaps_of_gt[g]) {
      Region& segment = segments[overlap.other];
      if (!gt[g].classified && !segment.classified && covers(overlap.pixels, gt[g].pixels) &&
          covers(overlap.pixels, segment.pixels)) {
        gt[g].classified = true;
        segment.classified = true;
        scores.planes[g].hoover = HooverClass::correct;
        ++scores.hoover.correct;
      }
    }
  }

  // Over-segmentation of g into p1..pk: every unclassified segment lying (by T) inside g is a
  // candidate; taking all of them gives the largest sum, so if any k >= 2 subset qualifies,
  // this set does.
  for (std::size_t g = 0; g < gt.size(); ++g) {
    if (gt[g].classified) {
      continue;
    }
    std::vector<std::size_t> parts;
    std::size_t covered = 0;
    for (const Overlap& overlap : overlaps_of_gt[g]) {
      const Region& segment = segments[overlap.other];
      if (!segment.classified && covers(overlap.pixels, segment.pixels)) {
        parts.push_back(overlap.other);
        covered += overlap.pixels;
      }
    }
    if (parts.size() >= 2 && covers(covered, gt[g].pixels)) {
      gt[g].classified = true;
      for (const std::size_t p : parts) {
        segments[p].classified = true;
      }
      scores.planes[g].hoover = HooverClass::over_segmented;
      ++scores.hoover.over;
    }
  }

  // Under-segmentation of g1..gk into p: the mirror image.
  for (std::size_t p = 0; p < segments.size(); ++p) {
    if (segments[p].classified) {
      continue;
    }
    std::vector<std::size_t> parts;
    std::size_t covered = 0;
    for (const Overlap& overlap : overlaps_of_segment[p]) {
      const Region& plane = gt[overlap.other];
      if (!plane.classified && covers(overlap.pixels, plane.pixels)) {
        parts.push_back(overlap.other);
        covered += overlap.pixels;
      }
    }
    if (parts.size() >= 2 && covers(covered, segments[p].pixels)) {
      segments[p].classified = true;
      for (const std::size_t g : parts) {
        gt[g].classified = true;
        scores.planes[g].hoover = HooverClass::under_segmented;
      }
      ++scores.hoover.under;
    }
  }

  scores.hoover.missed = static_cast<std::size_t>(
      std::count_if(gt.begin(), gt.end(), [](const Region& r) { return !r.classified; }));
  scores.hoover.noise = static_cast<std::size_t>(std::count_if(
      segments.begin(), segments.end(), [](const Region& r) { return !r.classified; }));
  return scores;
}

}  // namespace floodplane::eval
