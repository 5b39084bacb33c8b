// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <set>
#include <utility>

#include "eval/segmentation_metrics.h"

namespace pcd_compare {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The Hoover counts' keys: a plane's class (HooverClass's order), then the noise segments.
constexpr const char* kHooverCounts[] = {"correct", "over", "under", "missed", "noise"};
static_assert(static_cast<int>(floodplane::eval::HooverClass::missed) == 3, "kHooverCounts follows HooverClass");
// A plane's MissReason in the JSON and the --misses table; null for a correct detection.
constexpr const char* kMissReasons[] = {nullptr, "no_segment", "under_segmented", "over_segmented", "iou_below_t"};
static_assert(static_cast<int>(floodplane::eval::MissReason::iou_below_t) == 4, "kMissReasons follows MissReason");

Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

// The sum of the numbers at `key` (a JSON pointer) in `results`, and how many there were.
struct Sum {
  double sum = 0.0;
  std::size_t count = 0;
  Json mean() const { return number(count > 0 ? sum / static_cast<double>(count) : kNaN); }
};

Sum sumOf(const std::vector<const Json*>& results, const std::string& key) {
  const Json::json_pointer pointer(key);
  Sum total;
  for (const Json* result : results) {
    if (!result->contains(pointer) || !result->at(pointer).is_number()) continue;
    total.sum += result->at(pointer).get<double>();
    ++total.count;
  }
  return total;
}

// The mean row of `method` over the scenes of sensor model `sensor` (empty: every scene) that
// ran it; null if none did.
Json meanRow(const Json& scenes, const std::string& method, const std::string& sensor) {
  std::vector<const Json*> all, scored, floodplane;
  for (const Json& scene : scenes) {
    const Json& methods = scene.at("methods");
    if (!methods.contains(method) || (!sensor.empty() && scene.value("sensor", "") != sensor)) continue;
    all.push_back(&methods.at(method));
    // Scenes whose ground truth keeps no plane have no IoU to average.
    if (all.back()->value("ground_truth_planes", 0) > 0) scored.push_back(all.back());
    if (methods.contains("floodplane")) floodplane.push_back(&methods.at("floodplane"));
  }
  if (all.empty()) return Json();
  const Sum median = sumOf(all, "/median_ms");
  const Sum false_planes = sumOf(all, "/false_plane_fraction");
  Json row = {{"scenes", all.size()},
              {"scenes_with_ground_truth", scored.size()},
              {"median_ms", median.mean()},
              {"min_ms", sumOf(all, "/min_ms").mean()},
              // The ratio of the mean medians: long scenes weigh as they weigh in a user's
              // waiting. Only when floodplane ran on every scene.
              {"ratio_to_floodplane", number(floodplane.size() == all.size() && median.count == all.size()
                                                 ? median.sum / sumOf(floodplane, "/median_ms").sum
                                                 : kNaN)},
              {"planes", sumOf(all, "/planes").mean()}};
  // A method names the same parts on every scene.
  const Json parts = all.front()->value("parts_median_ms", Json::object());
  for (const auto& part : parts.items()) {
    row["parts_median_ms"][part.key()] = sumOf(all, "/parts_median_ms/" + part.key()).mean();
  }
  row["mean_iou"] = sumOf(scored, "/mean_iou").mean();
  row["weighted_iou"] = sumOf(scored, "/weighted_iou").mean();
  for (const char* count : kHooverCounts) row["hoover"][count] = sumOf(scored, std::string("/hoover/") + count).mean();
  row["false_plane_fraction"] = false_planes.mean();
  row["scenes_with_non_plane_ground_truth"] = false_planes.count;
  return row;
}

std::string fixed(const Json& json, int decimals) {
  if (!json.is_number()) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, json.get<double>());
  return text;
}

std::string percent(const Json& share) {
  return share.is_number() ? fixed(Json(100.0 * share.get<double>()), 0) + " %" : "-";
}

// One table of means; `normals` and `accuracy` add their columns.
std::string meanTable(const std::string& title, const Json& rows, bool normals, bool accuracy) {
  std::string out =
      "### " + title + "\n\n| method | files | median ms | min ms | x floodplane |" + (normals ? " normals ms |" : "") +
      " planes |" +
      (accuracy ? " mean IoU | weighted IoU | correct | over | under | missed | noise | false planes |" : "") +
      "\n|---|---:|---:|---:|---:|" + (normals ? "---:|" : "") + "---:|" +
      (accuracy ? "---:|---:|---:|---:|---:|---:|---:|---:|" : "") + "\n";
  for (const auto& [method, row] : rows.items()) {
    out +=
        "| " + method + " | " + std::to_string(row["scenes"].get<std::size_t>()) + " | " + fixed(row["median_ms"], 2) +
        " | " + fixed(row["min_ms"], 2) + " | " + fixed(row["ratio_to_floodplane"], 2) + " |" +
        (normals ? " " + fixed(row.value("parts_median_ms", Json::object()).value("normals", Json()), 2) + " |" : "") +
        " " + fixed(row["planes"], 1) + " |";
    if (accuracy) {
      out += " " + fixed(row["mean_iou"], 3) + " | " + fixed(row["weighted_iou"], 3) + " |";
      for (const char* count : kHooverCounts) out += " " + fixed(row["hoover"][count], 1) + " |";
      out += " " + fixed(row["false_plane_fraction"], 3) + " |";
    }
    out += "\n";
  }
  return out + "\n";
}

}  // namespace

