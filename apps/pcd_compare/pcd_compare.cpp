// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_compare: runs floodplane, PCL's sequential RANSAC and OMPS and Open3D's sequential RANSAC
// on organized PCD files and reports their runtime and, where a file carries ground-truth
// labels, their accuracy (the project's metrics.md, floodplane_eval); with --objects, the object
// methods (the objects on the planes) scored against object labels (object_report.cpp). This file is the driver:
// options, the timing protocol, the loop over files. The methods are in *_method.cpp, the
// report in report.cpp, the pictures in comparison_image.cpp; the baselines' tuning and the
// tables beyond the means are bench/tune_baselines.py and bench/compare_tables.py.

#include <pcl/pcl_config.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli.h"
#include "cli/depth_input.h"
#include "cli/interrupt_cleanup.h"
#include "cli/output_target.h"
#include "comparison_image.h"
#include "eval/segmentation_metrics.h"
#include "floodplane/io/atomic_file.h"
#include "floodplane/io/input_files.h"
#include "floodplane/io/json_text.h"
#include "floodplane/io/labelled_cloud.h"
#include "floodplane/io/output_rule.h"
#include "floodplane/io/pcd_file.h"
#include "floodplane/io/png_file.h"
#include "floodplane/version.h"
#include "input_cloud.h"
#include "label_files.h"
#include "method.h"
#include "object_report.h"
#include "report.h"
#include "view/display_check.h"

