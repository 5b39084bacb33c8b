// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// pcd_compare --objects' report: each object method's entry in a scene (its time, its objects
// and their scores against the ground truth's object labels, floodplane_eval's
// evaluateObjects), the means per method, and the Markdown table printed on stdout.

#include <cstdint>
#include <string>
#include <vector>

#include "input_cloud.h"
#include "report.h"

namespace pcd_compare {

/// An object method's entry in a scene: `timing` (median_ms, min_ms, parts_median_ms), the
/// number of objects in `labels` and, when `input` has ground truth (mOSD's coding: 1-9 the
/// table, from 20 the objects, each label apart), object_iou, objects_found, over, under,
/// support_in_objects (as ../shared/tools/osd_scores.py --objects gives them) and per_object.
Json objectJson(Json timing, const std::vector<std::uint32_t>& labels, const InputCloud& input);

/// Completes a report whose "scenes" hold objectJson entries: "means", per method over every
/// scene (time, objects) and over the scenes with ground truth (the scores).
void addObjectMeans(Json& report);

/// The means as a Markdown table.
std::string markdownObjectMeans(const Json& report);

}  // namespace pcd_compare
