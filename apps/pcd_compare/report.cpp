#include "report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace pcd_compare {

namespace {

using floodplane::eval::HooverClass;
using floodplane::eval::SegmentationScores;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kNone = "-";

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) {
    return kNone;
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

const MethodResult* findMethod(const SceneResult& scene, const std::string& name) {
  for (const MethodResult& result : scene.methods) {
    if (result.method == name) {
      return &result;
    }
  }
  return nullptr;
}

double partMs(const Timing& timing, const std::string& part) {
  for (const auto& [name, ms] : timing.parts_median_ms) {
    if (name == part) {
      return ms;
    }
  }
  return kNaN;
}

// This method's median over floodplane's in the same scene, the comparison metrics.md asks for.
double ratioToFloodplane(const SceneResult& scene, const MethodResult& result) {
  const MethodResult* reference = findMethod(scene, "floodplane");
  return reference != nullptr && reference->timing.median_ms > 0.0
             ? result.timing.median_ms / reference->timing.median_ms
             : kNaN;
}

// Averages of one method over the scenes: times over every scene, accuracy over the scenes
// with ground truth (Hoover counts too: counts per frame, as PEAC and CAPE report them), the
// false-plane fraction over the scenes where it is defined.
struct MeanRow {
  std::size_t scenes = 0;
  std::size_t scored = 0;
  double median_ms = 0.0;
  double min_ms = 0.0;
  double floodplane_median_ms = 0.0;  // over the same scenes, for the ratio of the means
  std::size_t with_floodplane = 0;
  std::map<std::string, double> parts_ms;
  double mean_iou = 0.0;
  double weighted_iou = 0.0;
  double correct = 0.0, over = 0.0, under = 0.0, missed = 0.0, noise = 0.0;
  double planes = 0.0;
  double false_planes = 0.0;
  std::size_t with_non_plane = 0;  // scenes with valid ground-truth-0 pixels

  void add(const SceneResult& scene, const MethodResult& result) {
    ++scenes;
    median_ms += result.timing.median_ms;
    min_ms += result.timing.min_ms;
    planes += static_cast<double>(result.planes);
    for (const auto& [name, ms] : result.timing.parts_median_ms) {
      parts_ms[name] += ms;
    }
    if (const MethodResult* reference = findMethod(scene, "floodplane")) {
      floodplane_median_ms += reference->timing.median_ms;
      ++with_floodplane;
    }
    if (result.scores) addScores(*result.scores);
  }
  void addScores(const SegmentationScores& scores) {
    if (std::isfinite(scores.false_plane_fraction)) {
      false_planes += scores.false_plane_fraction;
      ++with_non_plane;
    }
    // Scenes whose ground truth keeps no plane have no IoU to average.
    if (scores.planes.empty()) return;
    ++scored;
    mean_iou += scores.mean_iou;
    weighted_iou += scores.weighted_iou;
    correct += static_cast<double>(scores.hoover.correct);
    over += static_cast<double>(scores.hoover.over);
    under += static_cast<double>(scores.hoover.under);
    missed += static_cast<double>(scores.hoover.missed);
    noise += static_cast<double>(scores.hoover.noise);
  }
  double time(double sum) const { return scenes > 0 ? sum / static_cast<double>(scenes) : kNaN; }
  double accuracy(double sum) const { return scored > 0 ? sum / static_cast<double>(scored) : kNaN; }
  double falsePlanes() const { return with_non_plane > 0 ? false_planes / static_cast<double>(with_non_plane) : kNaN; }
  double part(const std::string& name) const {
    const auto found = parts_ms.find(name);
    return found != parts_ms.end() ? time(found->second) : kNaN;
  }
  // Ratio of the mean medians: a method's total time over floodplane's, which long scenes
  // dominate as they dominate a user's waiting. NaN unless floodplane ran on every scene.
  double ratio() const {
    return with_floodplane == scenes && floodplane_median_ms > 0.0 ? median_ms / floodplane_median_ms : kNaN;
  }
};

// The mean rows of the main table: per method over every scene, and per sensor model and
// method over the scenes of that sensor model.
struct Means {
  std::map<std::string, MeanRow> overall;                           // by method
  std::map<std::string, std::map<std::string, MeanRow>> by_sensor;  // by sensor, then method
};

Means methodMeans(const Report& report) {
  Means means;
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) {
      means.overall[result.method].add(scene, result);
      if (!scene.sensor.empty()) means.by_sensor[scene.sensor][result.method].add(scene, result);
    }
  }
  return means;
}