namespace {

namespace fs = std::filesystem;
using namespace pcd_compare;

// "floodplane": the library's defaults; "floodplane/s": sub-sampling s (1: every pixel from the
// start).
const std::vector<std::string> kMethods = {"floodplane",   "floodplane/1", "floodplane/2",  "floodplane/4",
                                           "floodplane/8", "ransac",       "open3d_ransac", "omps"};
const std::vector<std::string> kResolutions = {"floodplane/1", "floodplane/2", "floodplane/4", "floodplane/8"};
const std::vector<std::string> kSensors = {"kinect", "scanner", "none"};

struct Options {
  std::vector<std::string> inputs;
  floodplane::cli::DepthInputOptions depth;
  std::optional<floodplane::io::DepthCamera> camera;  // from `depth`, when given
  std::vector<std::string> labels;                    // --labels NAME=DIR, as given
  std::vector<LabelSource> label_sources;             // the same, parsed
  std::string ground_truth_dir;                       // --ground-truth DIR
  std::vector<std::string> methods = {"floodplane", "floodplane/2", "ransac", "open3d_ransac", "omps"};
  int repeat = 20;
  std::uint32_t min_gt_points = 0;  // --min-gt-points; 0: defaultMinPoints of each file's size
  std::string json_file, png_dir, png3d_dir;
  std::string sensor;      // every input's sensor model; empty: from the file name
  std::string tuned_file;  // empty: defaultTunedFile()
  bool resolutions = false, tuned = false, quiet = false, misses = false;
  bool objects = false;                     // --objects: the object methods in place of the plane methods
  std::vector<std::string> object_methods;  // --object-methods; empty: every object method
  std::string objects_dir;                  // --write-objects DIR
};

// The object methods' names, in objectMethods()' order.
std::vector<std::string> objectMethodNames() {
  std::vector<std::string> names;
  for (const auto& entry : objectMethods()) names.push_back(entry.first);
  return names;
}

// `names` in order, each once.
std::vector<std::string> firstOfEach(const std::vector<std::string>& names) {
  std::vector<std::string> once;
  for (const std::string& name : names) {
    if (std::find(once.begin(), once.end(), name) == once.end()) once.push_back(name);
  }
  return once;
}

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

std::unique_ptr<Method> makeMethod(const std::string& name) {
  if (name.rfind("floodplane", 0) == 0)
    return makeFloodplaneMethod(name == "floodplane" ? std::nullopt : std::optional<int>(std::stoi(name.substr(11))));
  return makeBaseline(name, {}, name);
}

// The tuned values' file when --tuned-file is not given: $FLOODPLANE_TUNED_FILE, else the copy
// next to the binary in a build tree, else the installed one (<prefix>/share/floodplane).
std::string defaultTunedFile() {
  if (const char* file = std::getenv("FLOODPLANE_TUNED_FILE"); file != nullptr && *file != '\0') return file;
  std::error_code error;
  const fs::path directory = fs::read_symlink("/proc/self/exe", error).parent_path();
  for (const fs::path& candidate :
       {directory / "tuned_baselines.json", directory.parent_path() / "share/floodplane/tuned_baselines.json"}) {
    if (fs::exists(candidate, error)) return candidate.string();
  }
  throw std::runtime_error(
      "--tuned: no tuned values found next to the binary or in its share/floodplane: "
      "pass --tuned-file or set FLOODPLANE_TUNED_FILE");
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One warm-up run, whose labels are scored (every method is deterministic), then `repeat`
// timed runs of the segmentation call alone. With `repeat` 0, and for slow methods, the scored
// run is the one timed run. Returns the scored run and sets `timing`: median and min of the
// runs' total_ms, the medians of their parts (OMPS: "normals"). [ms]
MethodRun measure(Method& method, const Cloud::ConstPtr& cloud, int repeat, Json& timing) {
  MethodRun first = method.run(cloud);
  const int runs = method.slow() ? 0 : repeat;
  std::vector<double> totals;
  std::vector<std::vector<double>> parts(first.parts_ms.size());
  for (int r = 0; r < std::max(runs, 1); ++r) {
    const MethodRun run = runs > 0 ? method.run(cloud) : first;
    totals.push_back(run.total_ms);
    for (std::size_t k = 0; k < parts.size(); ++k) parts[k].push_back(run.parts_ms.at(k).second);
  }
  timing = {{"median_ms", median(totals)}, {"min_ms", *std::min_element(totals.begin(), totals.end())}};
  for (std::size_t k = 0; k < parts.size(); ++k) timing["parts_median_ms"][first.parts_ms[k].first] = median(parts[k]);
  return first;
}

// The methods to run: those of --methods, and the baselines among them at their tuned values
// (one instance per sensor model of the tuning file).
struct Methods {
  std::vector<std::unique_ptr<Method>> selected;
  using BySensor = std::map<std::string, std::unique_ptr<Method>>;
  std::vector<std::pair<std::string, BySensor>> tuned;  // row name, instance by sensor model
  std::vector<std::unique_ptr<Method>> objects;         // --objects: the object methods
};

Methods makeMethods(const Options& options, Json& configuration) {
  Methods methods;
  if (options.objects) {
    for (const std::string& name : options.object_methods) {
      for (const auto& [known, make] : objectMethods()) {
        if (known == name) methods.objects.push_back(make());
      }
      configuration["object method " + name] = methods.objects.back()->parameters();
    }
    for (const LabelSource& source : options.label_sources) {
      configuration["object method " + source.name] =
          "objects another program wrote (--labels): " + (fs::path(source.directory) / "<stem>.objects.pcd").string() +
          " or <stem>.png per input; not run here, no time";
    }
    return methods;
  }
  for (const std::string& name : options.methods) {
    methods.selected.push_back(makeMethod(name));
    configuration["method " + name] = methods.selected.back()->parameters();
  }
  for (const LabelSource& source : options.label_sources) {
    configuration["method " + source.name] =
        "labels another program wrote (--labels): " + (fs::path(source.directory) / "<stem>.labels.pcd").string() +
        " or <stem>.png per input; not run here, no time";
  }
  if (options.tuned) {
    const TunedValues tuned = readTunedValues(options.tuned_file);
    for (const std::string& name : options.methods) {
      const auto values = tuned.find(name);
      if (values == tuned.end()) continue;
      auto& [row, by_sensor] = methods.tuned.emplace_back(name + " (tuned)", Methods::BySensor{});
      for (const auto& [sensor, parameters] : values->second) {
        by_sensor[sensor] = makeBaseline(name, parameters, row);
        // bench/tune_baselines.py reads the values back from here: "name=value, ...; ".
        configuration["method " + row + " [" + sensor + "]"] =
            describeValues(name, parameters) + "; " + by_sensor[sensor]->parameters() + "; from " + options.tuned_file;
      }
    }
  }
  return methods;
}

// The configuration's accuracy entry of --objects.
std::string objectAccuracy(const Options& options) {
  return std::string(options.ground_truth_dir.empty() ? "for files with a `label` field"
                                                      : "against the ground truth in " + options.ground_truth_dir) +
         ", object labels as mOSD codes them (1-9 the table, from 20 the objects, each label an object, those under "
         "200 pixels left out): object_iou (mean over objects of the IoU with the output object holding most of "
         "it), found (IoU >= 0.8), under (its best output object holds 20 % of another object), over (two output "
         "objects hold 20 % of it each), table in objects (the table's share inside output objects), as "
         "../shared/tools/osd_scores.py --objects; every pixel counts; means over the files";
}

Json configuration(const Options& options) {
  const std::string runs = options.repeat > 0 ? "median and min of " + std::to_string(options.repeat) +
                                                    " runs after one warm-up (the sequential RANSACs: one run)"
                                              : "one run per method and file (--repeat 0: no warm-up)";
  return {{"floodplane", FLOODPLANE_VERSION_STRING},
          {"PCL", PCL_VERSION_PRETTY},
          {"compiler", __VERSION__},
          {"build type", FLOODPLANE_BUILD_TYPE},
          {"timing", runs + ", of the segmentation call alone (cloud in memory; OMPS includes its normal "
                            "estimation), one thread, steady_clock"},
          {"accuracy",
           std::string(options.ground_truth_dir.empty() ? "for files with a `label` field"
                                                        : "against the ground truth in " + options.ground_truth_dir +
                                                              " (<stem>.labels.pcd or <stem>.png)") +
               ": IoU, weighted IoU, Hoover counts (T = 0.8) and false-plane fraction as in metrics.md; pixels "
               "with NaN xyz ignored; planes and segments below " +
               (options.min_gt_points > 0 ? std::to_string(options.min_gt_points) + " pixels (--min-gt-points)"
                                          : std::string("round(500 * W*H / (640*480)) pixels")) +
               " ignored; labels of the warm-up run; means per method, and per sensor model (--sensor, or the "
               "name <scene>.<sensor>.pcd)"}};
}

// <scene>.png in --png's directory (label images) and in --png3d's (3-D renderings): ground
// truth, then the methods that ran in a fixed order, floodplane last.
void writeComparisonImages(const Options& options, const InputCloud& input, const Json& scene,
                           const std::map<std::string, MethodRun>& runs) {
  std::vector<std::string> order = {"ransac", "open3d_ransac", "omps"};
  for (const LabelSource& source : options.label_sources) order.push_back(source.name);
  order.insert(order.end(), {"floodplane/8", "floodplane/4", "floodplane/2", "floodplane/1", "floodplane"});
  std::vector<LabelledPanel> panels;
  for (const std::string& name : order) {
    const auto run = runs.find(name);
    if (run == runs.end()) continue;
    char iou[32] = "";
    const Json& mean_iou = scene["methods"][name].value("mean_iou", Json());
    if (mean_iou.is_number()) std::snprintf(iou, sizeof iou, "  IoU %.3f", mean_iou.get<double>());
    panels.emplace_back(name + iou, run->second.labels);
  }
  for (const bool in_3d : {false, true}) {
    const std::string& directory = in_3d ? options.png3d_dir : options.png_dir;
    if (directory.empty()) continue;
    fs::create_directories(directory);
    floodplane::io::writePng((fs::path(directory) / (input.name + ".png")).string(),
                             comparisonImage(input, panels, scene["min_points"].get<std::size_t>(), in_3d));
  }
}

// Why files got no tuned rows, each reason with the files it applies to.
using MissingTuned = std::map<std::string, std::vector<std::string>>;

// An input's problem that does not stop its comparison (a label file of --labels or
// --ground-truth missing or unusable): said at once, counted in the exit code.
void reportLabelProblem(const InputCloud& input, const std::string& option, const std::string& problem, Json& report) {
  std::cerr << "pcd_compare: error: " << input.path << ": " << option << ": " << problem << "\n";
  report["label_problems"].push_back({{"file", input.path}, {"option", option}, {"problem", problem}});
}

Json compareScene(const Options& options, Methods& methods, const InputCloud& input, MissingTuned& missing,
                  Json& report) {
  const std::uint32_t min_points = options.min_gt_points > 0
                                       ? options.min_gt_points
                                       : floodplane::eval::defaultMinPoints(input.cloud->width, input.cloud->height);
  Json scene = {{"name", input.name},
                {"file", input.path},
                {"width", input.cloud->width},
                {"height", input.cloud->height},
                {"ground_truth", input.ground_truth.has_value()},
                {"min_points", min_points}};
  if (!input.sensor.empty()) scene["sensor"] = input.sensor;
  scene["methods"] = Json::object();
  std::map<std::string, MethodRun> runs;  // the scored runs by row, for the pictures
  const auto compare = [&](Method& method, const std::string& row) {
    Json timing;
    runs[row] = measure(method, input.cloud, options.repeat, timing);
    scene["methods"][row] = methodJson(timing, runs[row].labels, input, min_points);
  };
  for (const auto& method : methods.selected) compare(*method, method->name());
  for (const auto& [row, by_sensor] : methods.tuned) {
    const auto method = by_sensor.find(input.sensor);
    if (method == by_sensor.end()) {
      missing[input.sensor.empty()
                  ? "no sensor model (name the file <scene>.<sensor>.pcd, or pass --sensor " + joined(kSensors, "|") +
                        ")"
                  : "no values of " + row + " for sensor model '" + input.sensor + "' in " + options.tuned_file]
          .push_back(input.name);
      continue;
    }
    compare(*method->second, row);
  }
  for (const LabelSource& source : options.label_sources) {
    try {
      runs[source.name].labels = labelsFromDirectory(source.directory, input);
    } catch (const std::runtime_error& error) {
      runs.erase(source.name);
      reportLabelProblem(input, "--labels " + source.name, error.what(), report);
      continue;
    }
    // Not run here: no time, which the tables show as "-".
    const Json no_time = {{"median_ms", nullptr}, {"min_ms", nullptr}};
    scene["methods"][source.name] = methodJson(no_time, runs[source.name].labels, input, min_points);
  }
  if (!options.png_dir.empty() || !options.png3d_dir.empty()) writeComparisonImages(options, input, scene, runs);
  return scene;
}

// One input under --objects: each object method timed and scored (objectJson), its objects
// written as <write-objects>/<method>/<scene>.objects.pcd on request; then the objects of
// --labels' directories, scored without a time.
Json compareObjects(const Options& options, Methods& methods, const InputCloud& input, Json& report) {
  Json scene = {{"name", input.name},
                {"file", input.path},
                {"width", input.cloud->width},
                {"height", input.cloud->height},
                {"ground_truth", input.ground_truth.has_value()}};
  scene["methods"] = Json::object();
  for (const auto& method : methods.objects) {
    Json timing;
    const MethodRun run = measure(*method, input.cloud, options.repeat, timing);
    scene["methods"][method->name()] = objectJson(timing, run.labels, input);
    if (options.objects_dir.empty()) continue;
    const fs::path directory = fs::path(options.objects_dir) / method->name();
    fs::create_directories(directory);
    floodplane::io::savePcd((directory / (input.name + ".objects.pcd")).string(),
                            floodplane::io::labelledCloud<pcl::PointXYZL>(*input.cloud, run.labels));
  }
  for (const LabelSource& source : options.label_sources) {
    try {
      const Json no_time = {{"median_ms", nullptr}, {"min_ms", nullptr}};
      scene["methods"][source.name] =
          objectJson(no_time, labelsFromDirectory(source.directory, input, ".objects.pcd"), input);
    } catch (const std::runtime_error& error) {
      reportLabelProblem(input, "--labels " + source.name, error.what(), report);
    }
  }
  return scene;
}

std::string minutes(double seconds) {
  char text[32];
  const int whole = static_cast<int>(seconds + 0.5);
  std::snprintf(text, sizeof text, "%d:%02d", whole / 60, whole % 60);
  return text;
}

// The name of each input in the tables and image files, in the order of `files` (empty for
// an input the expansion found bad): its file name without extension, or, for a second file of
// one name from another directory, "<directory>_<name>", so that the two do not share a row
// label and an image file.
std::vector<std::string> sceneNames(const std::vector<floodplane::io::InputFile>& files) {
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (const floodplane::io::InputFile& file : files) {
    std::string name = file.error.empty() ? sceneName(file.path) : "";
    if (!name.empty() && !taken.insert(name).second)
      name = fs::path(file.path).parent_path().filename().string() + "_" + name;
    names.push_back(std::move(name));
  }
  return names;
}

// Compares every input, going on past files that cannot be read (listed in report["failed"])
// and label files that are missing (report["label_problems"]).
void compareAll(const Options& options, const std::vector<floodplane::io::InputFile>& files,
                const std::vector<std::string>& names, Methods& methods, Json& report, MissingTuned& missing) {
  const auto start = Clock::now();
  for (std::size_t i = 0; i < files.size(); ++i) {
    const floodplane::io::InputFile& file = files[i];
    if (!options.quiet && files.size() > 1) {
      const double elapsed = millisecondsSince(start) / 1000.0;  // [s]
      std::cerr << "pcd_compare: [" << i + 1 << "/" << files.size() << "] " << file.path;
      if (i > 0) {
        std::cerr << " (" << minutes(elapsed) << " so far, about "
                  << minutes(elapsed / static_cast<double>(i) * static_cast<double>(files.size() - i)) << " left)";
      }
      std::cerr << std::endl;
    }
    try {
      if (!file.error.empty()) throw std::runtime_error(file.error);
      InputCloud input = loadInputCloud(file.path, options.camera);
      input.name = names[i];
      if (!options.quiet && std::find(input.valid.begin(), input.valid.end(), 1) == input.valid.end()) {
        std::cerr << "pcd_compare: note: " << file.path << ": " << floodplane::cli::kEmptyFrameNote << std::endl;
      }
      if (!options.sensor.empty()) input.sensor = options.sensor;
      if (!options.ground_truth_dir.empty()) {
        input.ground_truth.reset();
        try {
          input.ground_truth = labelsFromDirectory(options.ground_truth_dir, input);
        } catch (const std::runtime_error& error) {
          reportLabelProblem(input, "--ground-truth", error.what(), report);
        }
      }
      report["scenes"].push_back(options.objects ? compareObjects(options, methods, input, report)
                                                 : compareScene(options, methods, input, missing, report));
    } catch (const std::exception& error) {
      std::cerr << "pcd_compare: error: " << file.path << ": " << error.what() << "\n";
      report["failed"].push_back(file.path);
    }
  }
}

constexpr const char* kDescription =
    "Compares plane segmentations of organized PCD files and 16-bit depth PNG images (with --intrinsics): "
    "floodplane, PCL's and Open3D's sequential RANSAC, PCL's OrganizedMultiPlaneSegmentation (omps), and any "
    "other method whose labels are in files (--labels). Prints the configuration and the means per method, over "
    "all files and per sensor model: runtime and planes found and, for files with ground truth (a `label` field "
    "in the PCD, or --ground-truth), mean and weighted IoU, Hoover counts and the false-plane fraction; without "
    "ground truth the tables have the time and plane columns only. --json has every file and plane; "
    "bench/compare_tables.py makes the per-file tables and CSV from it, bench/tune_baselines.py tunes the "
    "baselines. With --objects it compares object segmentations instead (the objects on the planes: PCL's "
    "organized tabletop pipeline and LCCP), scored against object labels as the mOSD frames carry them. An output "
    "that would overwrite a file the run reads is refused before any work; on Ctrl-C or SIGTERM the unfinished "
    "outputs are removed and pcd_compare ends by that signal (a shell's status 130 or 143).";

// The naming rule of label files (label_files.h), for --labels' and --ground-truth's help.
constexpr const char* kLabelFiles =
    "DIR holds, for each input <stem>.pcd or <stem>.png, exactly one of <stem>.labels.pcd (x y z and a 32-bit "
    "unsigned label field on the input's grid, as pcd_segment -o DIR writes) or <stem>.png (a grey 8- or 16-bit "
    "image of the input's size whose pixel values are the labels); label 0 is no plane";

// CLI11's check for a count of pixels >= 1 that fits the metrics' 32 bits: "" when `value` is
// one, else the reason, which CLI11 reports after the flag's name.
std::string wholePixelCount(const std::string& value) {
  const bool digits = !value.empty() && value.size() <= 10 &&
                      std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (digits && std::stoull(value) >= 1 && std::stoull(value) <= std::numeric_limits<std::uint32_t>::max()) return "";
  return "N must be a whole number of pixels from 1 to " + std::to_string(std::numeric_limits<std::uint32_t>::max()) +
         ", got '" + value + "'";
}

// --objects and its options, which the plane comparison's own options exclude.
void addObjectOptions(CLI::App& app, Options& options) {
  const std::vector<std::string> names = objectMethodNames();
  CLI::Option* objects = app.add_flag(
      "--objects", options.objects,
      "Compare object segmentations (the objects standing on the planes) instead of planes: run --object-methods "
      "and score their objects against the ground truth's object labels as the mOSD frames carry them (`label`: "
      "0 nothing, 1-9 the table, 20-29 the first object, 30-39 the second, ...; or --ground-truth): object_iou, "
      "found, under, over, table in objects (../shared/tools/osd_scores.py --objects)");
  app.add_option("--object-methods", options.object_methods,
                 "With --objects, the object methods to run, comma-separated, of " + joined(names) +
                     " (the configuration printed first says what each runs)")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(names))
      ->default_str(joined(names, ","))
      ->needs(objects);
  app.add_option("--write-objects", options.objects_dir,
                 "With --objects, write each method's objects as DIR/<method>/<scene>.objects.pcd (organized, x y z "
                 "label: object ids 1..K, 0 = none), which osd_scores.py --objects reads")
      ->type_name("DIR")
      ->needs(objects);
  for (const char* plane_option : {"--methods", "--resolutions", "--tuned", "--tuned-file", "--misses", "--png",
                                   "--png3d", "--min-gt-points", "--sensor"}) {
    objects->excludes(plane_option);
  }
}

void addOptions(CLI::App& app, Options& options) {
  // No existence check here: a missing file is reported with the others, and the batch goes on.
  app.add_option("INPUT", options.inputs,
                 "PCD files, depth PNG files (with --intrinsics), or directories of them (their *.pcd files, and "
                 "*.png files with --intrinsics, sorted)")
      ->required();
  floodplane::cli::addDepthInputOptions(app, options.depth);
  // One comma-separated token: without allow_extra_args(false) the option would also swallow
  // the INPUTs that follow it ("--methods omps scene.pcd").
  app.add_option("--methods", options.methods,
                 "Methods to run, comma-separated: floodplane (its defaults), floodplane/S (sub-sampling S; 1: every "
                 "pixel from the start), and the baselines")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(CLI::IsMember(kMethods))
      ->capture_default_str();
  app.add_option("--labels", options.labels,
                 std::string("Score another program's labels as the method NAME, a row of every table like the "
                             "methods run here (time \"-\": not run here); repeat for more methods. ") +
                     kLabelFiles +
                     ". An input whose file is missing, unreadable or of another size is reported and "
                     "the batch goes on (exit code 1). With --objects, the objects of another program: "
                     "<stem>.objects.pcd (as pcd_segment --objects and --write-objects write) in place of "
                     "<stem>.labels.pcd")
      ->type_name("NAME=DIR")
      ->allow_extra_args(false);
  app.add_option("--ground-truth", options.ground_truth_dir,
                 std::string("The ground truth of every input from label files in DIR, in place of a PCD's label "
                             "field: ") +
                     kLabelFiles + ". An input without one is compared without scores and reported (exit code 1)")
      ->type_name("DIR");
  app.add_option("--repeat", options.repeat,
                 "Timed runs per method and file after one warm-up (the sequential RANSACs run once); 0: one run "
                 "only, timed and scored")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--min-gt-points", options.min_gt_points,
                 "Score only ground-truth planes, and predicted segments, of at least N valid pixels (metrics.md); "
                 "default round(500 * W * H / (640 * 480)) for each file: 500 at 640x480, 427 at 512x512. SegComp "
                 "(Hoover et al.) counts regions of 100 pixels and more: --min-gt-points 100")
      ->type_name("N")
      ->check(CLI::Validator(wholePixelCount, ""));
  app.add_option("--json", options.json_file,
                 "Write the whole report (every file, method and plane) to this .json file");
  app.add_option("--png", options.png_dir,
                 std::string("Write <scene>.png per file into this directory: ground truth | ransac | open3d_ransac | "
                             "omps | --labels' methods | floodplane (those run), a pixel per point, segments coloured "
                             "by the ground-truth plane they overlap most, ") +
                     floodplane::cli::kUnlabelledPixels);
  // A picture of its own rather than a 3-D row under --png's: --png keeps working without a
  // display (CI, headless machines).
  app.add_option("--png3d", options.png3d_dir,
                 "Write <scene>.png per file into this directory: the panels of --png in 3-D (an arrow along each "
                 "segment's normal). Needs an X display: on a machine without one, run under xvfb-run -a");
  app.add_flag("--resolutions", options.resolutions, "Also run floodplane at sub-sampling 1, 2, 4, 8 (Table III)");
  app.add_flag("--tuned", options.tuned,
               "Also run each baseline among --methods at its tuned values for the file's sensor model (a row "
               "'<method> (tuned)')");
  app.add_option("--tuned-file", options.tuned_file,
                 "The tuned values (bench/tune_baselines.py writes them); default: $FLOODPLANE_TUNED_FILE, else "
                 "the one installed with pcd_compare");
  app.add_option("--sensor", options.sensor,
                 "The sensor model of every input, for --tuned and the means per sensor model; default: from "
                 "file names <scene>.<sensor>.pcd")
      ->check(CLI::IsMember(kSensors));
  app.add_flag("--misses", options.misses,
               "After the means, list per method every ground-truth plane that is not a correct detection, with "
               "why (no_segment: at least half of it unlabelled; under_segmented: merged into a segment with other "
               "planes; over_segmented: split into several; iou_below_t: found at an IoU below T), its size, IoU "
               "and unlabelled share, and every noise segment (--json has them too)");
  app.add_flag("-q,--quiet", options.quiet, "Print no configuration and no progress: only the means and errors");
  addObjectOptions(app, options);
}

