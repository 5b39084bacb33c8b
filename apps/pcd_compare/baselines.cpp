#include "baselines.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace pcd_compare {

namespace {

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

void rejectUnknown(const Baseline& baseline, const ParameterValues& values) {
  for (const auto& [name, value] : values) {
    (void)value;
    const bool known = std::any_of(baseline.defaults.begin(), baseline.defaults.end(),
                                   [&name](const auto& entry) { return entry.first == name; });
    if (!known) throw std::invalid_argument(baseline.name + " has no parameter '" + name + "'");
  }
}

SequentialRansacParameters ransacParameters(const ParameterValues& values) {
  SequentialRansacParameters parameters;
  parameters.distance_threshold = positive(values, "distance_threshold");
  parameters.min_inliers = count(values, "min_inliers");
  return parameters;
}

OmpsParameters ompsParameters(const ParameterValues& values) {
  OmpsParameters parameters;
  parameters.angular_threshold = positive(values, "angular_threshold");
  parameters.distance_threshold = positive(values, "distance_threshold");
  parameters.normal_smoothing_size = positive(values, "normal_smoothing_size");
  parameters.max_depth_change_factor = positive(values, "max_depth_change_factor");
  parameters.maximum_curvature = positive(values, "maximum_curvature");
  parameters.min_inliers = count(values, "min_inliers");
  return parameters;
}

// A `make` for `baseline` from a function of its complete, checked values.
template <typename MakeFromComplete>
void setMake(Baseline& baseline, MakeFromComplete make_from_complete) {
  baseline.make = [blueprint = baseline, make_from_complete](const ParameterValues& values, const std::string& name) {
    rejectUnknown(blueprint, values);
    return make_from_complete(withDefaults(blueprint, values), name);
  };
}

std::vector<Baseline> makeBaselines() {
  const SequentialRansacParameters ransac;
  const OmpsParameters omps;
  const std::vector<std::pair<std::string, double>> ransac_defaults = {
      {"distance_threshold", ransac.distance_threshold}, {"min_inliers", static_cast<double>(ransac.min_inliers)}};
  Baseline omps_baseline{"omps",
                         {{"angular_threshold", omps.angular_threshold},
                          {"distance_threshold", omps.distance_threshold},
                          {"normal_smoothing_size", omps.normal_smoothing_size},
                          {"max_depth_change_factor", omps.max_depth_change_factor},
                          {"maximum_curvature", omps.maximum_curvature},
                          {"min_inliers", static_cast<double>(omps.min_inliers)}},
                         "",
                         {}};
  setMake(omps_baseline, [](const ParameterValues& values, const std::string& name) {
    return makeOmpsMethod(ompsParameters(values), name);
  });
  Baseline ransac_baseline{"ransac", ransac_defaults, "min_inliers", {}};
  setMake(ransac_baseline, [](const ParameterValues& values, const std::string& name) {
    return makeRansacMethod(ransacParameters(values), name);
  });
  Baseline open3d_baseline{"open3d_ransac", ransac_defaults, "min_inliers", {}};
  setMake(open3d_baseline, [](const ParameterValues& values, const std::string& name) {
    return makeOpen3dRansacMethod(ransacParameters(values), name);
  });
  return {omps_baseline, ransac_baseline, open3d_baseline};
}

}  // namespace

const std::vector<Baseline>& baselines() {
  static const std::vector<Baseline> list = makeBaselines();
  return list;
}

const Baseline* findBaseline(const std::string& name) {
  for (const Baseline& baseline : baselines()) {
    if (baseline.name == name) return &baseline;
  }
  return nullptr;
}

ParameterValues withDefaults(const Baseline& baseline, const ParameterValues& values) {
  ParameterValues complete = values;
  for (const auto& [name, value] : baseline.defaults) complete.emplace(name, value);
  return complete;
}

std::string describeValues(const Baseline& baseline, const ParameterValues& values) {
  const ParameterValues complete = withDefaults(baseline, values);
  std::ostringstream text;
  for (std::size_t k = 0; k < baseline.defaults.size(); ++k) {
    const std::string& name = baseline.defaults[k].first;
    text << (k > 0 ? ", " : "") << name << "=" << complete.at(name);
  }
  return text.str();
}

std::vector<std::uint32_t> truncateSequence(const std::vector<std::uint32_t>& labels, double min_inliers) {
  std::vector<std::size_t> pixels;
  for (const std::uint32_t label : labels) {
    if (label >= pixels.size()) pixels.resize(label + std::size_t{1}, 0);
    ++pixels[label];
  }
  std::uint32_t first_dropped = static_cast<std::uint32_t>(pixels.size());
  for (std::size_t label = 1; label < pixels.size(); ++label) {
    if (static_cast<double>(pixels[label]) < min_inliers) {
      first_dropped = static_cast<std::uint32_t>(label);
      break;
    }
  }
  std::vector<std::uint32_t> kept = labels;
  for (std::uint32_t& label : kept) {
    if (label >= first_dropped) label = 0;
  }
  return kept;
}

}  // namespace pcd_compare
