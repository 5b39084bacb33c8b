// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "eval/object_metrics.h"

#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace floodplane::eval {

namespace {

void checkOptions(const ObjectMetricsOptions& options) {
  if (options.first_support_label == 0 || options.first_support_label > options.last_support_label ||
      options.last_support_label >= options.first_object_label) {
    throw std::invalid_argument("evaluateObjects: the support's labels must be a range from 1 below the objects'");
  }
  for (const double share : {options.found_iou, options.hold_share}) {
    if (!(share > 0.0 && share <= 1.0)) {
      throw std::invalid_argument("evaluateObjects: found_iou and hold_share must be in (0, 1], got " +
                                  std::to_string(share));
    }
  }
}

}  // namespace

ObjectScores evaluateObjects(const std::vector<std::uint32_t>& ground_truth,
                             const std::vector<std::uint32_t>& predicted, const ObjectMetricsOptions& options) {
  if (ground_truth.size() != predicted.size()) {
    throw std::invalid_argument("evaluateObjects: " + std::to_string(ground_truth.size()) +
                                " ground-truth labels and " + std::to_string(predicted.size()) + " predicted ones");
  }
  checkOptions(options);
  // One pass: the objects' sizes, the output objects' sizes, the overlaps (object -> output
  // object -> pixels, ordered so that ties go to the lower label), the support.
  std::map<std::uint32_t, std::size_t> object_pixels;
  std::unordered_map<std::uint32_t, std::size_t> output_pixels;
  std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>> overlap;
  std::size_t support = 0, support_in_objects = 0;
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    const std::uint32_t g = ground_truth[i], p = predicted[i];
    if (p != 0) ++output_pixels[p];
    if (g >= options.first_object_label) {
      ++object_pixels[g];
      if (p != 0) ++overlap[g][p];
    } else if (g >= options.first_support_label && g <= options.last_support_label) {
      ++support;
      if (p != 0) ++support_in_objects;
    }
  }
  ObjectScores scores;
  scores.output_objects = output_pixels.size();
  for (const auto& [label, pixels] : object_pixels) {
    if (pixels < options.min_object_pixels) continue;
    ObjectScore object;
    object.label = label;
    object.pixels = pixels;
    const auto held = overlap.find(label);
    if (held != overlap.end()) {
      std::size_t best_pixels = 0, holders = 0;
      for (const auto& [output, pixels_in] : held->second) {
        if (pixels_in > best_pixels) {
          best_pixels = pixels_in;
          object.best = output;
        }
        if (static_cast<double>(pixels_in) >= options.hold_share * static_cast<double>(pixels)) ++holders;
      }
      object.iou =
          static_cast<double>(best_pixels) / static_cast<double>(pixels + output_pixels.at(object.best) - best_pixels);
      object.over = holders >= 2;
    }
    object.found = object.iou >= options.found_iou;
    scores.objects.push_back(object);
  }
  for (ObjectScore& object : scores.objects) {
    if (object.best == 0) continue;
    for (const ObjectScore& other : scores.objects) {
      if (other.label == object.label) continue;
      const auto& held = overlap[other.label];
      const auto in_best = held.find(object.best);
      if (in_best != held.end() &&
          static_cast<double>(in_best->second) >= options.hold_share * static_cast<double>(other.pixels)) {
        object.under = true;
        break;
      }
    }
  }
  const double n = static_cast<double>(scores.objects.empty() ? 1 : scores.objects.size());
  double iou_sum = 0.0;
  std::size_t found = 0, over = 0, under = 0;
  for (const ObjectScore& object : scores.objects) {
    iou_sum += object.iou;
    found += object.found ? 1 : 0;
    over += object.over ? 1 : 0;
    under += object.under ? 1 : 0;
  }
  scores.object_iou = scores.objects.empty() ? 0.0 : iou_sum / static_cast<double>(scores.objects.size());
  scores.objects_found = static_cast<double>(found) / n;
  scores.over = static_cast<double>(over) / n;
  scores.under = static_cast<double>(under) / n;
  scores.support_in_objects = static_cast<double>(support_in_objects) / static_cast<double>(support == 0 ? 1 : support);
  return scores;
}

}  // namespace floodplane::eval