// The label sources of --labels, checked: distinct names that are not a method's, directories
// that exist. Throws std::invalid_argument naming the flag.
std::vector<LabelSource> labelSources(const std::vector<std::string>& arguments) {
  std::vector<LabelSource> sources;
  for (const std::string& argument : arguments) {
    LabelSource source = parseLabelSource(argument);
    const std::vector<std::string> object_methods = objectMethodNames();
    const bool method = std::find(kMethods.begin(), kMethods.end(), source.name) != kMethods.end() ||
                        std::find(object_methods.begin(), object_methods.end(), source.name) != object_methods.end();
    const bool taken = std::any_of(sources.begin(), sources.end(),
                                   [&source](const LabelSource& other) { return other.name == source.name; });
    if (method || taken) {
      throw std::invalid_argument("--labels " + argument + ": " + source.name + " is already " +
                                  (method ? "a method pcd_compare runs" : "the name of another --labels"));
    }
    if (!fs::is_directory(source.directory)) {
      throw std::invalid_argument("--labels " + argument + ": " + source.directory + " is not a directory");
    }
    sources.push_back(std::move(source));
  }
  return sources;
}

// What the options name on disk, checked before any work: --png and --png3d directories,
// --json a file, the label directories. Throws std::invalid_argument naming the flag.
void checkPaths(Options& options) {
  for (const auto& [flag, directory] : {std::pair<std::string, const std::string&>("--png", options.png_dir),
                                        std::pair<std::string, const std::string&>("--png3d", options.png3d_dir)}) {
    if (directory.empty()) continue;
    floodplane::cli::outputKind(flag, directory, {}, flag + " names a directory: it writes <scene>.png per input");
  }
  if (!options.json_file.empty() &&
      floodplane::cli::outputKind("--json", options.json_file, {".json"}, "--json names the report's .json file") ==
          floodplane::cli::OutputKind::directory) {
    throw std::invalid_argument("--json " + options.json_file +
                                " is a directory; --json names the report's .json file");
  }
  if (!options.objects_dir.empty()) {
    floodplane::cli::outputKind("--write-objects", options.objects_dir, {},
                                "--write-objects names a directory: it writes <method>/<scene>.objects.pcd per input");
    if (fs::exists(options.objects_dir) && !fs::is_directory(options.objects_dir)) {
      throw std::invalid_argument("--write-objects " + options.objects_dir +
                                  " is a file; --write-objects names a directory");
    }
  }
  options.label_sources = labelSources(options.labels);
  if (!options.ground_truth_dir.empty() && !fs::is_directory(options.ground_truth_dir)) {
    throw std::invalid_argument("--ground-truth " + options.ground_truth_dir + " is not a directory");
  }
  options.camera = floodplane::cli::depthCamera(options.depth);
}

