#include "baselines.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pcd_compare {

namespace {

// Every tunable parameter of a baseline with its default, in the order they are described.
std::vector<std::pair<std::string, double>> defaults(const std::string& baseline) {
  if (baseline == "omps") {
    const OmpsParameters omps;
    return {{"angular_threshold", omps.angular_threshold},
            {"distance_threshold", omps.distance_threshold},
            {"normal_smoothing_size", omps.normal_smoothing_size},
            {"max_depth_change_factor", omps.max_depth_change_factor},
            {"maximum_curvature", omps.maximum_curvature},
            {"min_inliers", static_cast<double>(omps.min_inliers)}};
  }
  if (baseline == "ransac" || baseline == "open3d_ransac") {
    const SequentialRansacParameters ransac;
    return {{"distance_threshold", ransac.distance_threshold},
            {"min_inliers", static_cast<double>(ransac.min_inliers)}};
  }
  return {};
}

// `values` completed with the defaults; unknown names rejected.
ParameterValues complete(const std::string& baseline, const ParameterValues& values) {
  const auto known = defaults(baseline);
  if (known.empty()) throw std::invalid_argument("'" + baseline + "' is not a tunable baseline");
  for (const auto& entry : values) {
    if (std::none_of(known.begin(), known.end(), [&entry](const auto& d) { return d.first == entry.first; })) {
      throw std::invalid_argument(baseline + " has no parameter '" + entry.first + "'");
    }
  }
  ParameterValues all = values;
  for (const auto& [name, value] : known) all.emplace(name, value);
  return all;
}

// Every value must be a finite positive number; counts must also be whole.
double positive(const ParameterValues& values, const std::string& name) {
  const double value = values.at(name);
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(name + " must be a positive number, got " + std::to_string(value));
  }
  return value;
}

std::size_t count(const ParameterValues& values, const std::string& name) {
  const double value = positive(values, name);
  if (value != std::floor(value) || value > 1e9) {
    throw std::invalid_argument(name + " must be a whole number, got " + std::to_string(value));
  }
  return static_cast<std::size_t>(value);
}

}  // namespace

bool isTunable(const std::string& baseline) { return !defaults(baseline).empty(); }

std::unique_ptr<Method> makeBaseline(const std::string& baseline, const ParameterValues& values,
                                     const std::string& name) {
  const ParameterValues all = complete(baseline, values);
  if (baseline == "omps") {
    OmpsParameters omps;
    omps.angular_threshold = positive(all, "angular_threshold");
    omps.distance_threshold = positive(all, "distance_threshold");
    omps.normal_smoothing_size = positive(all, "normal_smoothing_size");
    omps.max_depth_change_factor = positive(all, "max_depth_change_factor");
    omps.maximum_curvature = positive(all, "maximum_curvature");
    omps.min_inliers = count(all, "min_inliers");
    return makeOmpsMethod(omps, name);
  }
  SequentialRansacParameters ransac;
  ransac.distance_threshold = positive(all, "distance_threshold");
  ransac.min_inliers = count(all, "min_inliers");
  return baseline == "ransac" ? makeRansacMethod(ransac, name) : makeOpen3dRansacMethod(ransac, name);
}

std::string describeValues(const std::string& baseline, const ParameterValues& values) {
  const ParameterValues all = complete(baseline, values);
  std::ostringstream text;
  for (const auto& [name, value] : defaults(baseline)) {
    (void)value;
    text << (text.tellp() > 0 ? ", " : "") << name << "=" << all.at(name);
  }
  return text.str();
}

TunedValues readTunedValues(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the tuned parameters (bench/tune_baselines.py writes them)");
  TunedValues tuned;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    for (const auto& [baseline, entry] : json.at("methods").items()) {
      for (const auto& [sensor, winner] : entry.at("by_sensor").items()) {
        const auto values = winner.at("parameters").get<ParameterValues>();
        makeBaseline(baseline, values, baseline);  // checks the names and values
        tuned[baseline][sensor] = values;
      }
    }
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  return tuned;
}

}  // namespace pcd_compare
