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
// with ground truth (Hoover counts too: counts per frame, as PEAC and CAPE report them).
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
    // Scenes whose ground truth keeps no plane have no IoU to average.
    if (result.scores && !result.scores->planes.empty()) {
      ++scored;
      mean_iou += result.scores->mean_iou;
      weighted_iou += result.scores->weighted_iou;
      correct += static_cast<double>(result.scores->hoover.correct);
      over += static_cast<double>(result.scores->hoover.over);
      under += static_cast<double>(result.scores->hoover.under);
      missed += static_cast<double>(result.scores->hoover.missed);
      noise += static_cast<double>(result.scores->hoover.noise);
    }
  }
  double time(double sum) const { return scenes > 0 ? sum / static_cast<double>(scenes) : kNaN; }
  double accuracy(double sum) const {
    return scored > 0 ? sum / static_cast<double>(scored) : kNaN;
  }
  // Ratio of the mean medians: a method's total time over floodplane's, which long scenes
  // dominate as they dominate a user's waiting. NaN unless floodplane ran on every scene.
  double ratio() const {
    return with_floodplane == scenes && floodplane_median_ms > 0.0
               ? median_ms / floodplane_median_ms
               : kNaN;
  }
};

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
    case HooverClass::correct: return "correct";
    case HooverClass::over_segmented: return "over";
    case HooverClass::under_segmented: return "under";
    case HooverClass::missed: return "missed";
  }
  return "missed";
}

nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

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

const std::vector<std::pair<const char*, double floodplane::PhaseTimes::*>> kPhases = {
    {"seed_selection", &floodplane::PhaseTimes::seed_selection},
    {"flood_fill", &floodplane::PhaseTimes::flood_fill},
    {"relabelling", &floodplane::PhaseTimes::relabelling},
    {"merging", &floodplane::PhaseTimes::merging},
    {"region_output", &floodplane::PhaseTimes::region_output},
};

