// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "object_report.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <utility>

#include "eval/object_metrics.h"

namespace pcd_compare {

namespace {

// The scores of a scene's entry and of a mean row, in the table's order after the objects.
constexpr const char* kScores[] = {"object_iou", "objects_found", "under", "over", "support_in_objects"};

std::string fixed(const Json& json, int decimals) {
  if (!json.is_number()) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, json.get<double>());
  return text;
}

// The mean of the numbers at `key` over `entries`; null without any.
Json meanOf(const std::vector<const Json*>& entries, const std::string& key) {
  double sum = 0.0;
  std::size_t count = 0;
  for (const Json* entry : entries) {
    const auto value = entry->find(key);
    if (value == entry->end() || !value->is_number()) continue;
    sum += value->get<double>();
    ++count;
  }
  return count > 0 ? Json(sum / static_cast<double>(count)) : Json(nullptr);
}

}  // namespace

Json objectJson(Json timing, const std::vector<std::uint32_t>& labels, const InputCloud& input) {
  Json json = std::move(timing);
  std::set<std::uint32_t> objects(labels.begin(), labels.end());
  objects.erase(0);
  json["objects"] = objects.size();
  if (!input.ground_truth) return json;
  const auto scores = floodplane::eval::evaluateObjects(*input.ground_truth, labels);
  json["object_iou"] = scores.object_iou;
  json["objects_found"] = scores.objects_found;
  json["under"] = scores.under;
  json["over"] = scores.over;
  json["support_in_objects"] = scores.support_in_objects;
  json["ground_truth_objects"] = scores.objects.size();
  json["per_object"] = Json::array();
  for (const auto& object : scores.objects) {
    json["per_object"].push_back({{"label", object.label},
                                  {"pixels", object.pixels},
                                  {"best", object.best},
                                  {"iou", object.iou},
                                  {"found", object.found},
                                  {"over", object.over},
                                  {"under", object.under}});
  }
  return json;
}

void addObjectMeans(Json& report) {
  std::vector<std::string> methods;  // in run order
  for (const Json& scene : report["scenes"]) {
    for (const auto& [method, entry] : scene["methods"].items()) {
      if (std::find(methods.begin(), methods.end(), method) == methods.end()) methods.push_back(method);
    }
  }
  report["means"] = Json::object();
  for (const std::string& method : methods) {
    std::vector<const Json*> all, scored;
    for (const Json& scene : report["scenes"]) {
      if (!scene["methods"].contains(method)) continue;
      all.push_back(&scene["methods"][method]);
      if (scene["ground_truth"].get<bool>()) scored.push_back(all.back());
    }
    Json row = {{"scenes", all.size()},
                {"scenes_with_ground_truth", scored.size()},
                {"median_ms", meanOf(all, "median_ms")},
                {"min_ms", meanOf(all, "min_ms")},
                {"objects", meanOf(all, "objects")}};
    std::vector<const Json*> parts;
    for (const Json* entry : all) {
      if (entry->contains("parts_median_ms")) parts.push_back(&entry->at("parts_median_ms"));
    }
    // A method names the same parts on every scene.
    const Json names = all.front()->value("parts_median_ms", Json::object());
    for (const auto& part : names.items()) {
      row["parts_median_ms"][part.key()] = meanOf(parts, part.key());
    }
    for (const char* score : kScores) row[score] = meanOf(scored, score);
    report["means"][method] = std::move(row);
  }
}

std::string markdownObjectMeans(const Json& report) {
  bool scored = false;
  for (const Json& scene : report["scenes"]) scored = scored || scene["ground_truth"].get<bool>();
  std::string out = "## Object means per method\n\n### all files (" + std::to_string(report["scenes"].size()) +
                    ")\n\n| method | files | median ms | min ms | objects |" +
                    (scored ? " object_iou | found | under | over | table in objects |" : "") +
                    "\n|---|---:|---:|---:|---:|" + (scored ? "---:|---:|---:|---:|---:|" : "") + "\n";
  for (const auto& [method, row] : report["means"].items()) {
    out += "| " + method + " | " + std::to_string(row["scenes"].get<std::size_t>()) + " | " +
           fixed(row["median_ms"], 1) + " | " + fixed(row["min_ms"], 1) + " | " + fixed(row["objects"], 1) + " |";
    if (scored) {
      for (const char* score : kScores) out += " " + fixed(row[score], 3) + " |";
    }
    out += "\n";
  }
  return out + "\n";
}

}  // namespace pcd_compare