Json methodJson(Json timing, const std::vector<std::uint32_t>& labels, const InputCloud& input,
                std::uint32_t min_points) {
  Json json = std::move(timing);
  std::set<std::uint32_t> planes(labels.begin(), labels.end());
  planes.erase(0);
  json["planes"] = planes.size();
  if (!input.ground_truth) return json;
  floodplane::eval::MetricsOptions options;
  options.min_points = min_points;
  options.tolerance = 0.8;  // Hoover's T, metrics.md's default
  const auto scores = floodplane::eval::evaluateSegmentation(*input.ground_truth, labels, input.valid, options);
  json["mean_iou"] = number(scores.mean_iou);
  json["weighted_iou"] = number(scores.weighted_iou);
  json["hoover"] = {{"correct", scores.hoover.correct},
                    {"over", scores.hoover.over},
                    {"under", scores.hoover.under},
                    {"missed", scores.hoover.missed},
                    {"noise", scores.hoover.noise}};
  json["false_plane_fraction"] = number(scores.false_plane_fraction);
  json["ground_truth_planes"] = scores.planes.size();
  json["predicted_segments"] = scores.predicted_segments;
  json["per_plane"] = Json::array();
  for (const auto& plane : scores.planes) {
    const char* miss = kMissReasons[static_cast<int>(plane.miss)];
    json["per_plane"].push_back({{"label", plane.label},
                                 {"pixels", plane.pixels},
                                 {"iou", plane.iou},
                                 {"best_segment", plane.best_segment},
                                 {"hoover", kHooverCounts[static_cast<int>(plane.hoover)]},
                                 {"miss", miss != nullptr ? Json(miss) : Json(nullptr)},
                                 {"unlabelled_share", plane.unlabelled_share},
                                 {"main_segment", plane.main_segment},
                                 {"main_segment_share", plane.main_segment_share}});
  }
  json["noise_segments"] = Json::array();
  for (const auto& segment : scores.noise) {
    json["noise_segments"].push_back({{"label", segment.label},
                                      {"pixels", segment.pixels},
                                      {"iou", segment.iou},
                                      {"off_plane_share", segment.off_plane_share}});
  }
  return json;
}

void addMeans(Json& report) {
  std::vector<std::string> methods;  // in run order
  std::set<std::string> sensors;
  for (Json& scene : report["scenes"]) {
    const double floodplane_ms = scene["methods"].value(Json::json_pointer("/floodplane/median_ms"), kNaN);
    for (auto& [method, result] : scene["methods"].items()) {
      // Labels read from files (--labels) have no time: null, as NaN is.
      const double median_ms = result["median_ms"].is_number() ? result["median_ms"].get<double>() : kNaN;
      result["ratio_to_floodplane"] = number(median_ms / floodplane_ms);
      if (std::find(methods.begin(), methods.end(), method) == methods.end()) methods.push_back(method);
    }
    if (scene.contains("sensor")) sensors.insert(scene["sensor"].get<std::string>());
  }
  const auto means = [&](const std::string& sensor) {
    Json rows = Json::object();
    for (const std::string& method : methods) {
      if (Json row = meanRow(report["scenes"], method, sensor); !row.is_null()) rows[method] = std::move(row);
    }
    return rows;
  };
  report["means"] = means("");
  report["means_by_sensor"] = Json::object();
  for (const std::string& sensor : sensors) report["means_by_sensor"][sensor] = means(sensor);
}

