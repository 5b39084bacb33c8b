// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "eval/segmentation_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace floodplane::eval {

namespace {

// A region (ground-truth plane or predicted segment) that passed the size rule.
struct Region {
  std::uint32_t label = 0;
  std::size_t pixels = 0;
  bool classified = false;
  // Where its pixels went, for the reasons of the misses: a plane's pixels with predicted
  // label 0, a segment's pixels on a ground-truth plane (any label but 0, kept or not).
  std::size_t unlabelled = 0;
  std::size_t on_planes = 0;
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
std::vector<Region> keptRegions(const std::map<std::uint32_t, std::size_t>& counts, std::uint32_t min_points,
                                std::unordered_map<std::uint32_t, std::size_t>& index_of) {
  std::vector<Region> regions;
  for (const auto& [label, pixels] : counts) {
    if (pixels >= min_points) {
      index_of.emplace(label, regions.size());
      regions.push_back({label, pixels, false, 0, 0});
    }
  }
  return regions;
}

// O(g, p) for one pair of kept regions.
struct Overlap {
  std::size_t other = 0;  // index of the region on the other side
  std::size_t pixels = 0;
};

// The kept regions of both labellings and their overlaps, both ways, each list by ascending
// index of the other side.
struct Regions {
  std::vector<Region> gt;
  std::vector<Region> segments;
  std::vector<std::vector<Overlap>> overlaps_of_gt;
  std::vector<std::vector<Overlap>> overlaps_of_segment;
};

void checkSizes(const std::vector<std::uint32_t>& ground_truth, const std::vector<std::uint32_t>& predicted,
                const std::vector<std::uint8_t>& valid, const char* function) {
  if (predicted.size() != ground_truth.size() || valid.size() != ground_truth.size()) {
    throw std::invalid_argument(std::string(function) + ": ground_truth, predicted and valid must have one size (got " +
                                std::to_string(ground_truth.size()) + ", " + std::to_string(predicted.size()) + ", " +
                                std::to_string(valid.size()) + ")");
  }
}

Regions keptRegionsAndOverlaps(const std::vector<std::uint32_t>& ground_truth,
                               const std::vector<std::uint32_t>& predicted, const std::vector<std::uint8_t>& valid,
                               std::uint32_t min_points) {
  Regions regions;
  std::unordered_map<std::uint32_t, std::size_t> gt_index;
  std::unordered_map<std::uint32_t, std::size_t> segment_index;
  regions.gt = keptRegions(countLabels(ground_truth, valid), min_points, gt_index);
  regions.segments = keptRegions(countLabels(predicted, valid), min_points, segment_index);

  // Overlaps between kept regions only: ignored regions take part in nothing, but their
  // pixels still count in the sizes |g| and |p| of the kept ones.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> overlap_pixels;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    if (valid[i] == 0) continue;
    const auto g = gt_index.find(ground_truth[i]);
    const auto p = segment_index.find(predicted[i]);
    if (g != gt_index.end() && predicted[i] == 0) ++regions.gt[g->second].unlabelled;
    if (p != segment_index.end() && ground_truth[i] != 0) ++regions.segments[p->second].on_planes;
    if (g != gt_index.end() && p != segment_index.end()) ++overlap_pixels[{g->second, p->second}];
  }
  regions.overlaps_of_gt.resize(regions.gt.size());
  regions.overlaps_of_segment.resize(regions.segments.size());
  for (const auto& [pair, pixels] : overlap_pixels) {
    regions.overlaps_of_gt[pair.first].push_back({pair.second, pixels});
    regions.overlaps_of_segment[pair.second].push_back({pair.first, pixels});
  }
  return regions;
}

// IoU (Table I): the best-matching kept segment of each kept plane, and the two averages.
void scoreIou(const Regions& regions, SegmentationScores& scores) {
  const std::vector<Region>& gt = regions.gt;
  scores.planes.resize(gt.size());
  double iou_sum = 0.0;
  double weighted_sum = 0.0;
  double weight_total = 0.0;
  for (std::size_t g = 0; g < gt.size(); ++g) {
    PlaneScore& plane = scores.planes[g];
    plane.label = gt[g].label;
    plane.pixels = gt[g].pixels;
    for (const Overlap& overlap : regions.overlaps_of_gt[g]) {
      const Region& segment = regions.segments[overlap.other];
      const double intersection = static_cast<double>(overlap.pixels);
      const double united = static_cast<double>(gt[g].pixels + segment.pixels) - intersection;
      const double iou = intersection / united;
      // Strictly greater: ties go to the lower predicted label, so results are reproducible.
      if (iou > plane.iou) {
        plane.iou = iou;
        plane.best_segment = segment.label;
      }
    }
    iou_sum += plane.iou;
    weighted_sum += plane.iou * static_cast<double>(plane.pixels);
    weight_total += static_cast<double>(plane.pixels);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  scores.mean_iou = gt.empty() ? nan : iou_sum / static_cast<double>(gt.size());
  scores.weighted_iou = gt.empty() ? nan : weighted_sum / weight_total;
}

// The Hoover et al. classification, one kind after the other. Each step classifies only
// regions that no earlier step has classified.
class HooverClassifier {
 public:
  HooverClassifier(Regions& regions, double tolerance, SegmentationScores& scores)
      : regions_(regions), tolerance_(tolerance), scores_(scores) {}

  void classify() {
    findCorrectDetections();
    findOverSegmentations();
    findUnderSegmentations();
    const auto unclassified = [](const Region& r) { return !r.classified; };
    scores_.hoover.missed =
        static_cast<std::size_t>(std::count_if(regions_.gt.begin(), regions_.gt.end(), unclassified));
    scores_.hoover.noise =
        static_cast<std::size_t>(std::count_if(regions_.segments.begin(), regions_.segments.end(), unclassified));
  }

 private:
  bool covers(std::size_t overlap, std::size_t size) const {
    return static_cast<double>(overlap) >= tolerance_ * static_cast<double>(size);
  }

  // With T > 0.5 a plane has at most one segment that covers more than T of it, so the pairs
  // found here cannot compete.
  void findCorrectDetections() {
    std::vector<Region>& gt = regions_.gt;
    for (std::size_t g = 0; g < gt.size(); ++g) {
      for (const Overlap& overlap : regions_.overlaps_of_gt[g]) {
        Region& segment = regions_.segments[overlap.other];
        if (!gt[g].classified && !segment.classified && covers(overlap.pixels, gt[g].pixels) &&
            covers(overlap.pixels, segment.pixels)) {
          gt[g].classified = true;
          segment.classified = true;
          scores_.planes[g].hoover = HooverClass::correct;
          ++scores_.hoover.correct;
        }
      }
    }
  }

  // The unclassified regions on the other side of `overlaps` that lie (by T) inside the region
  // of `size` pixels, if there are at least two and together they cover T of it. Taking all
  // candidates gives the largest sum, so if any k >= 2 subset qualifies, this set does.
  std::vector<std::size_t> coveringParts(const std::vector<Overlap>& overlaps, const std::vector<Region>& others,
                                         std::size_t size) const {
    std::vector<std::size_t> parts;
    std::size_t covered = 0;
    for (const Overlap& overlap : overlaps) {
      const Region& other = others[overlap.other];
      if (!other.classified && covers(overlap.pixels, other.pixels)) {
        parts.push_back(overlap.other);
        covered += overlap.pixels;
      }
    }
    return parts.size() >= 2 && covers(covered, size) ? parts : std::vector<std::size_t>();
  }

  // Each unclassified region of `wholes` that at least two unclassified regions of `pieces`
  // split (coveringParts) is classified with its pieces; `found(whole, pieces)` counts it.
  template <typename Found>
  void findSplits(std::vector<Region>& wholes, const std::vector<std::vector<Overlap>>& overlaps_of_whole,
                  std::vector<Region>& pieces, Found found) {
    for (std::size_t w = 0; w < wholes.size(); ++w) {
      if (wholes[w].classified) continue;
      const std::vector<std::size_t> parts = coveringParts(overlaps_of_whole[w], pieces, wholes[w].pixels);
      if (parts.empty()) continue;
      wholes[w].classified = true;
      for (const std::size_t p : parts) pieces[p].classified = true;
      found(w, parts);
    }
  }

  // Over-segmentation of g into p1..pk.
  void findOverSegmentations() {
    findSplits(regions_.gt, regions_.overlaps_of_gt, regions_.segments,
               [this](std::size_t g, const std::vector<std::size_t>&) {
                 scores_.planes[g].hoover = HooverClass::over_segmented;
                 ++scores_.hoover.over;
               });
  }

  // Under-segmentation of g1..gk into p: the mirror image.
  void findUnderSegmentations() {
    findSplits(regions_.segments, regions_.overlaps_of_segment, regions_.gt,
               [this](std::size_t, const std::vector<std::size_t>& planes) {
                 for (const std::size_t g : planes) scores_.planes[g].hoover = HooverClass::under_segmented;
                 ++scores_.hoover.under;
               });
  }

  Regions& regions_;
  double tolerance_;
  SegmentationScores& scores_;
};

double share(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

// Why each plane that is not a correct detection is not (MissReason, in its order), and the
// noise segments, once the Hoover classification is done.
void explainMisses(const Regions& regions, double tolerance, SegmentationScores& scores) {
  for (std::size_t g = 0; g < regions.gt.size(); ++g) {
    PlaneScore& plane = scores.planes[g];
    const Region& truth = regions.gt[g];
    plane.unlabelled_share = share(truth.unlabelled, truth.pixels);
    const Overlap* main = nullptr;  // the first of the largest: the lower label on a tie
    for (const Overlap& overlap : regions.overlaps_of_gt[g]) {
      if (main == nullptr || overlap.pixels > main->pixels) main = &overlap;
    }
    if (main != nullptr) {
      plane.main_segment = regions.segments[main->other].label;
      plane.main_segment_share = share(main->pixels, truth.pixels);
    }
    switch (plane.hoover) {
      case HooverClass::correct:
        plane.miss = MissReason::none;
        continue;
      case HooverClass::over_segmented:
        plane.miss = MissReason::over_segmented;
        continue;
      case HooverClass::under_segmented:
        plane.miss = MissReason::under_segmented;
        continue;
      case HooverClass::missed:
        break;
    }
    if (2 * truth.unlabelled >= truth.pixels) {
      plane.miss = MissReason::no_segment;
    } else if (main == nullptr || 2 * main->pixels < truth.pixels) {
      plane.miss = MissReason::over_segmented;
    } else {
      const Region& segment = regions.segments[main->other];
      // More than (1 - T)|p| on other planes: what is left of p is less than T|p| (as Hoover's
      // tests compare, without rounding 1 - T).
      const std::size_t off_other_planes = segment.pixels - (segment.on_planes - main->pixels);
      plane.miss = static_cast<double>(off_other_planes) < tolerance * static_cast<double>(segment.pixels)
                       ? MissReason::under_segmented
                       : MissReason::iou_below_t;
    }
  }
  for (std::size_t p = 0; p < regions.segments.size(); ++p) {
    const Region& segment = regions.segments[p];
    if (segment.classified) continue;
    NoiseSegment noise;
    noise.label = segment.label;
    noise.pixels = segment.pixels;
    noise.off_plane_share = share(segment.pixels - segment.on_planes, segment.pixels);
    for (const Overlap& overlap : regions.overlaps_of_segment[p]) {
      const std::size_t united = segment.pixels + regions.gt[overlap.other].pixels - overlap.pixels;
      noise.iou = std::max(noise.iou, share(overlap.pixels, united));
    }
    scores.noise.push_back(noise);
  }
}

// The false-plane fraction over the kept segments of `segments` (labels, ascending).
double falsePlaneFraction(const std::vector<std::uint32_t>& ground_truth, const std::vector<std::uint32_t>& predicted,
                          const std::vector<std::uint8_t>& valid, const std::vector<Region>& segments) {
  std::unordered_set<std::uint32_t> kept;
  for (const Region& segment : segments) kept.insert(segment.label);
  std::size_t non_plane = 0;
  std::size_t reported_as_plane = 0;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    if (valid[i] == 0 || ground_truth[i] != 0) continue;
    ++non_plane;
    if (kept.count(predicted[i]) != 0) ++reported_as_plane;
  }
  return non_plane == 0 ? std::numeric_limits<double>::quiet_NaN()
                        : static_cast<double>(reported_as_plane) / static_cast<double>(non_plane);
}

}  // namespace

std::uint32_t defaultMinPoints(std::size_t width, std::size_t height) {
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  return static_cast<std::uint32_t>(std::lround(500.0 * pixels / (640.0 * 480.0)));
}

double falsePlaneFraction(const std::vector<std::uint32_t>& ground_truth, const std::vector<std::uint32_t>& predicted,
                          const std::vector<std::uint8_t>& valid, std::uint32_t min_points) {
  checkSizes(ground_truth, predicted, valid, "falsePlaneFraction");
  std::unordered_map<std::uint32_t, std::size_t> unused_index;
  return falsePlaneFraction(ground_truth, predicted, valid,
                            keptRegions(countLabels(predicted, valid), min_points, unused_index));
}

SegmentationScores evaluateSegmentation(const std::vector<std::uint32_t>& ground_truth,
                                        const std::vector<std::uint32_t>& predicted,
                                        const std::vector<std::uint8_t>& valid, const MetricsOptions& options) {
  checkSizes(ground_truth, predicted, valid, "evaluateSegmentation");
  if (!(options.tolerance > 0.5 && options.tolerance <= 1.0)) {
    throw std::invalid_argument("evaluateSegmentation: tolerance must be in (0.5, 1], got " +
                                std::to_string(options.tolerance));
  }
  Regions regions = keptRegionsAndOverlaps(ground_truth, predicted, valid, options.min_points);
  SegmentationScores scores;
  scores.predicted_segments = regions.segments.size();
  scores.false_plane_fraction = falsePlaneFraction(ground_truth, predicted, valid, regions.segments);
  scoreIou(regions, scores);
  HooverClassifier(regions, options.tolerance, scores).classify();
  explainMisses(regions, options.tolerance, scores);
  return scores;
}

}  // namespace floodplane::eval