std::vector<std::string> methodOrder(const Report& report) {
  std::vector<std::string> order;
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) {
      if (std::find(order.begin(), order.end(), result.method) == order.end()) {
        order.push_back(result.method);
      }
    }
  }
  return order;
}

bool anyGroundTruth(const Report& report) {
  for (const SceneResult& scene : report.scenes) {
    if (scene.has_ground_truth) {
      return true;
    }
  }
  return false;
}

bool anyPart(const Report& report, const std::string& part) {
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) {
      if (std::isfinite(partMs(result.timing, part))) {
        return true;
      }
    }
  }
  return false;
}

std::string hooverName(HooverClass hoover) {
  switch (hoover) {
    case HooverClass::correct:
      return "correct";
    case HooverClass::over_segmented:
      return "over";
    case HooverClass::under_segmented:
      return "under";
    case HooverClass::missed:
      return "missed";
  }
  return "missed";
}

nlohmann::json number(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json scoresJson(const SegmentationScores& scores) {
  nlohmann::json planes = nlohmann::json::array();
  for (const auto& plane : scores.planes) {
    planes.push_back({{"label", plane.label},
                      {"pixels", plane.pixels},
                      {"iou", plane.iou},
                      {"best_segment", plane.best_segment},
                      {"hoover", hooverName(plane.hoover)}});
  }
  return {{"mean_iou", number(scores.mean_iou)},
          {"weighted_iou", number(scores.weighted_iou)},
          {"hoover",
           {{"correct", scores.hoover.correct},
            {"over", scores.hoover.over},
            {"under", scores.hoover.under},
            {"missed", scores.hoover.missed},
            {"noise", scores.hoover.noise}}},
          {"false_plane_fraction", number(scores.false_plane_fraction)},
          {"ground_truth_planes", scores.planes.size()},
          {"predicted_segments", scores.predicted_segments},
          {"per_plane", planes}};
}

nlohmann::json resultJson(const SceneResult& scene, const MethodResult& result) {
  nlohmann::json json = {{"median_ms", result.timing.median_ms},
                         {"min_ms", result.timing.min_ms},
                         {"ratio_to_floodplane", number(ratioToFloodplane(scene, result))},
                         {"planes", result.planes}};
  for (const auto& [name, ms] : result.timing.parts_median_ms) {
    json["parts_median_ms"][name] = ms;
  }
  if (result.scores) {
    json.update(scoresJson(*result.scores));
  }
  return json;
}

// The accuracy columns of a table row, from one scene's scores or from the means.
struct AccuracyCells {
  double mean_iou = kNaN;
  double weighted_iou = kNaN;
  double correct = kNaN, over = kNaN, under = kNaN, missed = kNaN, noise = kNaN;
  double false_planes = kNaN;
  int count_decimals = 0;  // whole counts for a scene, one decimal for means
};

AccuracyCells sceneCells(const SegmentationScores& s) {
  return {s.mean_iou,
          s.weighted_iou,
          static_cast<double>(s.hoover.correct),
          static_cast<double>(s.hoover.over),
          static_cast<double>(s.hoover.under),
          static_cast<double>(s.hoover.missed),
          static_cast<double>(s.hoover.noise),
          s.false_plane_fraction,
          0};
}

AccuracyCells meanCells(const MeanRow& row) {
  return {row.accuracy(row.mean_iou),
          row.accuracy(row.weighted_iou),
          row.accuracy(row.correct),
          row.accuracy(row.over),
          row.accuracy(row.under),
          row.accuracy(row.missed),
          row.accuracy(row.noise),
          row.falsePlanes(),
          1};
}

std::string accuracyCells(const AccuracyCells& c) {
  const int n = c.count_decimals;
  return " " + fixed(c.mean_iou, 3) + " | " + fixed(c.weighted_iou, 3) + " | " + fixed(c.correct, n) + " | " +
         fixed(c.over, n) + " | " + fixed(c.under, n) + " | " + fixed(c.missed, n) + " | " + fixed(c.noise, n) + " | " +
         fixed(c.false_planes, 3) + " |";
}

// Which optional column groups the main table has.
struct MainColumns {
  bool accuracy = false;  // some scene has ground truth
  bool normals = false;   // some method reports its normal estimation (OMPS)
};

std::string mainTableHeader(const MainColumns& columns) {
  std::ostringstream out;
  out << "## Every file and method: runtime" << (columns.accuracy ? " and accuracy" : "") << "\n\n";
  out << "| scene | method | median ms | min ms | x floodplane |" << (columns.normals ? " normals ms |" : "")
      << " planes |";
  if (columns.accuracy) out << " mean IoU | weighted IoU | correct | over | under | missed | noise | false planes |";
  out << "\n|---|---|---:|---:|---:|" << (columns.normals ? "---:|" : "") << "---:|";
  if (columns.accuracy) out << "---:|---:|---:|---:|---:|---:|---:|---:|";
  out << "\n";
  return out.str();
}

std::string mainTableRow(const SceneResult& scene, const MethodResult& result, const MainColumns& columns) {
  std::ostringstream out;
  out << "| " << scene.name << " | " << result.method << " | " << fixed(result.timing.median_ms, 2) << " | "
      << fixed(result.timing.min_ms, 2) << " | " << fixed(ratioToFloodplane(scene, result), 2) << " |";
  if (columns.normals) out << " " << fixed(partMs(result.timing, "normals"), 2) << " |";
  out << " " << result.planes << " |";
  if (columns.accuracy) {
    out << (result.scores ? accuracyCells(sceneCells(*result.scores)) : " - | - | - | - | - | - | - | - |");
  }
  out << "\n";
  return out.str();
}

std::string meanTableHeader(const MainColumns& columns) {
  std::ostringstream out;
  out << "| method | files | median ms | min ms | x floodplane |" << (columns.normals ? " normals ms |" : "")
      << " planes |";
  if (columns.accuracy) out << " mean IoU | weighted IoU | correct | over | under | missed | noise | false planes |";
  out << "\n|---|---:|---:|---:|---:|" << (columns.normals ? "---:|" : "") << "---:|";
  if (columns.accuracy) out << "---:|---:|---:|---:|---:|---:|---:|---:|";
  return out.str() + "\n";
}

std::string meanTableRow(const std::string& method, const MeanRow& row, const MainColumns& columns) {
  std::ostringstream out;
  out << "| " << method << " | " << row.scenes << " | " << fixed(row.time(row.median_ms), 2) << " | "
      << fixed(row.time(row.min_ms), 2) << " | " << fixed(row.ratio(), 2) << " |";
  if (columns.normals) out << " " << fixed(row.part("normals"), 2) << " |";
  out << " " << fixed(row.time(row.planes), 1) << " |";
  if (columns.accuracy) out << accuracyCells(meanCells(row));
  return out.str() + "\n";
}

// One table of means: a row per method, in `order`.
std::string meanTable(const std::string& title, const std::map<std::string, MeanRow>& rows,
                      const std::vector<std::string>& order, const MainColumns& columns) {
  std::string out = "### " + title + "\n\n" + meanTableHeader(columns);
  for (const std::string& method : order) {
    const auto row = rows.find(method);
    if (row != rows.end()) out += meanTableRow(method, row->second, columns);
  }
  return out + "\n";
}

std::size_t sceneCount(const std::map<std::string, MeanRow>& rows) {
  std::size_t count = 0;
  for (const auto& [method, row] : rows) {
    (void)method;
    count = std::max(count, row.scenes);
  }
  return count;
}

// The means per method over every file, then over the files of each sensor model: one table
// per block, so that many methods and sensor models stay readable.
std::string meanTables(const Report& report) {
  const MainColumns columns{anyGroundTruth(report), anyPart(report, "normals")};
  const std::vector<std::string> order = methodOrder(report);
  const Means means = methodMeans(report);
  std::string out = "## Means per method\n\n";
  out += meanTable("all files (" + std::to_string(report.scenes.size()) + ")", means.overall, order, columns);
  for (const auto& [sensor, rows] : means.by_sensor) {
    out +=
        meanTable("sensor model " + sensor + " (" + std::to_string(sceneCount(rows)) + " files)", rows, order, columns);
  }
  return out;
}

// Mean IoU of every method on every file with ground truth, one column per method; the best
// of a row in bold.
std::string iouTable(const Report& report) {
  if (!anyGroundTruth(report)) return "";
  const std::vector<std::string> order = methodOrder(report);
  std::string out = "## Mean IoU per file (best in bold)\n\n| file |";
  std::string rule = "|---|";
  for (const std::string& method : order) {
    out += " " + method + " |";
    rule += "---:|";
  }
  out += "\n" + rule + "\n";
  for (const SceneResult& scene : report.scenes) {
    if (!scene.has_ground_truth) continue;
    double best = -1.0;
    for (const MethodResult& result : scene.methods) {
      if (result.scores && std::isfinite(result.scores->mean_iou)) best = std::max(best, result.scores->mean_iou);
    }
    out += "| " + scene.name + " |";
    for (const std::string& method : order) {
      const MethodResult* result = findMethod(scene, method);
      const double iou = result != nullptr && result->scores ? result->scores->mean_iou : kNaN;
      const std::string cell = fixed(iou, 3);
      // Bold every method that ties the best at the printed precision.
      out += " " + (std::isfinite(iou) && cell == fixed(best, 3) ? "**" + cell + "**" : cell) + " |";
    }
    out += "\n";
  }
  return out + "\n";
}

// Runtime and accuracy of every method on every file.
std::string mainTable(const Report& report) {
  const MainColumns columns{anyGroundTruth(report), anyPart(report, "normals")};
  std::string out = mainTableHeader(columns);
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) out += mainTableRow(scene, result, columns);
  }
  return out + "\n";
}

