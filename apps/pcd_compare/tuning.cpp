#include "tuning.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "eval/segmentation_metrics.h"
#include "input_cloud.h"
#include "io/atomic_file.h"
#include "io/input_files.h"

namespace pcd_compare {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kTolerance = 0.8;  // Hoover's T; IoU does not depend on it

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A cloud of the tuning subset, with what its metrics need.
struct TuningCloud {
  InputCloud input;
  floodplane::eval::MetricsOptions metrics;
};

// The subset: per sensor model, `per_sensor` clouds evenly spaced in the sorted file list of
// that model (all of them when there are fewer). Clouds without ground truth, or whose ground
// truth keeps no plane, cannot score and are not picked.
std::map<std::string, std::vector<TuningCloud>> loadSubset(const std::string& folder, std::size_t per_sensor) {
  std::map<std::string, std::vector<std::string>> paths;
  for (const floodplane::io::InputFile& file : floodplane::io::expandInputs({folder})) {
    if (!file.error.empty()) throw std::runtime_error(file.error);
    const std::string sensor = sensorModel(file.path);
    if (!sensor.empty()) paths[sensor].push_back(file.path);
  }
  if (paths.empty()) throw std::runtime_error(folder + ": no <scene>.<sensor>.pcd files to tune on");
  std::map<std::string, std::vector<TuningCloud>> subset;
  for (const auto& [sensor, files] : paths) {
    const std::size_t n = std::min(per_sensor, files.size());
    for (std::size_t k = 0; k < n; ++k) {
      const std::string& path = files[k * files.size() / n];
      TuningCloud cloud{loadInputCloud(path), {}};
      if (!cloud.input.ground_truth) throw std::runtime_error(path + ": no ground-truth labels to tune on");
      cloud.metrics.min_points =
          floodplane::eval::defaultMinPoints(cloud.input.cloud->width, cloud.input.cloud->height);
      cloud.metrics.tolerance = kTolerance;
      subset[sensor].push_back(std::move(cloud));
    }
  }
  return subset;
}

// Mean IoU of a set of runs, one per cloud, over the clouds whose ground truth keeps a plane
// (as pcd_compare's mean rows); NaN when none does.
class IouMean {
 public:
  void add(const TuningCloud& cloud, const std::vector<std::uint32_t>& labels) {
    const auto scores =
        floodplane::eval::evaluateSegmentation(*cloud.input.ground_truth, labels, cloud.input.valid, cloud.metrics);
    if (scores.planes.empty()) return;
    sum_ += scores.mean_iou;
    ++count_;
  }
  double mean() const { return count_ > 0 ? sum_ / static_cast<double>(count_) : std::nan(""); }

 private:
  double sum_ = 0.0;
  std::size_t count_ = 0;
};

// One point of the search: a value for every parameter, and its score.
struct Candidate {
  ParameterValues values;
  double mean_iou = -1.0;
};

// The search for one baseline on one sensor model's clouds.
class SensorSearch {
 public:
  SensorSearch(const Baseline& baseline, const std::map<std::string, std::vector<double>>& grid,
               const std::vector<TuningCloud>& clouds, std::string label, std::ostream& progress)
      : baseline_(baseline), grid_(grid), clouds_(clouds), label_(std::move(label)), progress_(progress) {}

  // Coordinate descent from the defaults: each parameter in turn takes the grid value that
  // scores best with the others held; a pass that changes nothing ends the search. A change
  // must gain more than 1e-9 (ties keep the current value, so the defaults win ties).
  void run(int passes) {
    const auto start = Clock::now();
    defaults_ = withDefaults(baseline_, {});
    best_ = evaluate(defaults_);
    default_score_ = scores_.at(describeValues(baseline_, defaults_));
    for (int pass = 0; pass < passes; ++pass) {
      bool changed = false;
      for (const auto& [name, value] : baseline_.defaults) {
        (void)value;
        if (name == baseline_.truncation_parameter || grid_.count(name) == 0) continue;
        for (const double candidate_value : grid_.at(name)) {
          ParameterValues values = best_.values;
          values[name] = candidate_value;
          const Candidate candidate = evaluate(values);
          if (candidate.mean_iou > best_.mean_iou + 1e-9) {
            best_ = candidate;
            changed = true;
          }
        }
      }
      if (!changed) break;
    }
    seconds_ = secondsSince(start);
  }