void accuracyCells(std::ostringstream& out, double mean_iou, double weighted_iou, double correct,
                   double over, double under, double missed, double noise, int count_decimals) {
  out << " " << fixed(mean_iou, 3) << " | " << fixed(weighted_iou, 3) << " | "
      << fixed(correct, count_decimals) << " | " << fixed(over, count_decimals) << " | "
      << fixed(under, count_decimals) << " | " << fixed(missed, count_decimals) << " | "
      << fixed(noise, count_decimals) << " |";
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
  std::ostringstream out;
  const bool accuracy = anyGroundTruth(report);
  const bool normals = anyPart(report, "normals");
  const std::vector<std::string> order = methodOrder(report);

  out << "## Runtime" << (accuracy ? " and accuracy" : "") << "\n\n";
  out << "| scene | method | median ms | min ms | x floodplane |"
      << (normals ? " normals ms |" : "") << " planes |";
  if (accuracy) {
    out << " mean IoU | weighted IoU | correct | over | under | missed | noise |";
  }
  out << "\n|---|---|---:|---:|---:|" << (normals ? "---:|" : "") << "---:|";
  if (accuracy) {
    out << "---:|---:|---:|---:|---:|---:|---:|";
  }
  out << "\n";
  std::map<std::string, MeanRow> means;
  for (const SceneResult& scene : report.scenes) {
    for (const MethodResult& result : scene.methods) {
      means[result.method].add(scene, result);
      out << "| " << scene.name << " | " << result.method << " | "
          << fixed(result.timing.median_ms, 2) << " | " << fixed(result.timing.min_ms, 2)
          << " | " << fixed(ratioToFloodplane(scene, result), 2) << " |";
      if (normals) {
        out << " " << fixed(partMs(result.timing, "normals"), 2) << " |";
      }
      out << " " << result.planes << " |";
      if (accuracy) {
        if (result.scores) {
          const auto& s = *result.scores;
          accuracyCells(out, s.mean_iou, s.weighted_iou, static_cast<double>(s.hoover.correct),
                        static_cast<double>(s.hoover.over), static_cast<double>(s.hoover.under),
                        static_cast<double>(s.hoover.missed),
                        static_cast<double>(s.hoover.noise), 0);
        } else {
          out << " - | - | - | - | - | - | - |";
        }
      }
      out << "\n";
    }
  }
  for (const std::string& method : order) {
    const MeanRow& row = means[method];
    out << "| **mean** (" << row.scenes << " scenes) | " << method << " | "
        << fixed(row.time(row.median_ms), 2) << " | " << fixed(row.time(row.min_ms), 2) << " | "
        << fixed(row.ratio(), 2) << " |";
    if (normals) {
      const auto part = row.parts_ms.find("normals");
      out << " " << fixed(part != row.parts_ms.end() ? row.time(part->second) : kNaN, 2) << " |";
    }
    out << " " << fixed(row.time(row.planes), 1) << " |";
    if (accuracy) {
      accuracyCells(out, row.accuracy(row.mean_iou), row.accuracy(row.weighted_iou),
                    row.accuracy(row.correct), row.accuracy(row.over), row.accuracy(row.under),
                    row.accuracy(row.missed), row.accuracy(row.noise), 1);
    }
    out << "\n";
  }
  out << "\n";

  bool any_resolutions = false;
  bool any_phases = false;
  for (const SceneResult& scene : report.scenes) {
    any_resolutions = any_resolutions || !scene.resolutions.empty();
    any_phases = any_phases || scene.phases.has_value();
  }
  if (any_resolutions) {
    out << "## floodplane by sub-sampling factor (Table III)\n\n"
        << "| scene | sub-sampling | median ms | min ms | speed-up over 1 | planes |"
        << (accuracy ? " mean IoU | weighted IoU |" : "") << "\n"
        << "|---|---:|---:|---:|---:|---:|" << (accuracy ? "---:|---:|" : "") << "\n";
    std::map<int, MeanRow> factor_means;
    std::map<int, double> speedup_sums;
    for (const SceneResult& scene : report.scenes) {
      double full = kNaN;
      for (const auto& [factor, result] : scene.resolutions) {
        if (factor == 1) {
          full = result.timing.median_ms;
        }
      }
      for (const auto& [factor, result] : scene.resolutions) {
        factor_means[factor].add(scene, result);
        speedup_sums[factor] += full / result.timing.median_ms;
        out << "| " << scene.name << " | " << factor << " | " << fixed(result.timing.median_ms, 2)
            << " | " << fixed(result.timing.min_ms, 2) << " | "
            << fixed(full / result.timing.median_ms, 2) << " | " << result.planes << " |";
        if (accuracy) {
          out << " " << (result.scores ? fixed(result.scores->mean_iou, 3) : kNone) << " | "
              << (result.scores ? fixed(result.scores->weighted_iou, 3) : kNone) << " |";
        }
        out << "\n";
      }
    }
    for (const auto& [factor, row] : factor_means) {
      out << "| **mean** (" << row.scenes << " scenes) | " << factor << " | "
          << fixed(row.time(row.median_ms), 2) << " | " << fixed(row.time(row.min_ms), 2)
          << " | " << fixed(row.time(speedup_sums[factor]), 2) << " | "
          << fixed(row.time(row.planes), 1) << " |";
      if (accuracy) {
        out << " " << fixed(row.accuracy(row.mean_iou), 3) << " | "
            << fixed(row.accuracy(row.weighted_iou), 3) << " |";
      }
      out << "\n";
    }
    out << "\n";
  }

  if (any_phases) {
    out << "## floodplane's time by phase (Fig. 5), share of the phases' total\n\n"
        << "| scene | seed selection | flood fill | relabelling | merging | region output | "
           "phases ms | call ms |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    floodplane::PhaseTimes sum;
    double call_sum = 0.0;
    std::size_t count = 0;
    const auto row = [&out](const std::string& name, const floodplane::PhaseTimes& phases,
                            double call_ms) {
      const double total = phases.total();
      out << "| " << name << " |";
      for (const auto& [key, member] : kPhases) {
        (void)key;
        out << " " << fixed(total > 0.0 ? 100.0 * (phases.*member) / total : kNaN, 1) << "% |";
      }
      out << " " << fixed(total, 2) << " | " << fixed(call_ms, 2) << " |\n";
    };
    for (const SceneResult& scene : report.scenes) {
      if (!scene.phases) {
        continue;
      }
      row(scene.name, scene.phases->median, scene.phases->call_median_ms);
      for (const auto& [key, member] : kPhases) {
        (void)key;
        sum.*member += scene.phases->median.*member;
      }
      call_sum += scene.phases->call_median_ms;
      ++count;
    }
    floodplane::PhaseTimes mean;
    for (const auto& [key, member] : kPhases) {
      (void)key;
      mean.*member = sum.*member / static_cast<double>(count);
    }
    row("**mean** (" + std::to_string(count) + " scenes)", mean,
        call_sum / static_cast<double>(count));
    out << "\n";
  }
  return out.str();
}