// floodplane at sub-sampling 1, 2, 4, 8 (Table III): a row per scene and factor, a mean row
// per factor. Empty when --resolutions was not given.
std::string resolutionTable(const Report& report) {
  const bool accuracy = anyGroundTruth(report);
  std::ostringstream out;
  out << "## floodplane by sub-sampling factor (Table III)\n\n"
      << "| scene | sub-sampling | median ms | min ms | speed-up over 1 | planes |"
      << (accuracy ? " mean IoU | weighted IoU | false planes |" : "") << "\n"
      << "|---|---:|---:|---:|---:|---:|" << (accuracy ? "---:|---:|---:|" : "") << "\n";
  std::map<int, MeanRow> factor_means;
  std::map<int, double> speedup_sums;
  for (const SceneResult& scene : report.scenes) {
    double full = kNaN;
    for (const auto& [factor, result] : scene.resolutions) {
      if (factor == 1) full = result.timing.median_ms;
    }
    for (const auto& [factor, result] : scene.resolutions) {
      factor_means[factor].add(scene, result);
      speedup_sums[factor] += full / result.timing.median_ms;
      out << "| " << scene.name << " | " << factor << " | " << fixed(result.timing.median_ms, 2) << " | "
          << fixed(result.timing.min_ms, 2) << " | " << fixed(full / result.timing.median_ms, 2) << " | "
          << result.planes << " |";
      if (accuracy) {
        out << " " << (result.scores ? fixed(result.scores->mean_iou, 3) : kNone) << " | "
            << (result.scores ? fixed(result.scores->weighted_iou, 3) : kNone) << " | "
            << (result.scores ? fixed(result.scores->false_plane_fraction, 3) : kNone) << " |";
      }
      out << "\n";
    }
  }
  if (factor_means.empty()) return "";
  for (const auto& [factor, row] : factor_means) {
    out << "| **mean** (" << row.scenes << " scenes) | " << factor << " | " << fixed(row.time(row.median_ms), 2)
        << " | " << fixed(row.time(row.min_ms), 2) << " | " << fixed(row.time(speedup_sums[factor]), 2) << " | "
        << fixed(row.time(row.planes), 1) << " |";
    if (accuracy) {
      out << " " << fixed(row.accuracy(row.mean_iou), 3) << " | " << fixed(row.accuracy(row.weighted_iou), 3) << " | "
          << fixed(row.falsePlanes(), 3) << " |";
    }
    out << "\n";
  }
  return out.str() + "\n";
}

