// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// pcd_compare's report: one JSON document (ordered as it was filled: files and methods in run
// order), which the driver fills scene by scene and --json writes; the means derived from it;
// the Markdown printed on stdout (configuration and means). Every other table, and the CSV,
// bench/compare_tables.py makes from the JSON.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "input_cloud.h"

namespace pcd_compare {

using Json = nlohmann::ordered_json;

/// A method's entry in a scene: `timing` (median_ms, min_ms and the parts' parts_median_ms),
/// the planes of `labels` and, when `input` has ground truth, the scores against it as in
/// metrics.md (T = 0.8; planes and segments below `min_points` pixels ignored): mean and
/// weighted IoU, Hoover counts, false-plane fraction, per plane (with why it is not a correct
/// detection: floodplane::eval::MissReason) and the noise segments; NaN as null.
Json methodJson(Json timing, const std::vector<std::uint32_t>& labels, const InputCloud& input,
                std::uint32_t min_points);

/// Completes a report whose "scenes" are filled: each method's ratio_to_floodplane in its
/// scene, then "means" (per method over every scene) and "means_by_sensor" (per sensor model
/// named by the scenes, then per method). Times average over every scene, accuracy over the
/// scenes whose ground truth keeps a plane (Hoover counts per frame, as PEAC and CAPE report
/// them), the false-plane fraction over the scenes where it is defined.
void addMeans(Json& report);

/// The report's "configuration" as a Markdown list.
std::string markdownConfiguration(const Json& report);
/// The means as Markdown tables: every file, then one table per sensor model.
std::string markdownMeans(const Json& report);
/// Per method, every kept ground-truth plane that is not a correct detection (file, label,
/// class of miss, size, IoU, unlabelled share, the segment holding most of it) and every noise
/// segment, as a Markdown table (--misses).
std::string markdownMisses(const Json& report);

}  // namespace pcd_compare
