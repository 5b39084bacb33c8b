// pcd_synth: renders scene files, or procedurally generated scenes, into organized PCD clouds
// with ground-truth plane labels. Argument parsing and file output only; the scenes and the
// rendering are floodplane_synth.

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "common/cli.h"
#include "io/atomic_file.h"
#include "io/label_palette.h"
#include "io/pcd_file.h"
#include "io/png_file.h"
#include "synth/ground_truth_json.h"
#include "synth/point_cloud.h"
#include "synth/renderer.h"
#include "synth/scene_file.h"
#include "synth/scene_generator.h"

namespace {

namespace fs = std::filesystem;
namespace synth = floodplane::synth;

// Far more scenes than any test set needs, few enough that a typo is caught.
constexpr int kMaxRandomScenes = 100000;

struct Options {
  std::vector<std::string> scene_files;
  std::string output_dir;
  std::optional<std::string> sensor;  // default: "both" for scene files, "all" for --random
  std::uint64_t seed = 1;
  std::optional<int> random_count;
  std::optional<int> width;
  std::optional<int> height;
  bool png = false;
  bool write_scene = false;
  bool quiet = false;
};

std::vector<synth::SensorModel> sensorModels(const std::string& choice) {
  if (choice == "both") {
    return {synth::SensorModel::none, synth::SensorModel::kinect};
  }
  if (choice == "all") {
    return {synth::SensorModel::none, synth::SensorModel::kinect, synth::SensorModel::scanner};
  }
  return {*synth::sensorModelFromName(choice)};
}

std::size_t visiblePlanes(const synth::RenderedFrame& frame) {
  std::size_t seen = 0;
  for (const auto& plane : frame.planes) {
    seen += plane.pixel_count > 0 ? 1 : 0;
  }
  return seen;
}

double missingFraction(const synth::RenderedFrame& frame) {
  std::size_t missing = 0;
  for (const Eigen::Vector3f& point : frame.points) {
    missing += std::isnan(point.z()) ? 1 : 0;
  }
  return static_cast<double>(missing) / static_cast<double>(frame.points.size());
}

// Writes <stem>.pcd, <stem>.planes.json and, with --png, <stem>.labels.png, each atomically.
void writeFrame(const std::string& stem, const synth::RenderedFrame& frame, bool png) {
  floodplane::io::savePcd(stem + ".pcd", synth::toPointCloud(frame));
  floodplane::io::writeBytesAtomically(stem + ".planes.json", synth::groundTruthJson(frame));
  if (png) {
    floodplane::io::writePng(stem + ".labels.png",
                             floodplane::io::labelImage(frame.labels, frame.intrinsics.width, frame.intrinsics.height));
  }
}

std::string outputStem(const Options& options, const std::string& scene_name, synth::SensorModel sensor) {
  return (fs::path(options.output_dir) / (scene_name + "." + synth::sensorModelName(sensor))).string();
}

// Renders one scene file in every requested sensor model and writes its outputs.
void renderSceneFile(const std::string& scene_file, const Options& options) {
  synth::Scene scene = synth::loadScene(scene_file);
  if (options.width) {
    scene.intrinsics = scene.intrinsics.scaledTo(*options.width, *options.height);
  }
  for (const synth::SensorModel sensor : sensorModels(*options.sensor)) {
    synth::RenderSettings settings;
    settings.sensor = sensor;
    settings.seed = options.seed;
    const auto start = std::chrono::steady_clock::now();
    const synth::RenderedFrame frame = synth::renderScene(scene, settings);
    const std::chrono::duration<double> render_time = std::chrono::steady_clock::now() - start;

    const std::string stem = outputStem(options, scene.name, sensor);
    writeFrame(stem, frame, options.png);
    if (!options.quiet) {
      std::cout << scene.name << " (" << synth::sensorModelName(sensor) << "): " << frame.intrinsics.width << "x"
                << frame.intrinsics.height << ", " << frame.planes.size() << " planes (" << visiblePlanes(frame)
                << " visible), rendered in " << static_cast<long>(render_time.count() * 1000.0 + 0.5) << " ms -> "
                << stem << ".pcd\n";
    }
  }
}

// Generates the scenes of `seed` the sensors need (the room for none and kinect, the blocks for
// the scanner), renders them with noise seed `seed`, writes the outputs and returns a summary
// for the progress line.
std::string renderRandomSeed(std::uint64_t seed, const Options& options) {
  const std::string name = synth::randomSceneName(seed);
  std::optional<synth::Scene> room;
  std::optional<synth::Scene> blocks;
  std::ostringstream summary;
  for (const synth::SensorModel sensor : sensorModels(*options.sensor)) {
    const bool scanner = sensor == synth::SensorModel::scanner;
    std::optional<synth::Scene>& scene = scanner ? blocks : room;
    if (!scene) {
      scene = scanner ? synth::generateBlocksScene(seed) : synth::generateRoomScene(seed);
      if (options.write_scene) {
        floodplane::io::writeBytesAtomically(
            (fs::path(options.output_dir) / (name + (scanner ? ".blocks.json" : ".room.json"))).string(),
            synth::sceneJson(*scene));
      }
    }
    synth::RenderSettings settings;
    settings.sensor = sensor;
    settings.seed = seed;
    const synth::RenderedFrame frame = synth::renderScene(*scene, settings);
    writeFrame(outputStem(options, name, sensor), frame, options.png);
    summary << "; " << synth::sensorModelName(sensor) << " " << frame.intrinsics.width << "x" << frame.intrinsics.height
            << ", " << visiblePlanes(frame) << " of " << frame.planes.size() << " planes visible";
    if (sensor != synth::SensorModel::none) {
      summary << ", " << std::fixed << std::setprecision(1) << 100.0 * missingFraction(frame) << " % no return";
    }
  }
  return summary.str();
}

// Scenes are named by their file stem, so two files with one stem would overwrite each other's
// outputs. Returns the files that failed.
std::vector<std::string> renderSceneFiles(const Options& options) {
  std::map<std::string, std::string> file_of_scene;
  std::vector<std::string> failed;
  for (const std::string& scene_file : options.scene_files) {
    const std::string name = fs::path(scene_file).stem().string();
    const auto [previous, inserted] = file_of_scene.emplace(name, scene_file);
    try {
      if (!inserted) {
        throw std::runtime_error(scene_file + ": has the same name as " + previous->second +
                                 ", whose outputs it would overwrite");
      }
      renderSceneFile(scene_file, options);
    } catch (const std::exception& error) {
      std::cerr << "pcd_synth: error: " << error.what() << "\n";
      failed.push_back(scene_file);
    }
  }
  return failed;
}

// Returns the seeds that failed.
std::vector<std::string> renderRandomScenes(const Options& options) {
  std::vector<std::string> failed;
  const auto count = static_cast<std::uint64_t>(*options.random_count);
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::uint64_t seed = options.seed + i;
    const auto start = std::chrono::steady_clock::now();
    try {
      const std::string summary = renderRandomSeed(seed, options);
      const std::chrono::duration<double> time = std::chrono::steady_clock::now() - start;
      if (!options.quiet) {
        std::cout << synth::randomSceneName(seed) << " (" << i + 1 << " of " << count << ")" << summary << "; "
                  << std::fixed << std::setprecision(2) << time.count() << " s\n"
                  << std::flush;
      }
    } catch (const std::exception& error) {
      std::cerr << "pcd_synth: error: seed " << seed << ": " << error.what() << "\n";
      failed.push_back(std::to_string(seed));
    }
  }
  return failed;
}