// One row of the phase table: each phase's share of the phases' total, the total, the call.
std::string phaseRow(const std::string& name, const floodplane::PhaseTimes& phases, double call_ms) {
  const double total = phases.total();
  std::string row = "| " + name + " |";
  for (const auto& [key, member] : phaseMembers()) {
    (void)key;
    row += " " + fixed(total > 0.0 ? 100.0 * (phases.*member) / total : kNaN, 1) + "% |";
  }
  return row + " " + fixed(total, 2) + " | " + fixed(call_ms, 2) + " |\n";
}

// floodplane's time by phase (Fig. 5): a row per scene and the mean. Empty when --phases was
// not given.
std::string phaseTable(const Report& report) {
  std::string header = "| scene |";
  std::string rule = "|---|";
  for (const auto& [key, member] : phaseMembers()) {
    (void)member;
    std::string name = key;
    std::replace(name.begin(), name.end(), '_', ' ');
    header += " " + name + " |";
    rule += "---:|";
  }
  std::string out = "## floodplane's time by phase (Fig. 5), share of the phases' total\n\n" + header +
                    " phases ms | call ms |\n" + rule + "---:|---:|\n";
  floodplane::PhaseTimes sum;
  double call_sum = 0.0;
  std::size_t count = 0;
  for (const SceneResult& scene : report.scenes) {
    if (!scene.phases) continue;
    out += phaseRow(scene.name, scene.phases->median, scene.phases->call_median_ms);
    for (const auto& [key, member] : phaseMembers()) {
      (void)key;
      sum.*member += scene.phases->median.*member;
    }
    call_sum += scene.phases->call_median_ms;
    ++count;
  }
  if (count == 0) return "";
  floodplane::PhaseTimes mean;
  for (const auto& [key, member] : phaseMembers()) {
    (void)key;
    mean.*member = sum.*member / static_cast<double>(count);
  }
  out += phaseRow("**mean** (" + std::to_string(count) + " scenes)", mean, call_sum / static_cast<double>(count));
  return out + "\n";
}

}  // namespace

