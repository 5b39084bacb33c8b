// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parameters and the noise model as the apps report them (JSON, and one line of text):
// written once for pcd_segment, pcd_compare and the benchmarks. Unset (scale-free) lengths
// are null in JSON and "auto" in text.

#include <nlohmann/json.hpp>

#include <string>

#include "floodplane/params.h"
#include "floodplane/segmenter.h"

namespace floodplane::io {

nlohmann::ordered_json paramsJson(const Params& params);
nlohmann::ordered_json noiseJson(const NoiseModel& noise);
/// "distance_threshold auto, seed_size 0.06 m, ..." for a configuration header: every field
/// of params_table.h by its name.
std::string describeParams(const Params& params);

}  // namespace floodplane::io