// Every file the run would write: --json's report, the images of --png and --png3d, the objects
// of --write-objects.
std::vector<std::string> outputsOfRun(const Options& options, const std::vector<std::string>& names) {
  std::vector<std::string> outputs;
  if (!options.json_file.empty()) outputs.push_back(options.json_file);
  for (const std::string& directory : {options.png_dir, options.png3d_dir}) {
    if (directory.empty()) continue;
    for (const std::string& name : names) {
      if (!name.empty()) outputs.push_back((fs::path(directory) / (name + ".png")).string());
    }
  }
  if (options.objects && !options.objects_dir.empty()) {
    const std::vector<std::string> methods =
        options.object_methods.empty() ? objectMethodNames() : firstOfEach(options.object_methods);
    for (const std::string& method : methods) {
      for (const std::string& name : names) {
        if (!name.empty())
          outputs.push_back((fs::path(options.objects_dir) / method / (name + ".objects.pcd")).string());
      }
    }
  }
  return outputs;
}

// Every file the run reads: the inputs, their label files of --labels and --ground-truth
// (either name label_files.h allows), the tuned values.
std::vector<std::string> inputsOfRun(const Options& options, const std::vector<floodplane::io::InputFile>& files,
                                     const std::vector<std::string>& names) {
  std::vector<std::string> inputs;
  std::vector<std::string> label_directories;
  for (const LabelSource& source : options.label_sources) label_directories.push_back(source.directory);
  if (!options.ground_truth_dir.empty()) label_directories.push_back(options.ground_truth_dir);
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (names[i].empty()) continue;
    inputs.push_back(files[i].path);
    for (const std::string& directory : label_directories) {
      inputs.push_back((fs::path(directory) / (names[i] + ".labels.pcd")).string());
      inputs.push_back((fs::path(directory) / (names[i] + ".objects.pcd")).string());
      inputs.push_back((fs::path(directory) / (names[i] + ".png")).string());
    }
  }
  if (!options.tuned_file.empty()) inputs.push_back(options.tuned_file);
  return inputs;
}

}  // namespace