std::string markdownConfiguration(const Report& report) {
  std::ostringstream out;
  out << "## Configuration\n\n";
  for (const auto& [key, value] : report.configuration) {
    out << "- **" << key << "**: " << value << "\n";
  }
  out << "\n";
  return out.str();
}

std::string markdownTables(const Report& report) {
  return meanTables(report) + iouTable(report) + mainTable(report) + resolutionTable(report) + phaseTable(report);
}

std::string csvReport(const Report& report) {
  std::ostringstream out;
  out << "scene,file,method,subsampling,width,height,median_ms,min_ms,ratio_to_floodplane,"
         "normals_ms,planes,mean_iou,weighted_iou,correct,over,under,missed,noise,false_plane_fraction\n";
  const auto line = [&out](const SceneResult& scene, const MethodResult& result, int factor, double ratio) {
    // Scene names come from file names; quote them in case they hold commas.
    out << '"' << scene.name << "\",\"" << scene.path << "\"," << result.method << "," << factor << "," << scene.width
        << "," << scene.height << "," << fixed(result.timing.median_ms, 4) << "," << fixed(result.timing.min_ms, 4)
        << "," << fixed(ratio, 4) << "," << fixed(partMs(result.timing, "normals"), 4) << "," << result.planes << ",";
    if (result.scores) {
      const auto& s = *result.scores;
      out << fixed(s.mean_iou, 6) << "," << fixed(s.weighted_iou, 6) << "," << s.hoover.correct << "," << s.hoover.over
          << "," << s.hoover.under << "," << s.hoover.missed << "," << s.hoover.noise << ","
          << fixed(s.false_plane_fraction, 6);
    } else {
      out << ",,,,,,,";
    }
    out << "\n";
  };
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) {
      line(scene, result, 1, ratioToFloodplane(scene, result));
    }
    for (const auto& [factor, result] : scene.resolutions) {
      if (factor != 1 || findMethod(scene, "floodplane") == nullptr) {
        line(scene, result, factor, ratioToFloodplane(scene, result));
      }
    }
  }
  return out.str();
}

