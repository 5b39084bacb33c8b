#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace pcd_compare {

namespace {

using floodplane::eval::HooverClass;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::vector<std::string> kHooverCounts = {"correct", "over", "under", "missed", "noise"};

Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }
double value(const Json& json) { return json.is_number() ? json.get<double>() : kNaN; }

std::string hooverName(HooverClass hoover) {
  switch (hoover) {
    case HooverClass::correct:
      return "correct";
    case HooverClass::over_segmented:
      return "over";
    case HooverClass::under_segmented:
      return "under";
    case HooverClass::missed:
      break;
  }
  return "missed";
}

// One method's sums over scenes, for its mean row.
struct MeanRow {
  std::size_t scenes = 0, scored = 0, with_floodplane = 0, with_non_plane = 0;
  double median_ms = 0.0, min_ms = 0.0, floodplane_ms = 0.0, planes = 0.0, false_planes = 0.0;
  std::map<std::string, double> parts_ms, accuracy;  // accuracy: the IoUs and Hoover counts

  void add(const Json& scene, const Json& result) {
    ++scenes;
    median_ms += value(result["median_ms"]);
    min_ms += value(result["min_ms"]);
    planes += value(result["planes"]);
    const Json parts = result.value("parts_median_ms", Json::object());
    for (const auto& [part, ms] : parts.items()) parts_ms[part] += value(ms);
    if (scene["methods"].contains("floodplane")) {
      floodplane_ms += value(scene["methods"]["floodplane"]["median_ms"]);
      ++with_floodplane;
    }
    if (result.contains("false_plane_fraction") && result["false_plane_fraction"].is_number()) {
      false_planes += value(result["false_plane_fraction"]);
      ++with_non_plane;
    }
    // Scenes whose ground truth keeps no plane have no IoU to average.
    if (result.value("ground_truth_planes", 0) == 0) return;
    ++scored;
    accuracy["mean_iou"] += value(result["mean_iou"]);
    accuracy["weighted_iou"] += value(result["weighted_iou"]);
    for (const std::string& count : kHooverCounts) accuracy[count] += value(result["hoover"][count]);
  }

  Json json() const {
    const auto time = [this](double sum) { return number(scenes > 0 ? sum / static_cast<double>(scenes) : kNaN); };
    const auto mean = [this](const std::string& key) {
      return number(scored > 0 ? accuracy.at(key) / static_cast<double>(scored) : kNaN);
    };
    Json row = {{"scenes", scenes},
                {"scenes_with_ground_truth", scored},
                {"median_ms", time(median_ms)},
                {"min_ms", time(min_ms)},
                // The ratio of the mean medians: long scenes weigh as they weigh in a user's
                // waiting. Only when floodplane ran on every scene.
                {"ratio_to_floodplane",
                 number(with_floodplane == scenes && floodplane_ms > 0.0 ? median_ms / floodplane_ms : kNaN)},
                {"planes", time(planes)}};
    for (const auto& [part, ms] : parts_ms) row["parts_median_ms"][part] = time(ms);
    row["mean_iou"] = mean("mean_iou");
    row["weighted_iou"] = mean("weighted_iou");
    for (const std::string& count : kHooverCounts) row["hoover"][count] = mean(count);
    row["false_plane_fraction"] =
        number(with_non_plane > 0 ? false_planes / static_cast<double>(with_non_plane) : kNaN);
    row["scenes_with_non_plane_ground_truth"] = with_non_plane;
    return row;
  }
};

Json meansJson(const std::vector<std::pair<std::string, MeanRow>>& rows) {
  Json json = Json::object();
  for (const auto& [method, row] : rows) json[method] = row.json();
  return json;
}

MeanRow& rowOf(std::vector<std::pair<std::string, MeanRow>>& rows, const std::string& method) {
  for (auto& [name, row] : rows) {
    if (name == method) return row;
  }
  return rows.emplace_back(method, MeanRow{}).second;
}

std::string fixed(const Json& json, int decimals) {
  if (!json.is_number()) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, json.get<double>());
  return text;
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
      for (const std::string& count : kHooverCounts) out += " " + fixed(row["hoover"][count], 1) + " |";
      out += " " + fixed(row["false_plane_fraction"], 3) + " |";
    }
    out += "\n";
  }
  return out + "\n";
}

}  // namespace

Json methodJson(const Timing& timing, std::size_t planes,
                const std::optional<floodplane::eval::SegmentationScores>& scores) {
  Json json = {{"median_ms", timing.median_ms}, {"min_ms", timing.min_ms}, {"planes", planes}};
  for (const auto& [name, ms] : timing.parts_median_ms) json["parts_median_ms"][name] = ms;
  if (!scores) return json;
  json["mean_iou"] = number(scores->mean_iou);
  json["weighted_iou"] = number(scores->weighted_iou);
  json["hoover"] = {{"correct", scores->hoover.correct},
                    {"over", scores->hoover.over},
                    {"under", scores->hoover.under},
                    {"missed", scores->hoover.missed},
                    {"noise", scores->hoover.noise}};
  json["false_plane_fraction"] = number(scores->false_plane_fraction);
  json["ground_truth_planes"] = scores->planes.size();
  json["predicted_segments"] = scores->predicted_segments;
  json["per_plane"] = Json::array();
  for (const auto& plane : scores->planes) {
    json["per_plane"].push_back({{"label", plane.label},
                                 {"pixels", plane.pixels},
                                 {"iou", plane.iou},
                                 {"best_segment", plane.best_segment},
                                 {"hoover", hooverName(plane.hoover)}});
  }
  return json;
}

void addMeans(Json& report) {
  std::vector<std::pair<std::string, MeanRow>> overall;
  std::map<std::string, std::vector<std::pair<std::string, MeanRow>>> by_sensor;
  for (Json& scene : report["scenes"]) {
    const double floodplane_ms =
        scene["methods"].contains("floodplane") ? value(scene["methods"]["floodplane"]["median_ms"]) : kNaN;
    for (auto& [method, result] : scene["methods"].items()) {
      result["ratio_to_floodplane"] = number(floodplane_ms > 0.0 ? value(result["median_ms"]) / floodplane_ms : kNaN);
      rowOf(overall, method).add(scene, result);
      if (!scene.contains("sensor")) continue;
      rowOf(by_sensor[scene["sensor"].get<std::string>()], method).add(scene, result);
    }
  }
  report["means"] = meansJson(overall);
  report["means_by_sensor"] = Json::object();
  for (const auto& [sensor, rows] : by_sensor) report["means_by_sensor"][sensor] = meansJson(rows);
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

}  // namespace pcd_compare
