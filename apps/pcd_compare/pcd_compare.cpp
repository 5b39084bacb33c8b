// pcd_compare: runs floodplane, PCL's sequential RANSAC and PCL's OrganizedMultiPlaneSegmentation
// on organized PCD files and reports their runtime and, where the file carries ground-truth
// labels, their accuracy (the project's metrics.md definitions, floodplane_eval).
// Argument parsing, the timing protocol and output only; the methods are in *_method.cpp.

#include <CLI/CLI.hpp>
#include <pcl/pcl_config.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/cli.h"
#include "common/display_check.h"
#include "comparison_image.h"
#include "comparison_image_3d.h"
#include "eval/segmentation_metrics.h"
#include "io/atomic_file.h"
#include "io/png_file.h"
#include "floodplane/version.h"
#include "input_cloud.h"
#include "io/input_files.h"
#include "method.h"
#include "report.h"
#include "tuning.h"

namespace {

namespace fs = std::filesystem;
using namespace pcd_compare;

constexpr double kTolerance = 0.8;  // Hoover's T, metrics.md's default

struct Options {
  std::vector<std::string> inputs;
  std::vector<std::string> methods;
  int repeat = 20;
  std::string csv_file;
  std::string json_file;
  std::string png_dir;
  std::string png3d_dir;
  bool resolutions = false;
  bool phases = false;
  bool quiet = false;
  bool tuned = false;  // also the baselines at their tuned values
  std::string tuned_file = FLOODPLANE_TUNED_BASELINES;
  std::string tune_dir;          // tune the baselines on this folder instead of comparing
  std::string tune_grid_file;    // the grid to search (default: defaultGrid())
  std::size_t tune_clouds = 12;  // clouds per sensor model in the tuning subset
};

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> items;
  std::istringstream stream(list);
  for (std::string item; std::getline(stream, item, ',');) {
    if (!item.empty()) {
      items.push_back(item);
    }
  }
  return items;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string compilerName() {
#if defined(__clang__)
  return std::string("clang ") + __VERSION__;
#elif defined(__GNUC__)
  return std::string("GCC ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}

// One warm-up run, whose labels are scored (every method is deterministic), then `repeat`
// timed runs of the segmentation call alone. With `repeat` 0 the scored run is the one timed
// run: for large folders, where accuracy needs one run and a cold time is good enough.
struct Measured {
  MethodRun first;
  Timing timing;
  std::vector<MethodRun> runs;  // the timed runs, without labels
};

Measured measure(Method& method, const Cloud::ConstPtr& cloud, int repeat) {
  Measured measured;
  measured.first = method.run(cloud);
  std::vector<double> totals;
  std::vector<std::vector<double>> parts(measured.first.parts_ms.size());
  for (int r = 0; r < std::max(repeat, 1); ++r) {
    MethodRun run = repeat > 0 ? method.run(cloud) : measured.first;
    totals.push_back(run.total_ms);
    for (std::size_t k = 0; k < parts.size() && k < run.parts_ms.size(); ++k) {
      parts[k].push_back(run.parts_ms[k].second);
    }
    run.labels.clear();
    run.labels.shrink_to_fit();
    measured.runs.push_back(std::move(run));
  }
  measured.timing.median_ms = median(totals);
  measured.timing.min_ms = *std::min_element(totals.begin(), totals.end());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    measured.timing.parts_median_ms.emplace_back(measured.first.parts_ms[k].first, median(parts[k]));
  }
  return measured;
}

std::size_t distinctPlanes(const std::vector<std::uint32_t>& labels) {
  std::set<std::uint32_t> planes(labels.begin(), labels.end());
  planes.erase(0);
  return planes.size();
}

MethodResult evaluate(const std::string& name, const Measured& measured, const InputCloud& input,
                      std::uint32_t min_points) {
  MethodResult result;
  result.method = name;
  result.timing = measured.timing;
  result.planes = distinctPlanes(measured.first.labels);
  if (input.ground_truth) {
    floodplane::eval::MetricsOptions options;
    options.min_points = min_points;
    options.tolerance = kTolerance;
    result.scores =
        floodplane::eval::evaluateSegmentation(*input.ground_truth, measured.first.labels, input.valid, options);
  }
  return result;
}

// Every method --methods can name, in the order of the default list.
const std::vector<std::string> kMethodNames = {"floodplane", "floodplane/2", "ransac", "open3d_ransac", "omps"};

bool isMethodName(const std::string& name) {
  return std::find(kMethodNames.begin(), kMethodNames.end(), name) != kMethodNames.end();
}

std::unique_ptr<Method> makeMethod(const std::string& name) {
  if (name == "floodplane") return makeFloodplaneMethod(1);
  if (name == "floodplane/2") return makeFloodplaneMethod(2);
  if (name == "ransac") return makeRansacMethod();
  if (name == "open3d_ransac") return makeOpen3dRansacMethod();
  return makeOmpsMethod();
}

// A baseline at its tuned values: one instance per sensor model of the tuning file.
struct TunedMethod {
  std::string name;  // "<baseline> (tuned)"
  std::map<std::string, std::unique_ptr<Method>> by_sensor;
};

struct Methods {
  std::vector<std::unique_ptr<Method>> selected;                    // in --methods order
  std::vector<TunedMethod> tuned;                                   // --tuned, in --methods order
  std::vector<std::pair<int, std::unique_ptr<Method>>> subsampled;  // floodplane at 2, 4, 8
  std::unique_ptr<Method> full_resolution;                          // floodplane at 1 when not selected
  std::unique_ptr<Method> phase_timer;                              // floodplane with its phase timer
};

// The baselines among --methods at the values of the tuning file, per sensor model.
std::vector<TunedMethod> makeTunedMethods(const Options& options) {
  const TunedValues tuned = readTunedValues(options.tuned_file);
  std::vector<TunedMethod> methods;
  for (const std::string& name : options.methods) {
    const Baseline* baseline = findBaseline(name);
    const auto entry = tuned.by_method_and_sensor.find(name);
    if (baseline == nullptr || entry == tuned.by_method_and_sensor.end()) continue;
    TunedMethod method{name + " (tuned)", {}};
    for (const auto& [sensor, values] : entry->second) {
      method.by_sensor.emplace(sensor, baseline->make(values, method.name));
    }
    methods.push_back(std::move(method));
  }
  return methods;
}

Methods makeMethods(const Options& options) {
  Methods methods;
  for (const std::string& name : options.methods) methods.selected.push_back(makeMethod(name));
  if (options.tuned) methods.tuned = makeTunedMethods(options);
  if (options.resolutions) {
    for (const int factor : {2, 4, 8}) {
      methods.subsampled.emplace_back(factor, makeFloodplaneMethod(factor));
    }
    const bool have_floodplane =
        std::find(options.methods.begin(), options.methods.end(), "floodplane") != options.methods.end();
    if (!have_floodplane) {
      methods.full_resolution = makeFloodplaneMethod(1);
    }
  }
  if (options.phases) {
    // A separate instance and separate runs: the phase timer's clock reads must not be in
    // the timings of the main table.
    methods.phase_timer = makeFloodplaneMethod(1, true);
  }
  return methods;
}

std::vector<std::pair<std::string, std::string>> configuration(const Options& options, const Methods& methods) {
  std::vector<std::pair<std::string, std::string>> config;
  config.emplace_back("floodplane", FLOODPLANE_VERSION_STRING);
  config.emplace_back("PCL", PCL_VERSION_PRETTY);
  config.emplace_back("compiler", compilerName());
  config.emplace_back("build type", FLOODPLANE_BUILD_TYPE);
  const std::string runs = options.repeat > 0
                               ? "median and min of " + std::to_string(options.repeat) + " runs after one warm-up"
                               : "one run per method and file (--repeat 0: no warm-up)";
  config.emplace_back("timing", runs +
                                    ", of the segmentation call alone (cloud in "
                                    "memory; OMPS includes its normal estimation), one thread, "
                                    "steady_clock");
  config.emplace_back("accuracy",
                      "for files with a `label` field: IoU, weighted IoU, Hoover counts "
                      "(T = 0.8) and false-plane fraction as in metrics.md; pixels with NaN xyz "
                      "ignored; planes and segments below round(500 * W*H / (640*480)) pixels "
                      "ignored; labels of the warm-up run; means per method, and per sensor "
                      "model for files named <scene>.<sensor>.pcd");
  for (const auto& method : methods.selected) {
    config.emplace_back("method " + method->name(), method->parameters());
  }
  for (const TunedMethod& tuned : methods.tuned) {
    for (const auto& [sensor, method] : tuned.by_sensor) {
      config.emplace_back("method " + tuned.name + " [" + sensor + "]",
                          method->parameters() + "; from " + options.tuned_file);
    }
  }
  for (const auto& [factor, method] : methods.subsampled) {
    (void)factor;
    config.emplace_back("method " + method->name(), method->parameters());
  }
  if (methods.phase_timer) {
    config.emplace_back("phases", methods.phase_timer->parameters() + "; separate runs, not those of the main table");
  }
  return config;
}

// Ground truth and the methods of --methods in a fixed order, whichever of them ran.
std::vector<Panel> comparisonPanels(const InputCloud& input,
                                    const std::vector<std::pair<std::string, const MethodRun*>>& runs,
                                    const SceneResult& scene) {
  static const std::vector<std::string> kOrder = {"ransac", "open3d_ransac", "omps", "floodplane/2", "floodplane"};
  std::vector<Panel> panels;
  const std::vector<std::uint32_t> no_ground_truth;
  const std::vector<std::uint32_t>& ground_truth = input.ground_truth ? *input.ground_truth : no_ground_truth;
  if (input.ground_truth) {
    std::vector<std::uint32_t> shown = ground_truth;
    // Pixels without a point show as "no plane", as they do in the predictions.
    for (std::size_t i = 0; i < shown.size(); ++i) {
      shown[i] = input.valid[i] != 0 ? shown[i] : 0;
    }
    panels.push_back({"ground truth", std::move(shown), {}});
  }
  for (const std::string& name : kOrder) {
    for (std::size_t k = 0; k < runs.size(); ++k) {
      if (runs[k].first != name) {
        continue;
      }
      std::string title = name;
      const MethodResult& result = scene.methods[k];
      if (result.scores && !result.scores->planes.empty()) {
        std::ostringstream text;
        text.precision(3);
        text << std::fixed << name << "  IoU " << result.scores->mean_iou;
        title = text.str();
      }
      panels.push_back({title, coloursMatchedToGroundTruth(runs[k].second->labels, ground_truth, input.valid),
                        runs[k].second->labels});
    }
  }
  return panels;
}

// <scene>.png in --png's directory (label images) and in --png3d's (3-D renderings).
void writeComparisonImages(const Options& options, const InputCloud& input,
                           const std::vector<std::pair<std::string, const MethodRun*>>& runs,
                           const SceneResult& scene) {
  const std::vector<Panel> panels = comparisonPanels(input, runs, scene);
  if (panels.empty()) {
    return;
  }
  if (!options.png_dir.empty()) {
    fs::create_directories(options.png_dir);
    floodplane::io::writePng((fs::path(options.png_dir) / (scene.name + ".png")).string(),
                             comparisonImage(panels, input.cloud->width, input.cloud->height));
  }
  if (!options.png3d_dir.empty()) {
    fs::create_directories(options.png3d_dir);
    floodplane::io::writePng((fs::path(options.png3d_dir) / (scene.name + ".png")).string(),
                             comparisonImage3d(panels, input.cloud, scene.min_points));
  }
}

// floodplane at sub-sampling 1 (from the main table when it ran there), 2, 4 and 8.
std::vector<std::pair<int, MethodResult>> measureResolutions(const Options& options, Methods& methods,
                                                             const InputCloud& input, const SceneResult& scene) {
  std::vector<std::pair<int, MethodResult>> resolutions;
  const auto floodplane = std::find_if(scene.methods.begin(), scene.methods.end(),
                                       [](const MethodResult& r) { return r.method == "floodplane"; });
  if (floodplane != scene.methods.end()) {
    resolutions.emplace_back(1, *floodplane);
  } else {
    const Measured full = measure(*methods.full_resolution, input.cloud, options.repeat);
    resolutions.emplace_back(1, evaluate("floodplane", full, input, scene.min_points));
  }
  for (const auto& [factor, method] : methods.subsampled) {
    const Measured sub = measure(*method, input.cloud, options.repeat);
    resolutions.emplace_back(factor, evaluate(method->name(), sub, input, scene.min_points));
  }
  return resolutions;
}

// Each phase's median over the timed runs of the phase timer's instance.
PhaseResult measurePhases(Method& phase_timer, const InputCloud& input, int repeat) {
  const Measured timed = measure(phase_timer, input.cloud, repeat);
  PhaseResult phases;
  phases.call_median_ms = timed.timing.median_ms;
  const auto phaseMedian = [&timed](double floodplane::PhaseTimes::*phase) {
    std::vector<double> times;
    for (const MethodRun& run : timed.runs) times.push_back((*run.phases).*phase);
    return median(times);
  };
  for (const auto& [key, member] : phaseMembers()) {
    (void)key;
    phases.median.*member = phaseMedian(member);
  }
  return phases;
}

SceneResult compareScene(const Options& options, Methods& methods, const InputCloud& input) {
  SceneResult scene;
  scene.name = input.name;
  scene.path = input.path;
  scene.sensor = input.sensor;
  scene.width = input.cloud->width;
  scene.height = input.cloud->height;
  scene.has_ground_truth = input.ground_truth.has_value();
  scene.min_points = floodplane::eval::defaultMinPoints(scene.width, scene.height);

  std::vector<Measured> measured;
  for (const auto& method : methods.selected) {
    measured.push_back(measure(*method, input.cloud, options.repeat));
    scene.methods.push_back(evaluate(method->name(), measured.back(), input, scene.min_points));
  }
  for (const TunedMethod& tuned : methods.tuned) {
    const auto method = tuned.by_sensor.find(input.sensor);
    if (method == tuned.by_sensor.end()) {
      if (!options.quiet) std::cerr << "pcd_compare: " << input.name << ": no tuned values of " << tuned.name << "\n";
      continue;
    }
    const Measured run = measure(*method->second, input.cloud, options.repeat);
    scene.methods.push_back(evaluate(tuned.name, run, input, scene.min_points));
  }
  if (options.resolutions) scene.resolutions = measureResolutions(options, methods, input, scene);
  if (methods.phase_timer) scene.phases = measurePhases(*methods.phase_timer, input, options.repeat);
  if (!options.png_dir.empty() || !options.png3d_dir.empty()) {
    std::vector<std::pair<std::string, const MethodRun*>> runs;
    for (std::size_t k = 0; k < methods.selected.size(); ++k) {
      runs.emplace_back(methods.selected[k]->name(), &measured[k].first);
    }
    writeComparisonImages(options, input, runs, scene);
  }
  return scene;
}

constexpr const char* kDescription =
    "Compares plane segmentations of organized PCD files: floodplane (at sub-sampling 1 and "
    "2), PCL's sequential RANSAC, Open3D's sequential RANSAC and PCL's "
    "OrganizedMultiPlaneSegmentation, the baselines also at tuned values (--tuned, from "
    "--tune). Prints the configuration, then Markdown tables of runtimes (median and min over "
    "--repeat runs after a warm-up) and, for files with a ground-truth `label` field, "
    "accuracy: mean and weighted IoU, Hoover counts and the false-plane fraction, as means "
    "(over all files, then per sensor model for files named <scene>.<sensor>.pcd), per file "
    "and method. INPUT is a PCD file or a directory (its *.pcd files, sorted).";

// The methods named in --methods, each once: a method named twice would be timed twice and
// collide in the tables.
std::vector<std::string> uniqueMethods(const std::string& method_list) {
  std::vector<std::string> methods;
  for (const std::string& name : splitList(method_list)) {
    if (std::find(methods.begin(), methods.end(), name) == methods.end()) methods.push_back(name);
  }
  return methods;
}

void addInputAndMethodOptions(CLI::App& app, Options& options, std::string& method_list) {
  // No existence check here: a missing file is reported with the others, and the batch goes on.
  app.add_option("inputs", options.inputs, "PCD files or directories of *.pcd (required unless --tune)");
  // One comma-separated token, split here: a vector option would also swallow the INPUTs
  // that follow it ("--methods omps scene.pcd").
  app.add_option("--methods", method_list, "Methods to run, comma-separated, from " + joined(kMethodNames))
      ->check([](const std::string& list) -> std::string {
        for (const std::string& name : splitList(list)) {
          if (!isMethodName(name)) return "unknown method '" + name + "' (use " + joined(kMethodNames) + ")";
        }
        return splitList(list).empty() ? "no method given" : "";
      })
      ->capture_default_str();
  app.add_option("--repeat", options.repeat,
                 "Timed runs per method and file, after one warm-up; 0: one run only, timed and scored "
                 "(for large folders)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

void addTuningOptions(CLI::App& app, Options& options) {
  app.add_flag("--tuned", options.tuned,
               "Also run each baseline among --methods at its tuned values (a row '<method> (tuned)'), "
               "those of the scene's sensor model in --tuned-file");
  app.add_option("--tuned-file", options.tuned_file, "The tuned values: written by --tune, read by --tuned")
      ->capture_default_str();
  app.add_option("--tune", options.tune_dir,
                 "Instead of comparing: tune the baselines among --methods on this folder of "
                 "<scene>.<sensor>.pcd files with labels (never the report split), maximising mean IoU "
                 "per sensor model, and write --tuned-file")
      ->check(CLI::ExistingDirectory);
  app.add_option("--tune-grid", options.tune_grid_file,
                 "JSON file of the values to try: {\"omps\": {\"angular_threshold\": [0.05, 0.09]}, ...}; "
                 "only the baselines it names are tuned (default: the built-in grid)")
      ->check(CLI::ExistingFile);
  app.add_option("--tune-clouds", options.tune_clouds, "Clouds per sensor model in the tuning subset")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

void addOutputOptions(CLI::App& app, Options& options) {
  app.add_option("--csv", options.csv_file, "Also write the rows as CSV to this file");
  app.add_option("--json", options.json_file, "Also write everything as JSON to this file");
  app.add_option("--png", options.png_dir,
                 "Write <scene>.png per file into this directory: ground truth | ransac | open3d_ransac | "
                 "omps | floodplane/2 | floodplane (those run), segments coloured by the ground-truth plane "
                 "they overlap most");
  // A picture of its own rather than a 3-D row under --png's: --png keeps working without a
  // display (CI, headless machines), and each picture stays one row of panels wide.
  app.add_option("--png3d", options.png3d_dir,
                 "Write <scene>.png per file into this directory: the panels of --png rendered in 3-D "
                 "(seen from above and to the right of the sensor, an arrow along each segment's normal). "
                 "Needs an X display: on a machine without one, run under xvfb-run -a");
  app.add_flag("--resolutions", options.resolutions, "Also run floodplane at sub-sampling 1, 2, 4, 8 (Table III)");
  app.add_flag("--phases", options.phases, "Also report floodplane's time per phase (Fig. 5), from separate runs");
  app.add_flag("-q,--quiet", options.quiet, "Print no configuration and no progress: only the tables and errors");
}

// Compares every input, going on past files that cannot be read (listed in report.failed).
void compareAll(const Options& options, Methods& methods, Report& report) {
  const std::vector<floodplane::io::InputFile> files = floodplane::io::expandInputs(options.inputs);
  std::set<std::string> names;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const floodplane::io::InputFile& file = files[i];
    if (!options.quiet && files.size() > 1) {
      std::cerr << "pcd_compare: [" << i + 1 << "/" << files.size() << "] " << file.path << "\n";
    }
    try {
      if (!file.error.empty()) throw std::runtime_error(file.error);
      InputCloud input = loadInputCloud(file.path);
      // Scenes are named by their file name; two files of one name from different
      // directories would share a row label and an image file.
      if (!names.insert(input.name).second) {
        input.name = fs::path(file.path).parent_path().filename().string() + "/" + input.name;
        std::replace(input.name.begin(), input.name.end(), '/', '_');
      }
      report.scenes.push_back(compareScene(options, methods, input));
    } catch (const std::exception& error) {
      std::cerr << "pcd_compare: error: " << file.path << ": " << error.what() << "\n";
      report.failed.push_back(file.path);
    }
  }
}

// Writes the CSV and JSON files asked for; false if one could not be written (said on stderr).
bool writeReportFiles(const Options& options, const Report& report) {
  try {
    if (!options.csv_file.empty()) floodplane::io::writeBytesAtomically(options.csv_file, csvReport(report));
    if (!options.json_file.empty()) floodplane::io::writeBytesAtomically(options.json_file, jsonReport(report));
  } catch (const std::exception& error) {
    std::cerr << "pcd_compare: error: " << error.what() << "\n";
    return false;
  }
  return true;
}

void printFailures(const Report& report) {
  if (report.failed.empty()) return;
  std::cerr << "pcd_compare: " << report.failed.size() << " of " << report.failed.size() + report.scenes.size()
            << " files failed:";
  for (const std::string& file : report.failed) std::cerr << " " << file;
  std::cerr << "\n";
}

// --tune: the grid (the file's, or the built-in one for the baselines among --methods), the
// search, the file. Returns the exit code.
int tune(const Options& options) {
  try {
    Grid grid = options.tune_grid_file.empty() ? defaultGrid() : readGrid(options.tune_grid_file);
    for (auto entry = grid.begin(); entry != grid.end();) {
      const bool selected =
          std::find(options.methods.begin(), options.methods.end(), entry->first) != options.methods.end();
      entry = selected ? std::next(entry) : grid.erase(entry);
    }
    if (grid.empty()) throw std::runtime_error("--methods names no baseline of the grid to tune");
    TuningOptions tuning;
    tuning.folder = options.tune_dir;
    tuning.grid = std::move(grid);
    tuning.output_file = options.tuned_file;
    tuning.clouds_per_sensor = options.tune_clouds;
    std::ostringstream discard;
    tuneBaselines(tuning, options.quiet ? discard : std::cerr);
  } catch (const std::exception& error) {
    std::cerr << "pcd_compare: error: " << error.what() << "\n";
    return 1;
  }
  if (!options.quiet) std::cerr << "pcd_compare: wrote " << options.tuned_file << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::string method_list = joined(kMethodNames, ",");
  CLI::App app{kDescription, "pcd_compare"};
  floodplane::apps::addVersionFlag(app);
  addInputAndMethodOptions(app, options, method_list);
  addOutputOptions(app, options);
  addTuningOptions(app, options);
  if (const std::optional<int> exit_code = floodplane::apps::parseCommandLine(app, argc, argv)) return *exit_code;
  options.methods = uniqueMethods(method_list);
  if (!options.tune_dir.empty()) return tune(options);
  if (options.inputs.empty()) return floodplane::apps::usageError(app, "no INPUT given");
  if (!options.png3d_dir.empty()) {
    // Before any work: the comparison can take minutes, and every image would fail alike.
    if (const std::optional<std::string> reason = floodplane::view::renderingUnavailableReason()) {
      std::cerr << "pcd_compare: error: --png3d cannot draw in 3-D: " << *reason << "\n";
      return 1;
    }
  }

  Methods methods;
  try {
    methods = makeMethods(options);
  } catch (const std::exception& error) {
    std::cerr << "pcd_compare: error: " << error.what() << "\n";
    return 1;
  }
  Report report;
  report.configuration = configuration(options, methods);
  if (!options.quiet) std::cout << markdownConfiguration(report) << std::flush;
  compareAll(options, methods, report);
  std::cout << markdownTables(report) << std::flush;
  const bool written = writeReportFiles(options, report);
  printFailures(report);
  return report.failed.empty() && written ? 0 : 1;
}