namespace {

nlohmann::json phasesJson(const PhaseResult& phases) {
  nlohmann::json json;
  const double total = phases.median.total();
  for (const auto& [key, member] : phaseMembers()) {
    json["median_ms"][key] = phases.median.*member;
    json["share"][key] = number(total > 0.0 ? (phases.median.*member) / total : kNaN);
  }
  json["phases_total_ms"] = total;
  json["call_median_ms"] = phases.call_median_ms;
  return json;
}

nlohmann::json sceneJson(const SceneResult& scene) {
  nlohmann::json json = {{"name", scene.name},
                         {"file", scene.path},
                         {"width", scene.width},
                         {"height", scene.height},
                         {"ground_truth", scene.has_ground_truth},
                         {"min_points", scene.min_points},
                         {"methods", nlohmann::json::object()}};
  if (!scene.sensor.empty()) json["sensor"] = scene.sensor;
  for (const MethodResult& result : scene.methods) {
    json["methods"][result.method] = resultJson(scene, result);
  }
  for (const auto& [factor, result] : scene.resolutions) {
    json["resolutions"][std::to_string(factor)] = resultJson(scene, result);
  }
  if (scene.phases) json["phases"] = phasesJson(*scene.phases);
  return json;
}

nlohmann::json meanJson(const MeanRow& row) {
  return {{"scenes", row.scenes},
          {"scenes_with_ground_truth", row.scored},
          {"median_ms", number(row.time(row.median_ms))},
          {"min_ms", number(row.time(row.min_ms))},
          {"ratio_to_floodplane", number(row.ratio())},
          {"mean_iou", number(row.accuracy(row.mean_iou))},
          {"weighted_iou", number(row.accuracy(row.weighted_iou))},
          {"hoover",
           {{"correct", number(row.accuracy(row.correct))},
            {"over", number(row.accuracy(row.over))},
            {"under", number(row.accuracy(row.under))},
            {"missed", number(row.accuracy(row.missed))},
            {"noise", number(row.accuracy(row.noise))}}},
          {"false_plane_fraction", number(row.falsePlanes())},
          {"scenes_with_non_plane_ground_truth", row.with_non_plane}};
}

nlohmann::json meansJson(const std::map<std::string, MeanRow>& rows) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& [method, row] : rows) json[method] = meanJson(row);
  return json;
}

}  // namespace

std::string jsonReport(const Report& report) {
  nlohmann::json json;
  for (const auto& [key, value] : report.configuration) {
    json["configuration"][key] = value;
  }
  json["scenes"] = nlohmann::json::array();
  for (const SceneResult& scene : report.scenes) json["scenes"].push_back(sceneJson(scene));
  const Means means = methodMeans(report);
  json["means"] = meansJson(means.overall);
  json["means_by_sensor"] = nlohmann::json::object();
  for (const auto& [sensor, rows] : means.by_sensor) json["means_by_sensor"][sensor] = meansJson(rows);
  json["failed"] = report.failed;
  return json.dump(2) + "\n";
}

const std::vector<std::pair<const char*, double floodplane::PhaseTimes::*>>& phaseMembers() {
  static const std::vector<std::pair<const char*, double floodplane::PhaseTimes::*>> members = {
      {"preparation", &floodplane::PhaseTimes::preparation},
      {"seed_selection", &floodplane::PhaseTimes::seed_selection},
      {"flood_fill", &floodplane::PhaseTimes::flood_fill},
      {"relabelling", &floodplane::PhaseTimes::relabelling},
      {"merging", &floodplane::PhaseTimes::merging},
      {"region_output", &floodplane::PhaseTimes::region_output},
      {"pcl_conversion", &floodplane::PhaseTimes::pcl_conversion},
  };
  return members;
}

}  // namespace pcd_compare