// Combinations CLI11 cannot express; an empty string when the options are consistent.
std::string inconsistency(const Options& options) {
  if (options.random_count && !options.scene_files.empty()) {
    return "give scene files or --random N, not both";
  }
  if (!options.random_count && options.scene_files.empty()) {
    return "nothing to render: give scene files or --random N";
  }
  if (options.random_count && options.width) {
    return "--width and --height apply to scene files; random scenes have their sensor's resolution";
  }
  if (!options.random_count && options.write_scene) {
    return "--write-scene saves generated scenes and needs --random N";
  }
  if (options.random_count && options.seed > std::numeric_limits<std::uint64_t>::max() -
                                                 static_cast<std::uint64_t>(*options.random_count - 1)) {
    return "--seed " + std::to_string(options.seed) + " + --random " + std::to_string(*options.random_count) +
           " scenes runs past the largest seed";
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Renders scene files (JSON, see data/scenes/README.md), or N procedurally generated scenes (--random), "
      "into organized pcl::PointXYZL clouds: the measured point in x y z (NaN for no return) and the "
      "ground-truth plane id in label. Writes <scene>.<sensor>.pcd and <scene>.<sensor>.planes.json per scene "
      "and sensor model into OUTDIR. Random scene i (from 0) has seed S + i and is named random_<seed, 4 "
      "digits>; the kinect and none frames show a room, the scanner frame blocks on a table.",
      "pcd_synth"};
  floodplane::apps::addVersionFlag(app);
  // No existence check here: a missing file is reported with the others at the end.
  app.add_option("scenes", options.scene_files, "Scene files to render");
  app.add_option("-o,--output-dir", options.output_dir, "Directory for the outputs (created if missing)")->required();
  app.add_option("--random", options.random_count,
                 "Render N generated scenes, seeds S to S + N - 1, instead of scene files")
      ->check(CLI::Range(1, kMaxRandomScenes));
  app.add_option("--sensor", options.sensor,
                 "Sensor model: none (exact), kinect, scanner (close-range structured light; random scanner "
                 "scenes are 512x512), both (none and kinect) or all; default both for scene files, all for "
                 "--random")
      ->check(CLI::IsMember({"none", "kinect", "scanner", "both", "all"}));
  app.add_option("--seed", options.seed, "Seed of the sensor noise; with --random also of the first scene (S)")
      ->capture_default_str();
  auto* width = app.add_option("--width", options.width,
                               "Render scene files at this width instead of the scene's (intrinsics scale "
                               "with the resolution)")
                    ->check(CLI::Range(1, 32768));
  auto* height = app.add_option("--height", options.height, "Render scene files at this height instead of the scene's")
                     ->check(CLI::Range(1, 32768));
  width->needs(height);
  height->needs(width);
  app.add_flag("--png", options.png, "Also write <scene>.<sensor>.labels.png (ground truth)");
  app.add_flag("--write-scene", options.write_scene,
               "With --random, also save each generated scene as a scene file: <scene>.room.json, "
               "<scene>.blocks.json");
  app.add_flag("-q,--quiet", options.quiet, "Print only errors");
  if (const std::optional<int> done = floodplane::apps::parseCommandLine(app, argc, argv)) return *done;
  if (const std::string problem = inconsistency(options); !problem.empty())
    return floodplane::apps::usageError(app, problem);
  if (!options.sensor) {
    options.sensor = options.random_count ? "all" : "both";
  }

  try {
    fs::create_directories(options.output_dir);
  } catch (const fs::filesystem_error& error) {
    std::cerr << "pcd_synth: error: cannot create output directory '" << options.output_dir
              << "': " << error.code().message() << "\n";
    return 1;
  }

  const std::vector<std::string> failed =
      options.random_count ? renderRandomScenes(options) : renderSceneFiles(options);
  if (!failed.empty()) {
    const std::size_t total =
        options.random_count ? static_cast<std::size_t>(*options.random_count) : options.scene_files.size();
    std::cerr << "pcd_synth: " << failed.size() << " of " << total
              << (options.random_count ? " seeds failed:" : " scene files failed:");
    for (const auto& item : failed) {
      std::cerr << " " << item;
    }
    std::cerr << "\n";
    return 1;
  }
  return 0;
}
