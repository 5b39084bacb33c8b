#pragma once
// The baselines whose parameters can be tuned (PCL's OMPS and RANSAC, Open3D's RANSAC): for
// each, its tunable parameters by name with their defaults, and how to make the method from a
// set of values. The tuner and the --tuned rows both go through this one table.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "method.h"

namespace pcd_compare {

/// A value per parameter name.
using ParameterValues = std::map<std::string, double>;

struct Baseline {
  std::string name;  ///< as in --methods: "omps", "ransac", "open3d_ransac"
  /// Every tunable parameter with its default, in the order the search visits them.
  std::vector<std::pair<std::string, double>> defaults;
  /// A parameter that only stops a sequence of extractions ("min_inliers" of a sequential
  /// RANSAC): a run at its smallest value contains the run at any larger value, planes
  /// numbered in extraction order. Empty when there is none.
  std::string truncation_parameter;
  /// Makes the method from `values` (missing names take their defaults), named `name`.
  /// Throws std::invalid_argument for an unknown name or a value out of range.
  std::function<std::unique_ptr<Method>(const ParameterValues& values, const std::string& name)> make;
};

/// The tunable baselines.
const std::vector<Baseline>& baselines();
/// The baseline called `name`, or nullptr.
const Baseline* findBaseline(const std::string& name);
/// `values` completed with the defaults of `baseline`.
ParameterValues withDefaults(const Baseline& baseline, const ParameterValues& values);
/// "name=value, ..." in the baseline's parameter order.
std::string describeValues(const Baseline& baseline, const ParameterValues& values);

/// Keeps the planes of a sequential extraction (labels 1, 2, ... in extraction order) up to,
/// not including, the first with fewer than `min_inliers` pixels: the labels the same method
/// would have given with that `min_inliers`, when it gave `labels` with a smaller one.
std::vector<std::uint32_t> truncateSequence(const std::vector<std::uint32_t>& labels, double min_inliers);

}  // namespace pcd_compare