  nlohmann::json json() const {
    nlohmann::json names = nlohmann::json::array();
    for (const TuningCloud& cloud : clouds_) names.push_back(cloud.input.name);
    return {{"parameters", best_.values},
            {"mean_iou", best_.mean_iou},
            {"default_mean_iou", default_score_},
            {"clouds", names},
            {"settings_evaluated", cache_.size()},
            {"method_runs", runs_},
            {"seconds", seconds_}};
  }

 private:
  // The truncation parameter's values to score from each run: its grid values and, when not
  // among them, the default.
  std::vector<double> truncationValues(const ParameterValues& values) const {
    std::set<double> list = {values.at(baseline_.truncation_parameter)};
    const auto grid_values = grid_.find(baseline_.truncation_parameter);
    if (grid_values != grid_.end()) list.insert(grid_values->second.begin(), grid_values->second.end());
    return {list.begin(), list.end()};
  }

  // The best candidate among `values` and, for a sequential method, the same with every
  // truncation value (scored from one run at the smallest). Cached by the values it ran with.
  Candidate evaluate(const ParameterValues& values) {
    ParameterValues run_values = values;
    std::vector<double> truncations;
    if (!baseline_.truncation_parameter.empty()) {
      truncations = truncationValues(values);
      run_values[baseline_.truncation_parameter] = truncations.front();
    }
    const std::string key = describeValues(baseline_, run_values);
    const auto cached = cache_.find(key);
    if (cached != cache_.end()) return cached->second;

    const auto start = Clock::now();
    std::unique_ptr<Method> method = baseline_.make(run_values, baseline_.name);
    std::vector<IouMean> means(std::max<std::size_t>(truncations.size(), 1));
    for (const TuningCloud& cloud : clouds_) {
      const MethodRun run = method->run(cloud.input.cloud);
      ++runs_;
      if (truncations.empty()) {
        means[0].add(cloud, run.labels);
      } else {
        for (std::size_t k = 0; k < truncations.size(); ++k) {
          means[k].add(cloud, truncateSequence(run.labels, truncations[k]));
        }
      }
    }
    Candidate best{values, -1.0};
    for (std::size_t k = 0; k < means.size(); ++k) {
      ParameterValues scored = values;
      if (!truncations.empty()) scored[baseline_.truncation_parameter] = truncations[k];
      const double score = means[k].mean();
      scores_[describeValues(baseline_, scored)] = score;
      // The values asked for win ties against other truncation values.
      const bool asked = truncations.empty() || truncations[k] == values.at(baseline_.truncation_parameter);
      if (score > best.mean_iou + 1e-9 || (asked && std::abs(score - best.mean_iou) <= 1e-9)) {
        best = {scored, score};
      }
    }
    progress_ << "pcd_compare: tune " << label_ << " #" << cache_.size() + 1 << " " << describeValues(baseline_, values)
              << ": mean IoU " << best.mean_iou;
    if (truncations.size() > 1) {
      progress_ << " at " << baseline_.truncation_parameter << "=" << best.values.at(baseline_.truncation_parameter)
                << " (all " << truncations.size() << " values from one run)";
    }
    progress_ << ", " << secondsSince(start) << " s\n" << std::flush;
    cache_.emplace(key, best);
    return best;
  }

  const Baseline& baseline_;
  const std::map<std::string, std::vector<double>>& grid_;
  const std::vector<TuningCloud>& clouds_;
  std::string label_;
  std::ostream& progress_;
  ParameterValues defaults_;
  Candidate best_;
  double default_score_ = 0.0;
  std::map<std::string, Candidate> cache_;  // by the values a run was made with
  std::map<std::string, double> scores_;    // by every set of values scored
  std::size_t runs_ = 0;
  double seconds_ = 0.0;
};

void checkGrid(const Grid& grid) {
  for (const auto& [method, parameters] : grid) {
    const Baseline* baseline = findBaseline(method);
    if (baseline == nullptr) throw std::runtime_error("no tunable baseline '" + method + "'");
    for (const auto& [name, values] : parameters) {
      if (values.empty()) throw std::runtime_error(method + "." + name + ": no values");
      for (const double value : values) {
        try {
          baseline->make({{name, value}}, method);
        } catch (const std::invalid_argument& error) {
          throw std::runtime_error(method + ": " + error.what());
        }
      }
    }
  }
}

}  // namespace

