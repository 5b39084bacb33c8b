// pcd_synth: renders scene files into organized PCD clouds with ground-truth plane labels.
// Argument parsing and file output only; the rendering is floodplane_synth.

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/label_palette.h"
#include "io/pcd_file.h"
#include "io/png_file.h"
#include "synth/ground_truth_json.h"
#include "synth/point_cloud.h"
#include "synth/renderer.h"
#include "synth/scene_file.h"
#include "floodplane/version.h"

namespace {

namespace fs = std::filesystem;
namespace synth = floodplane::synth;

struct Options {
  std::vector<std::string> scene_files;
  std::string output_dir;
  std::string sensor = "both";
  std::uint64_t seed = 1;
  std::optional<int> width;
  std::optional<int> height;
  bool png = false;
  bool quiet = false;
};

std::vector<synth::SensorModel> sensorModels(const std::string& choice) {
  if (choice == "both") {
    return {synth::SensorModel::none, synth::SensorModel::kinect};
  }
  return {*synth::sensorModelFromName(choice)};
}

// Renders one scene file in every requested sensor model and writes its outputs.
void renderSceneFile(const std::string& scene_file, const Options& options) {
  synth::Scene scene = synth::loadScene(scene_file);
  if (options.width) {
    scene.intrinsics = scene.intrinsics.scaledTo(*options.width, *options.height);
  }
  for (const synth::SensorModel sensor : sensorModels(options.sensor)) {
    synth::RenderSettings settings;
    settings.sensor = sensor;
    settings.seed = options.seed;
    const auto start = std::chrono::steady_clock::now();
    const synth::RenderedFrame frame = synth::renderScene(scene, settings);
    const std::chrono::duration<double> render_time = std::chrono::steady_clock::now() - start;

    const std::string stem =
        (fs::path(options.output_dir) / (scene.name + "." + synth::sensorModelName(sensor))).string();
    floodplane::io::savePcd(stem + ".pcd", synth::toPointCloud(frame));
    floodplane::io::writeBytesAtomically(stem + ".planes.json", synth::groundTruthJson(frame));
    if (options.png) {
      floodplane::io::writePng(stem + ".labels.png", floodplane::io::labelImage(frame.labels, frame.intrinsics.width,
                                                                                frame.intrinsics.height));
    }
    if (!options.quiet) {
      std::size_t seen = 0;
      for (const auto& plane : frame.planes) {
        seen += plane.pixel_count > 0 ? 1 : 0;
      }
      std::cout << scene.name << " (" << synth::sensorModelName(sensor) << "): " << frame.intrinsics.width << "x"
                << frame.intrinsics.height << ", " << frame.planes.size() << " planes (" << seen
                << " visible), rendered in " << static_cast<long>(render_time.count() * 1000.0 + 0.5) << " ms -> "
                << stem << ".pcd\n";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{
      "Renders scene files (JSON, see data/scenes/README.md) into organized pcl::PointXYZL "
      "clouds: the measured point in x y z (NaN for no return) and the ground-truth plane id "
      "in label. Writes <scene>.<sensor>.pcd and <scene>.<sensor>.planes.json per scene and "
      "sensor model into OUTDIR.",
      "pcd_synth"};
  app.set_version_flag("--version", FLOODPLANE_VERSION_STRING);
  // No existence check here: a missing file is reported with the others at the end.
  app.add_option("scenes", options.scene_files, "Scene files to render")->required();
  app.add_option("-o,--output-dir", options.output_dir, "Directory for the outputs (created if missing)")->required();
  app.add_option("--sensor", options.sensor, "Sensor model: none (exact), kinect, or both")
      ->check(CLI::IsMember({"none", "kinect", "both"}))
      ->capture_default_str();
  app.add_option("--seed", options.seed, "Seed of the kinect model's noise")->capture_default_str();
  auto* width = app.add_option("--width", options.width,
                               "Render at this width instead of the scene's (intrinsics scale "
                               "with the resolution)")
                    ->check(CLI::Range(1, 32768));
  auto* height = app.add_option("--height", options.height, "Render at this height instead of the scene's")
                     ->check(CLI::Range(1, 32768));
  width->needs(height);
  height->needs(width);
  app.add_flag("--png", options.png, "Also write <scene>.<sensor>.labels.png (ground truth)");
  app.add_flag("-q,--quiet", options.quiet, "Print only errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }

  try {
    fs::create_directories(options.output_dir);
  } catch (const fs::filesystem_error& error) {
    std::cerr << "pcd_synth: error: cannot create output directory '" << options.output_dir
              << "': " << error.code().message() << "\n";
    return 1;
  }

  // Scenes are named by their file stem, so two files with one stem would overwrite each
  // other's outputs.
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
  if (!failed.empty()) {
    std::cerr << "pcd_synth: " << failed.size() << " of " << options.scene_files.size() << " scene files failed:";
    for (const auto& file : failed) {
      std::cerr << " " << file;
    }
    std::cerr << "\n";
    return 1;
  }
  return 0;
}
