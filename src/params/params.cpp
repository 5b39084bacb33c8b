// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/params.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "params/params_table.h"

namespace floodplane {

bool isValidSubsampling(int factor) { return factor == 1 || factor == 2 || factor == 4 || factor == 8; }

namespace {

std::string positive(double value, const char* name, const char* unit) {
  if (std::isfinite(value) && value > 0.0) return {};
  return std::string(name) + " must be a finite number of " + unit + " > 0, got " + std::to_string(value);
}
std::string positive(const std::optional<double>& value, const char* name, const char* unit) {
  return value ? positive(*value, name, unit) : std::string();
}

std::string nonNegative(double value, const char* name) {
  if (std::isfinite(value) && value >= 0.0) return {};
  return std::string(name) + " must be a finite number >= 0, got " + std::to_string(value);
}
std::string nonNegative(const std::optional<double>& value, const char* name) {
  return value ? nonNegative(*value, name) : std::string();
}

// The rule of each kind of value (params_table.h); `name` is the field's.
std::string problemOf(params_table::Length, const std::optional<double>& value, const char* name) {
  return positive(value, name, "metres");
}
std::string problemOf(params_table::Angle, double value, const char* name) {
  std::string problem = positive(value, name, "radians");
  if (problem.empty() && value >= M_PI / 2)
    problem = std::string(name) + " must be < pi/2 radians, got " + std::to_string(value);
  return problem;
}
std::string problemOf(params_table::Count, const std::optional<std::uint32_t>&, const char*) { return {}; }
std::string problemOf(params_table::Fraction, double value, const char* name) { return nonNegative(value, name); }
std::string problemOf(params_table::Subsampling, int value, const char* name) {
  if (isValidSubsampling(value)) return {};
  return std::string(name) + " must be 1, 2, 4 or 8, got " + std::to_string(value);
}
std::string problemOf(params_table::Noise, const std::optional<double>& value, const char* name) {
  return nonNegative(value, name);
}

}  // namespace

std::string Params::problem() const {
  std::string problem;
#define FLOODPLANE_CHECK(field, kind, flag, setter, help) \
  if (problem.empty()) problem = problemOf(params_table::kind{}, field, #field);
  FLOODPLANE_PARAMETERS(FLOODPLANE_CHECK)
#undef FLOODPLANE_CHECK
  return problem;
}

void Params::validate() const {
  const std::string what = problem();
  if (!what.empty()) throw std::invalid_argument("floodplane::Params: " + what);
}

}  // namespace floodplane