int main(int argc, char** argv) {
  // First, before any thread starts (see there): Ctrl-C leaves no temporary file behind.
  floodplane::cli::removeTemporariesOnInterrupt("pcd_compare");
  Options options;
  CLI::App app{kDescription, "pcd_compare"};
  floodplane::cli::addVersionFlag(app);
  addOptions(app, options);
  if (const std::optional<int> exit_code = floodplane::cli::parseCommandLine(app, argc, argv)) return *exit_code;
  if (options.resolutions) options.methods.insert(options.methods.end(), kResolutions.begin(), kResolutions.end());
  options.methods = firstOfEach(options.methods);
  options.object_methods = firstOfEach(options.object_methods.empty() ? objectMethodNames() : options.object_methods);
  try {
    checkPaths(options);
  } catch (const std::invalid_argument& error) {
    return floodplane::cli::usageError(app, error.what());
  }
  const std::vector<floodplane::io::InputFile> files =
      floodplane::cli::expandFrameInputs(options.inputs, options.camera.has_value());
  if (const std::optional<std::string> problem = floodplane::cli::missingCamera(files, options.camera.has_value())) {
    return floodplane::cli::usageError(app, *problem);
  }
  const std::vector<std::string> scene_names = sceneNames(files);
  if (options.tuned && options.tuned_file.empty()) {
    try {
      options.tuned_file = defaultTunedFile();
    } catch (const std::exception& error) {
      std::cerr << "pcd_compare: error: " << error.what() << "\n";
      return 1;
    }
  }
  if (const std::optional<std::string> collision = floodplane::io::outputCollision(
          outputsOfRun(options, scene_names), inputsOfRun(options, files, scene_names))) {
    const std::string flags = options.objects ? "--json or --write-objects" : "--json, --png or --png3d";
    return floodplane::cli::usageError(app, *collision + "; nothing written: give " + flags + " another place");
  }
  // Before any work: the comparison can take minutes, and every image would fail alike.
  if (const auto reason = options.png3d_dir.empty() ? std::nullopt : floodplane::view::renderingUnavailableReason()) {
    std::cerr << "pcd_compare: error: --png3d cannot draw in 3-D: " << *reason << "\n";
    return 1;
  }
  Json report = {{"configuration", configuration(options)},
                 {"scenes", Json::array()},
                 {"failed", Json::array()},
                 {"label_problems", Json::array()}};
  Methods methods;
  try {
    methods = makeMethods(options, report["configuration"]);
    if (options.objects) {
      report["configuration"]["timing"] =
          (options.repeat > 0 ? "median and min of " + std::to_string(options.repeat) + " runs after one warm-up"
                              : std::string("one run per method and file (--repeat 0: no warm-up)")) +
          ", of the object method's whole call (normals, planes and clusters; supervoxels and LCCP) on the cloud "
          "in memory, one thread, steady_clock";
      report["configuration"]["accuracy"] = objectAccuracy(options);
    }
  } catch (const std::exception& error) {
    std::cerr << "pcd_compare: error: " << error.what() << "\n";
    return 1;
  }
  if (!options.quiet) std::cout << markdownConfiguration(report) << std::flush;
  MissingTuned missing;
  compareAll(options, files, scene_names, methods, report, missing);
  if (options.objects) {
    addObjectMeans(report);
    std::cout << markdownObjectMeans(report) << std::flush;
  } else {
    addMeans(report);
    std::cout << markdownMeans(report) << std::flush;
  }
  if (options.misses) std::cout << markdownMisses(report) << std::flush;
  bool written = true;
  try {
    if (!options.json_file.empty())
      floodplane::io::writeBytesAtomically(options.json_file, floodplane::io::jsonText(report));
  } catch (const std::exception& error) {
    std::cerr << "pcd_compare: error: " << error.what() << "\n";
    written = false;
  }
  for (const auto& [reason, names] : missing) {
    std::cerr << "pcd_compare: --tuned: no tuned rows for " << names.size() << " file(s), " << reason << ": "
              << joined(names) << "\n";
  }
  const std::size_t failed = report["failed"].size();
  if (failed > 0) {
    std::cerr << "pcd_compare: " << failed << " of " << failed + report["scenes"].size()
              << " files failed: " << joined(report["failed"].get<std::vector<std::string>>(), " ") << "\n";
  }
  const std::size_t label_problems = report["label_problems"].size();
  if (label_problems > 0) {
    std::cerr << "pcd_compare: " << label_problems << (label_problems == 1 ? " label file" : " label files")
              << " missing or unusable (said above); those inputs have no row or no scores for them\n";
  }
  return failed == 0 && label_problems == 0 && written ? 0 : 1;
}
