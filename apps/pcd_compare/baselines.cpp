// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The tunable baselines of method.h: one table of their parameters, and the tuned values' file.

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "baselines/omps_run.h"
#include "method.h"

namespace pcd_compare {

namespace {

using Settings = floodplane::baselines::OmpsSettings;

// A tunable baseline: every parameter with its default, in the order they are described, and
// the method's factory.
struct Baseline {
  std::vector<std::pair<std::string, double>> defaults;
  std::unique_ptr<Method> (*make)(const ParameterValues& values, const std::string& name);
};

// PCL's and Open3D's sequential RANSAC (extractPlanesInTurn, method.h).
const std::vector<std::pair<std::string, double>> kSequentialRansac = {
    {"distance_threshold", 0.01},  // inlier distance from the plane [m]
    {"min_inliers", 100}};

// OMPS's defaults are the paper's Sec. IV settings (baselines/omps_run.h) and PCL's default maximum
// curvature.
const std::map<std::string, Baseline> kBaselines = {
    {"omps",
     {{{"angular_threshold", Settings::angular_threshold},          // [rad]
       {"distance_threshold", Settings::distance_threshold},        // [m]
       {"normal_smoothing_size", Settings::normal_smoothing_size},  // [pixels]
       // Depth change that ends a normal's smoothing area, as a factor of the depth [1/m].
       {"max_depth_change_factor", Settings::max_depth_change_factor},
       {"maximum_curvature", 0.001},  // of a region's points
       {"min_inliers", Settings::min_inliers}},
      makeOmpsMethod}},
    {"ransac", {kSequentialRansac, makeRansacMethod}},
    {"open3d_ransac", {kSequentialRansac, makeOpen3dRansacMethod}}};

// `values` completed with the defaults and checked: unknown baselines and names rejected, every
// value a finite positive number, the one count (min_inliers) also whole.
ParameterValues complete(const std::string& baseline, const ParameterValues& values) {
  const auto known = kBaselines.find(baseline);
  if (known == kBaselines.end()) throw std::invalid_argument("'" + baseline + "' is not a tunable baseline");
  ParameterValues all(known->second.defaults.begin(), known->second.defaults.end());
  for (const auto& [name, value] : values) {
    if (all.count(name) == 0) throw std::invalid_argument(baseline + " has no parameter '" + name + "'");
    all[name] = value;
  }
  for (const auto& [name, value] : all) {
    if (!std::isfinite(value) || value <= 0.0) {
      throw std::invalid_argument(name + " must be a positive number, got " + std::to_string(value));
    }
    if (name == "min_inliers" && (value != std::floor(value) || value > 1e9)) {
      throw std::invalid_argument(name + " must be a whole number, got " + std::to_string(value));
    }
  }
  return all;
}

}  // namespace

std::unique_ptr<Method> makeBaseline(const std::string& baseline, const ParameterValues& values,
                                     const std::string& name) {
  const ParameterValues all = complete(baseline, values);
  return kBaselines.at(baseline).make(all, name);
}

std::string describeValues(const std::string& baseline, const ParameterValues& values) {
  const ParameterValues all = complete(baseline, values);
  std::ostringstream text;
  for (const auto& entry : kBaselines.at(baseline).defaults) {
    text << (text.tellp() > 0 ? ", " : "") << entry.first << "=" << all.at(entry.first);
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
        complete(baseline, values);  // checks the names and values
        tuned[baseline][sensor] = values;
      }
    }
  } catch (const std::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  return tuned;
}

}  // namespace pcd_compare
