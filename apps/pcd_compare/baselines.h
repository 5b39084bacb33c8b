#pragma once
// The baselines whose parameters can be tuned (PCL's OMPS and RANSAC, Open3D's RANSAC): each
// made from a set of values by name, and the tuned values that bench/tune_baselines.py writes
// per baseline and sensor model, which --tuned reads.

#include <map>
#include <memory>
#include <string>

#include "method.h"

namespace pcd_compare {

/// Per baseline, then per sensor model, the tuned values.
using TunedValues = std::map<std::string, std::map<std::string, ParameterValues>>;

/// True for "omps", "ransac" and "open3d_ransac".
bool isTunable(const std::string& baseline);
/// The tunable `baseline` at `values` (missing names take their defaults), named `name`.
/// Throws std::invalid_argument for an unknown parameter or a value out of range.
std::unique_ptr<Method> makeBaseline(const std::string& baseline, const ParameterValues& values,
                                     const std::string& name);
/// Every parameter of `baseline` with its value, the defaults filled in: "name=value, ...".
std::string describeValues(const std::string& baseline, const ParameterValues& values);
/// Reads a tuning result; std::runtime_error naming the file if it cannot be read, parsed, or
/// names an unknown baseline, parameter or bad value.
TunedValues readTunedValues(const std::string& path);

}  // namespace pcd_compare