Grid defaultGrid() {
  // Each list brackets the default by a factor of 2-4 on both sides; the distances reach 5 mm,
  // five times the scanner's noise at 1 m (a sequential RANSAC below that cuts noisy Kinect
  // planes into hundreds of slices, and one run takes minutes).
  const std::vector<double> ransac_distance = {0.005, 0.01, 0.02, 0.04};
  const std::vector<double> ransac_min_inliers = {100, 300, 1000, 3000};
  return {{"omps",
           {{"angular_threshold", {0.01, 0.02, 0.04, 0.09, 0.15, 0.25}},
            {"distance_threshold", {0.002, 0.005, 0.01, 0.02, 0.04, 0.08, 0.16}},
            {"normal_smoothing_size", {2, 4, 6, 10, 15, 20}},
            {"max_depth_change_factor", {0.005, 0.01, 0.02, 0.05, 0.1, 0.2}},
            {"maximum_curvature", {0.001, 0.003, 0.01, 0.03, 0.1, 0.3}},
            {"min_inliers", {20, 50, 200, 800}}}},
          {"ransac", {{"distance_threshold", ransac_distance}, {"min_inliers", ransac_min_inliers}}},
          {"open3d_ransac", {{"distance_threshold", ransac_distance}, {"min_inliers", ransac_min_inliers}}}};
}

Grid readGrid(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the grid file");
  Grid grid;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& [method, parameters] : json.items()) {
      for (const auto& [name, values] : parameters.items()) {
        grid[method][name] = values.get<std::vector<double>>();
      }
    }
    checkGrid(grid);
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  if (grid.empty()) throw std::runtime_error(path + ": the grid names no baseline");
  return grid;
}

// The methods of an earlier result file at `path` (kept for the baselines not tuned now), or
// an empty object when there is none or it cannot be parsed.
nlohmann::json earlierMethods(const std::string& path) {
  std::ifstream in(path);
  if (!in) return nlohmann::json::object();
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    return json.at("methods").is_object() ? json.at("methods") : nlohmann::json::object();
  } catch (const std::exception&) {
    return nlohmann::json::object();
  }
}

void tuneBaselines(const TuningOptions& options, std::ostream& progress) {
  checkGrid(options.grid);
  const auto subset = loadSubset(options.folder, options.clouds_per_sensor);
  nlohmann::json result = {{"description",
                            "Baseline parameters tuned by pcd_compare --tune: per method and sensor model, the grid "
                            "values with the highest mean IoU (metrics.md) on the clouds listed, by coordinate descent "
                            "from the defaults (one parameter at a time over its grid values, the others held; passes "
                            "until nothing changes; ties keep the current value). The truncation parameter of a "
                            "sequential RANSAC (min_inliers) is scored for every grid value from one run at the "
                            "smallest. A run of --tune replaces the methods it tunes and keeps the others."},
                           {"methods", nlohmann::json::object()}};
  for (const auto& [method, parameters] : options.grid) {
    const auto start = Clock::now();
    const Baseline& baseline = *findBaseline(method);
    nlohmann::json entry = {{"tuning_folder", options.folder},
                            {"clouds_per_sensor", options.clouds_per_sensor},
                            {"passes_at_most", options.passes},
                            {"grid", parameters},
                            {"default", withDefaults(baseline, {})}};
    for (const auto& [sensor, clouds] : subset) {
      SensorSearch search(baseline, parameters, clouds, method + " [" + sensor + "]", progress);
      search.run(options.passes);
      entry["by_sensor"][sensor] = search.json();
    }
    entry["seconds"] = secondsSince(start);
    result["methods"][method] = entry;
  }
  // Read last, so that tuning runs of different methods may overlap.
  nlohmann::json methods = earlierMethods(options.output_file);
  methods.update(result["methods"]);
  result["methods"] = methods;
  floodplane::io::writeBytesAtomically(options.output_file, result.dump(2) + "\n");
}

TunedValues readTunedValues(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the tuned parameters (run pcd_compare --tune first)");
  TunedValues tuned;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& [method, entry] : json.at("methods").items()) {
      const Baseline* baseline = findBaseline(method);
      if (baseline == nullptr) throw std::runtime_error("unknown method '" + method + "'");
      for (const auto& [sensor, winner] : entry.at("by_sensor").items()) {
        const auto values = winner.at("parameters").get<ParameterValues>();
        baseline->make(values, method);  // checks the names and values
        tuned.by_method_and_sensor[method][sensor] = values;
      }
    }
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  return tuned;
}

}  // namespace pcd_compare