std::string csvReport(const Report& report) {
  std::ostringstream out;
  out << "scene,file,method,subsampling,width,height,median_ms,min_ms,ratio_to_floodplane,"
         "normals_ms,planes,mean_iou,weighted_iou,correct,over,under,missed,noise\n";
  const auto line = [&out](const SceneResult& scene, const MethodResult& result, int factor,
                           double ratio) {
    // Scene names come from file names; quote them in case they hold commas.
    out << '"' << scene.name << "\",\"" << scene.path << "\"," << result.method << "," << factor
        << "," << scene.width << "," << scene.height << "," << fixed(result.timing.median_ms, 4)
        << "," << fixed(result.timing.min_ms, 4) << "," << fixed(ratio, 4) << ","
        << fixed(partMs(result.timing, "normals"), 4) << "," << result.planes << ",";
    if (result.scores) {
      const auto& s = *result.scores;
      out << fixed(s.mean_iou, 6) << "," << fixed(s.weighted_iou, 6) << "," << s.hoover.correct
          << "," << s.hoover.over << "," << s.hoover.under << "," << s.hoover.missed << ","
          << s.hoover.noise;
    } else {
      out << ",,,,,,";
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

std::string jsonReport(const Report& report) {
  nlohmann::json json;
  for (const auto& [key, value] : report.configuration) {
    json["configuration"][key] = value;
  }
  json["scenes"] = nlohmann::json::array();
  std::map<std::string, MeanRow> means;
  for (const SceneResult& scene : report.scenes) {
    nlohmann::json entry = {{"name", scene.name},
                            {"file", scene.path},
                            {"width", scene.width},
                            {"height", scene.height},
                            {"ground_truth", scene.has_ground_truth},
                            {"min_points", scene.min_points},
                            {"methods", nlohmann::json::object()}};
    for (const MethodResult& result : scene.methods) {
      entry["methods"][result.method] = resultJson(scene, result);
      means[result.method].add(scene, result);
    }
    for (const auto& [factor, result] : scene.resolutions) {
      entry["resolutions"][std::to_string(factor)] = resultJson(scene, result);
    }
    if (scene.phases) {
      nlohmann::json phases;
      const double total = scene.phases->median.total();
      for (const auto& [key, member] : kPhases) {
        phases["median_ms"][key] = scene.phases->median.*member;
        phases["share"][key] = number(total > 0.0 ? (scene.phases->median.*member) / total : kNaN);
      }
      phases["phases_total_ms"] = total;
      phases["call_median_ms"] = scene.phases->call_median_ms;
      entry["phases"] = phases;
    }
    json["scenes"].push_back(entry);
  }
  json["means"] = nlohmann::json::object();
  for (const auto& [method, row] : means) {
    json["means"][method] = {{"scenes", row.scenes},
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
                               {"noise", number(row.accuracy(row.noise))}}}};
  }
  json["failed"] = report.failed;
  return json.dump(2) + "\n";
}

}  // namespace pcd_compare
