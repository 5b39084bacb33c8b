// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/params_json.h"

#include <sstream>

#include "params/params_table.h"

namespace floodplane::io {

namespace {

template <class Value>
nlohmann::ordered_json orNull(const std::optional<Value>& value) {
  return value ? nlohmann::ordered_json(*value) : nlohmann::ordered_json(nullptr);
}
template <class Value>
nlohmann::ordered_json orNull(const Value& value) {
  return nlohmann::ordered_json(value);
}

template <class Value>
std::string orAuto(const std::optional<Value>& value, const char* unit) {
  if (!value) return "auto";
  std::ostringstream text;
  text << *value << unit;
  return text.str();
}
template <class Value>
std::string orAuto(const Value& value, const char* unit) {
  return orAuto(std::optional<Value>(value), unit);
}

const char* unitOf(params_table::Length) { return " m"; }
const char* unitOf(params_table::Angle) { return " rad"; }
const char* unitOf(params_table::Count) { return ""; }
const char* unitOf(params_table::Fraction) { return ""; }
const char* unitOf(params_table::Subsampling) { return ""; }
const char* unitOf(params_table::Noise) { return ""; }

}  // namespace

nlohmann::ordered_json paramsJson(const Params& p) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
#define FLOODPLANE_TO_JSON(field, kind, flag, setter, help) json[#field] = orNull(p.field);
  FLOODPLANE_PARAMETERS(FLOODPLANE_TO_JSON)
#undef FLOODPLANE_TO_JSON
  return json;
}

nlohmann::ordered_json noiseJson(const NoiseModel& noise) {
  return {{"estimated", noise.estimated},
          {"sigma_constant", noise.sigma_constant},
          {"sigma_quadratic", noise.sigma_quadratic},
          {"step_constant", noise.step_constant},
          {"step_quadratic", noise.step_quadratic},
          {"patches", noise.patches}};
}

std::string describeParams(const Params& p) {
  std::ostringstream text;
  const char* separator = "";
#define FLOODPLANE_DESCRIBE(field, kind, flag, setter, help)                           \
  text << separator << #field << " " << orAuto(p.field, unitOf(params_table::kind{})); \
  separator = ", ";
  FLOODPLANE_PARAMETERS(FLOODPLANE_DESCRIBE)
#undef FLOODPLANE_DESCRIBE
  if (p.estimatesNoise()) text << " (the noise estimated per frame)";
  return text.str();
}

}  // namespace floodplane::io