std::string markdownConfiguration(const Json& report) {
  std::string out = "## Configuration\n\n";
  for (const auto& [key, text] : report["configuration"].items())
    out += "- **" + key + "**: " + text.get<std::string>() + "\n";
  return out + "\n";
}

std::string markdownMeans(const Json& report) {
  bool normals = false, accuracy = false;
  for (const auto& [method, row] : report["means"].items()) {
    normals = normals || row.value("parts_median_ms", Json::object()).contains("normals");
  }
  for (const auto& scene : report["scenes"]) accuracy = accuracy || scene["ground_truth"].get<bool>();
  std::string out = "## Means per method\n\n" + meanTable("all files (" + std::to_string(report["scenes"].size()) + ")",
                                                          report["means"], normals, accuracy);
  for (const auto& [sensor, rows] : report["means_by_sensor"].items()) {
    std::size_t files = 0;
    for (const auto& [method, row] : rows.items()) files = std::max(files, row["scenes"].get<std::size_t>());
    out += meanTable("sensor model " + sensor + " (" + std::to_string(files) + " files)", rows, normals, accuracy);
  }
  return out;
}

std::string markdownMisses(const Json& report) {
  std::vector<std::string> methods;  // in run order, those with scores
  for (const Json& scene : report["scenes"]) {
    for (const auto& [method, result] : scene["methods"].items()) {
      if (result.contains("per_plane") && std::find(methods.begin(), methods.end(), method) == methods.end())
        methods.push_back(method);
    }
  }
  std::string out = "## Misses per method\n\n";
  if (methods.empty()) return out + "No file has ground truth: nothing to miss.\n\n";
  for (const std::string& method : methods) {
    std::string rows;
    std::size_t planes = 0, misses = 0, noise = 0;
    for (const Json& scene : report["scenes"]) {
      const Json& result = scene["methods"].value(method, Json::object());
      const std::string file = scene["name"].get<std::string>();
      for (const Json& plane : result.value("per_plane", Json::array())) {
        ++planes;
        if (plane["miss"].is_null()) continue;
        ++misses;
        rows += "| " + file + " | " + std::to_string(plane["label"].get<std::uint32_t>()) + " | " +
                plane["miss"].get<std::string>() + " | " + std::to_string(plane["pixels"].get<std::size_t>()) + " | " +
                fixed(plane["iou"], 2) + " | " + percent(plane["unlabelled_share"]) + " | " +
                (plane["main_segment"].get<std::uint32_t>() == 0
                     ? std::string("no segment holds any of it")
                     : "segment " + std::to_string(plane["main_segment"].get<std::uint32_t>()) + " holds " +
                           percent(plane["main_segment_share"])) +
                " |\n";
      }
      for (const Json& segment : result.value("noise_segments", Json::array())) {
        ++noise;
        rows += "| " + file + " | segment " + std::to_string(segment["label"].get<std::uint32_t>()) + " | noise | " +
                std::to_string(segment["pixels"].get<std::size_t>()) + " | " + fixed(segment["iou"], 2) + " | - | " +
                percent(segment["off_plane_share"]) + " of it on no plane |\n";
      }
    }
    out += "### " + method + ": " + std::to_string(misses) + " of " + std::to_string(planes) +
           " ground-truth planes not correct, " + std::to_string(noise) + " noise segments\n\n";
    if (rows.empty()) continue;
    out +=
        "| file | region | class | pixels | IoU | unlabelled | where it went |\n"
        "|---|---|---|---:|---:|---:|---|\n" +
        rows + "\n";
  }
  return out;
}

}  // namespace pcd_compare
