#pragma once
// The results of a comparison and their three renderings: Markdown (stdout), CSV and JSON.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "eval/segmentation_metrics.h"
#include "floodplane/segmenter.h"

namespace pcd_compare {

struct Timing {
  double median_ms = 0.0;
  double min_ms = 0.0;
  /// Medians of the method's named parts (OMPS: "normals"). [ms]
  std::vector<std::pair<std::string, double>> parts_median_ms;
};

struct MethodResult {
  std::string method;
  Timing timing;
  std::size_t planes = 0;  ///< distinct non-zero labels the method gave
  /// Against the ground truth, when the file has one.
  std::optional<floodplane::eval::SegmentationScores> scores;
};

/// floodplane's phases (Fig. 5, and the preparation before it) in call order: each one's name
/// in the JSON and its member of PhaseTimes.
const std::vector<std::pair<const char*, double floodplane::PhaseTimes::*>>& phaseMembers();

struct PhaseResult {
  floodplane::PhaseTimes median;  ///< per phase, the median over the timed runs [ms]
  double call_median_ms = 0.0;    ///< the whole call with the phase timer on [ms]
};

struct SceneResult {
  std::string name;
  std::string path;
  /// The sensor model named in the file name (<scene>.<sensor>.pcd), empty when none is:
  /// scenes with one are also averaged per sensor model.
  std::string sensor;
  std::size_t width = 0;
  std::size_t height = 0;
  bool has_ground_truth = false;
  std::uint32_t min_points = 0;       ///< the metrics' size rule at this resolution
  std::vector<MethodResult> methods;  ///< in --methods order
  /// floodplane at sub-sampling 1, 2, 4, 8 (--resolutions), with the factor.
  std::vector<std::pair<int, MethodResult>> resolutions;
  std::optional<PhaseResult> phases;  ///< --phases
};

struct Report {
  /// Printed first and stored in the JSON: (key, value) in order.
  std::vector<std::pair<std::string, std::string>> configuration;
  std::vector<SceneResult> scenes;
  std::vector<std::string> failed;  ///< files that could not be compared
};

/// The tables: the means per method (over every file, then one table per sensor model), the
/// mean IoU per file and method, one row per file and method; then the sub-sampling and phase
/// tables when they were measured.
std::string markdownTables(const Report& report);
/// The configuration as a Markdown list.
std::string markdownConfiguration(const Report& report);
/// One line per scene and method (and sub-sampling factor); no mean rows.
std::string csvReport(const Report& report);
/// Everything, including per-plane IoU; NaN as null.
std::string jsonReport(const Report& report);

}  // namespace pcd_compare
