// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_synth: renders scene files, or procedurally generated scenes, into organized PCD clouds
// with ground-truth plane labels. Argument parsing and file output only; the scenes and the
// rendering are floodplane_synth.

#include <CLI/CLI.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
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

#include "cli/cli.h"
#include "cli/interrupt_cleanup.h"
#include "cli/output_target.h"
#include "floodplane/io/atomic_file.h"
#include "floodplane/io/label_palette.h"
#include "floodplane/io/pcd_file.h"
#include "floodplane/io/png_file.h"
#include "synth/camera_path.h"
#include "synth/ground_truth_json.h"
#include "synth/point_cloud.h"
#include "synth/renderer.h"
#include "synth/room_walk.h"
#include "synth/scene_file.h"
#include "synth/scene_generator.h"
#include "synth/sequence_labels.h"

namespace {

namespace fs = std::filesystem;
namespace synth = floodplane::synth;

// Far more scenes than any test set needs, few enough that a typo is caught.
constexpr int kMaxRandomScenes = 100000;
// An hour at 30 Hz.
constexpr int kMaxSequenceFrames = 108000;
// A scene file may show a few objects and no walls: its camera walks on a short leash and
// keeps looking roughly the scene's way.
constexpr double kSceneFileLeash = 0.5;     // metres
constexpr double kSceneFileMaxTurn = 25.0;  // degrees
// Quirk limits: far beyond a real sensor's, near enough to catch a unit mix-up (--warp in metres
// instead of millimetres, --bend of a whole wall at 1 /m: see synth/sensor_model.h).
constexpr int kMaxQuantizeBits = 16;
constexpr double kMaxWarpMillimetres = 50.0;
constexpr double kMaxBendPerMetre = 1.0;

struct Options {
  std::vector<std::string> scene_files;
  std::string output_dir;
  std::optional<std::string> sensor;  // default: "both" for scene files, "all" for --random
  std::uint64_t seed = 1;
  std::optional<int> random_count;
  std::optional<std::string> family;  // of --random: "room" (default) or "boards"
  std::optional<int> sequence_frames;
  bool look_away = false;  // glances away from the walking direction in a sequence
  std::optional<int> width;
  std::optional<int> height;
  bool png = false;
  bool ascii = false;
  bool write_scene = false;
  bool quiet = false;
  // A real sensor's quirks, all off by default (synth/scanner_model.h, synth/sensor_model.h).
  std::optional<int> quantize_bits;  // scanner
  std::optional<double> warp_mm;     // scanner, kinect
  bool speckle = false;              // scanner
  std::optional<double> bend_per_m;  // kinect
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

// The render settings of one frame: `sensor` with noise seed `noise_seed` and the quirks the
// options turn on; the warp's shape from `warp_seed` (the scene's seed, one calibration for
// every frame of a sequence).
synth::RenderSettings renderSettings(synth::SensorModel sensor, std::uint64_t noise_seed, std::uint64_t warp_seed,
                                     const Options& options) {
  synth::RenderSettings settings;
  settings.sensor = sensor;
  settings.seed = noise_seed;
  if (options.quantize_bits) settings.scanner.range_bits = *options.quantize_bits;
  settings.scanner.speckle = options.speckle;
  if (options.warp_mm) {
    settings.warp.amplitude = *options.warp_mm / 1000.0;
    settings.warp.seed = warp_seed;
  }
  if (options.bend_per_m) settings.kinect.bend_curvature = *options.bend_per_m;
  return settings;
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

// Writes <stem>.pcd (text with --ascii), <stem>.planes.json and, with --png, <stem>.labels.png,
// all or none (an error or an interrupt leaves none of the frame's files).
void writeFrame(const std::string& stem, const synth::RenderedFrame& frame, const Options& options) {
  floodplane::io::AtomicFileGroup files;
  files.add(stem + ".pcd", floodplane::io::encodePcd(synth::toPointCloud(frame),
                                                     options.ascii ? floodplane::io::PcdEncoding::ascii
                                                                   : floodplane::io::PcdEncoding::binary_compressed));
  files.add(stem + ".planes.json", synth::groundTruthJson(frame));
  if (options.png) {
    std::vector<std::uint8_t> has_point;
    has_point.reserve(frame.points.size());
    for (const Eigen::Vector3f& point : frame.points) has_point.push_back(point.allFinite() ? 1 : 0);
    files.add(stem + ".labels.png", floodplane::io::encodePng(floodplane::io::labelImage(
                                        frame.labels, has_point, frame.intrinsics.width, frame.intrinsics.height)));
  }
  files.commit();
}

std::string outputStem(const Options& options, const std::string& scene_name, synth::SensorModel sensor) {
  return (fs::path(options.output_dir) / (scene_name + "." + synth::sensorModelName(sensor))).string();
}

// "random_0007_f0012": frame 12 of a sequence; the sensor model still comes last in a file name.
std::string frameName(const std::string& scene_name, int frame) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "_f%04d", frame);
  return scene_name + digits;
}

// Renders the sequence of `scene` along `poses` (walked with `walk`) in every requested sensor
// model, with noise seeds from `noise_seed` (synth::sequenceFrameSeed), and writes
// <scene>_fNNNN.<sensor>.* and <scene>.poses.json. Ground-truth ids stay constant: faces merged
// in any frame are one surface in all (SequenceSurfaces); frames written before a later merge
// changed their labels are rendered and written again. Returns a summary for the progress line.
std::string renderSequence(const synth::Scene& scene, const std::vector<Eigen::Isometry3d>& poses,
                           const synth::WalkSettings& walk, const std::vector<synth::SensorModel>& sensors,
                           std::uint64_t noise_seed, const Options& options) {
  floodplane::io::writeBytesAtomically((fs::path(options.output_dir) / (scene.name + ".poses.json")).string(),
                                       synth::cameraPathJson(scene.name, poses, walk.frame_rate, walk.look_away));
  synth::SequenceSurfaces surfaces;
  const auto frames = static_cast<int>(poses.size());
  const auto render = [&](synth::SensorModel sensor, int k) {
    synth::Scene view = scene;
    view.world_from_camera = poses[static_cast<std::size_t>(k)];
    return synth::renderScene(view,
                              renderSettings(sensor, synth::sequenceFrameSeed(noise_seed, k), noise_seed, options));
  };
  // The planes as written, per sensor and frame, to find the frames a later merge changes.
  std::vector<std::vector<synth::RenderedFrame>> written(sensors.size());
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    for (int k = 0; k < frames; ++k) {
      synth::RenderedFrame frame = render(sensors[s], k);
      surfaces.add(frame);
      surfaces.relabel(frame);
      writeFrame(outputStem(options, frameName(scene.name, k), sensors[s]), frame, options);
      synth::RenderedFrame listing;
      listing.planes = std::move(frame.planes);
      written[s].push_back(std::move(listing));
    }
  }
  int rendered_again = 0;
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    for (int k = 0; k < frames; ++k) {
      if (!surfaces.changes(written[s][static_cast<std::size_t>(k)])) continue;
      synth::RenderedFrame frame = render(sensors[s], k);
      surfaces.relabel(frame);
      writeFrame(outputStem(options, frameName(scene.name, k), sensors[s]), frame, options);
      ++rendered_again;
    }
  }
  double walked = 0.0;
  double turned = 0.0;
  for (std::size_t k = 1; k < poses.size(); ++k) {
    walked += (poses[k].translation() - poses[k - 1].translation()).norm();
    turned += Eigen::AngleAxisd(poses[k - 1].linear().transpose() * poses[k].linear()).angle();
  }
  std::ostringstream summary;
  summary << "; " << frames << " frames";
  for (const synth::SensorModel sensor : sensors) summary << " " << synth::sensorModelName(sensor);
  summary << ", walked " << std::fixed << std::setprecision(1) << walked << " m, turned " << std::setprecision(0)
          << turned * 180.0 / 3.14159265358979323846 << " deg";
  if (rendered_again > 0) summary << ", " << rendered_again << " frames rendered again for merged faces";
  return summary.str();
}

// Renders one scene file in every requested sensor model and writes its outputs.
void renderSceneFile(const std::string& scene_file, const Options& options) {
  synth::Scene scene = synth::loadScene(scene_file);
  if (options.width) {
    scene.intrinsics = scene.intrinsics.scaledTo(*options.width, *options.height);
  }
  if (options.sequence_frames) {
    synth::WalkSettings walk;
    walk.max_distance_from_start = kSceneFileLeash;
    walk.max_turn = kSceneFileMaxTurn;
    walk.look_away.enabled = options.look_away;
    const auto start = std::chrono::steady_clock::now();
    const std::string summary =
        renderSequence(scene, synth::walkingCameraPath(scene, *options.sequence_frames, options.seed, walk), walk,
                       sensorModels(*options.sensor), options.seed, options);
    const std::chrono::duration<double> time = std::chrono::steady_clock::now() - start;
    if (!options.quiet) {
      std::cout << scene.name << summary << "; " << std::fixed << std::setprecision(2) << time.count() << " s\n";
    }
    return;
  }
  for (const synth::SensorModel sensor : sensorModels(*options.sensor)) {
    const auto start = std::chrono::steady_clock::now();
    const synth::RenderedFrame frame =
        synth::renderScene(scene, renderSettings(sensor, options.seed, options.seed, options));
    const std::chrono::duration<double> render_time = std::chrono::steady_clock::now() - start;

    const std::string stem = outputStem(options, scene.name, sensor);
    writeFrame(stem, frame, options);
    if (!options.quiet) {
      std::cout << scene.name << " (" << synth::sensorModelName(sensor) << "): " << frame.intrinsics.width << "x"
                << frame.intrinsics.height << ", " << frame.planes.size() << " planes (" << visiblePlanes(frame)
                << " visible), rendered in " << static_cast<long>(render_time.count() * 1000.0 + 0.5) << " ms -> "
                << stem << ".pcd\n";
    }
  }
}

bool boardsFamily(const Options& options) { return options.family && *options.family == "boards"; }

// "random_0007", or "boards_0007" for --family boards.
std::string randomSceneName(std::uint64_t seed, const Options& options) {
  return boardsFamily(options) ? synth::boardsSceneName(seed) : synth::randomSceneName(seed);
}

// The boards scene of `seed` in every requested sensor model (none, kinect).
std::string renderBoardsSeed(std::uint64_t seed, const Options& options) {
  const std::string name = synth::boardsSceneName(seed);
  const synth::Scene scene = synth::generateBoardsScene(seed);
  if (options.write_scene) {
    floodplane::io::writeBytesAtomically((fs::path(options.output_dir) / (name + ".boards.json")).string(),
                                         synth::sceneJson(scene));
  }
  std::ostringstream summary;
  for (const synth::SensorModel sensor : sensorModels(*options.sensor)) {
    const synth::RenderedFrame frame = synth::renderScene(scene, renderSettings(sensor, seed, seed, options));
    writeFrame(outputStem(options, name, sensor), frame, options);
    std::size_t edges = 0;
    for (const auto& plane : frame.planes) {
      edges += plane.pixel_count > 0 && synth::isBoardEdgeFace(plane.primitive, plane.face) ? 1 : 0;
    }
    summary << "; " << synth::sensorModelName(sensor) << " " << frame.intrinsics.width << "x" << frame.intrinsics.height
            << ", " << visiblePlanes(frame) << " of " << frame.planes.size() << " planes visible, " << edges
            << (edges == 1 ? " board edge" : " board edges");
    if (sensor != synth::SensorModel::none) {
      summary << ", " << std::fixed << std::setprecision(1) << 100.0 * missingFraction(frame) << " % no return";
    }
  }
  return summary.str();
}

// Generates the scenes of `seed` the sensors need (the room for none and kinect, the blocks for
// the scanner; the boards scene for --family boards), renders them with noise seed `seed`,
// writes the outputs and returns a summary for the progress line.
std::string renderRandomSeed(std::uint64_t seed, const Options& options) {
  if (boardsFamily(options)) return renderBoardsSeed(seed, options);
  const std::string name = synth::randomSceneName(seed);
  if (options.sequence_frames) {
    const synth::Scene scene = synth::generateRoomScene(seed);
    if (options.write_scene) {
      floodplane::io::writeBytesAtomically((fs::path(options.output_dir) / (name + ".room.json")).string(),
                                           synth::sceneJson(scene));
    }
    synth::WalkSettings walk;
    walk.look_away.enabled = options.look_away;
    return renderSequence(scene, synth::walkingCameraPath(scene, *options.sequence_frames, seed, walk), walk,
                          sensorModels(*options.sensor), seed, options);
  }
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
    const synth::RenderedFrame frame = synth::renderScene(*scene, renderSettings(sensor, seed, seed, options));
    writeFrame(outputStem(options, name, sensor), frame, options);
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
        std::cout << randomSceneName(seed, options) << " (" << i + 1 << " of " << count << ")" << summary << "; "
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
  if (options.sequence_frames && options.sensor && (*options.sensor == "scanner" || *options.sensor == "all")) {
    return "--sequence walks through rooms seen by the sensor models none and kinect, not the scanner's";
  }
  if (options.family && !options.random_count) {
    return "--family chooses the family of the generated scenes of --random N";
  }
  if (boardsFamily(options) && options.sequence_frames) {
    return "--family boards renders single frames; --sequence walks through the room family";
  }
  if (boardsFamily(options) && options.sensor && (*options.sensor == "scanner" || *options.sensor == "all")) {
    return "--family boards has no scanner scene: its rooms are for the sensor models none and kinect (--sensor "
           "none, kinect or both)";
  }
  if (options.look_away && !options.sequence_frames) {
    return "--look-away turns the walking camera of --sequence N";
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

// Quirks that no requested sensor model has, and values out of range (CLI11's ranges let NaN
// through); an empty string when the quirks make sense. Needs options.sensor set.
std::string quirkInconsistency(const Options& options) {
  const std::vector<synth::SensorModel> sensors = sensorModels(*options.sensor);
  const auto renders = [&](synth::SensorModel model) {
    return std::find(sensors.begin(), sensors.end(), model) != sensors.end();
  };
  const bool scanner = renders(synth::SensorModel::scanner);
  const bool kinect = renders(synth::SensorModel::kinect);
  const std::string not_rendered = ", not rendered here (--sensor " + *options.sensor + ")";
  if (options.quantize_bits && !scanner) {
    return "--quantize-bits applies to the scanner model" + not_rendered;
  }
  if (options.speckle && !scanner) {
    return "--speckle applies to the scanner model" + not_rendered;
  }
  if (options.warp_mm && !scanner && !kinect) {
    return "--warp applies to the scanner and kinect models" + not_rendered;
  }
  if (options.bend_per_m && !kinect) {
    return "--bend applies to the kinect model" + not_rendered;
  }
  if (options.warp_mm && !(*options.warp_mm > 0.0 && *options.warp_mm <= kMaxWarpMillimetres)) {
    return "--warp: the peak warp must be a number of millimetres above 0 and at most " +
           std::to_string(static_cast<int>(kMaxWarpMillimetres));
  }
  if (options.bend_per_m && !(std::abs(*options.bend_per_m) <= kMaxBendPerMetre && *options.bend_per_m != 0.0)) {
    return "--bend: the curvature must be a number per metre, not 0, between -1 and 1";
  }
  return "";
}

constexpr const char* kDescription =
    "Renders scene files (JSON, see data/scenes/README.md), or N procedurally generated scenes (--random), "
    "into organized pcl::PointXYZL clouds: the measured point in x y z (NaN for no return) and the "
    "ground-truth plane id in label. Writes <scene>.<sensor>.pcd and <scene>.<sensor>.planes.json per scene "
    "and sensor model into OUTDIR, the camera's up (the world's z in the camera frame) in the JSON's \"up\" and, as "
    "the camera's orientation in the world, in the PCD's VIEWPOINT (pcd_segment --up viewpoint). Random scene i (from "
    "0) has seed S + i and is named random_<seed, 4 "
    "digits>; the kinect and none frames show a room, the scanner frame blocks on a table (--family boards: "
    "boards_<seed>, 2 cm boards in a bare room, none and kinect only). With --sequence N, "
    "writes N frames of a camera walking through each scene instead: <scene>_f0000.<sensor>.pcd to "
    "<scene>_f<N-1>.<sensor>.pcd (and .planes.json), with one ground-truth id per surface over the whole "
    "sequence, and <scene>.poses.json with each frame's camera pose. A frame's files appear together once all are "
    "written, or not at all; on Ctrl-C or SIGTERM the unfinished ones are removed and pcd_synth ends by that signal "
    "(a shell's status 130 or 143).";

// The scenes to render and how: scene files or --random (--family), a walking camera
// (--sequence), the sensor models, the seed, the resolution, the output directory.
void addSceneOptions(CLI::App& app, Options& options) {
  // No existence check here: a missing file is reported with the others at the end.
  app.add_option("scenes", options.scene_files, "Scene files to render");
  app.add_option("-o,--output-dir", options.output_dir,
                 "Directory for the outputs (created if missing). A name with an extension (scenes.pcd) is "
                 "refused unless the directory exists or the name ends in /")
      ->required();
  app.add_option("--random", options.random_count,
                 "Render N generated scenes, seeds S to S + N - 1, instead of scene files")
      ->check(CLI::Range(1, kMaxRandomScenes));
  app.add_option("--family", options.family,
                 "With --random: which generated scenes. room (default): a furnished room for none and kinect, "
                 "blocks on a table for the scanner, named random_<seed>. boards: a bare room with 2-5 boards 2 cm "
                 "thick (standing or hung on a wall, leaning on it at 5-25 degrees, lying on the floor, a shelf "
                 "sticking out of a wall), seen from 0.8-3.5 m at an angle so that their 2 cm edges show, named "
                 "boards_<seed> (so both families can share a directory); sensor models none and kinect only "
                 "(default both), no --sequence; --write-scene saves <scene>.boards.json")
      ->check(CLI::IsMember({"room", "boards"}));
  app.add_option("--sequence", options.sequence_frames,
                 "Render N frames of a camera walking through each scene: 1.0-1.4 m/s at 30 Hz, turning about "
                 "the vertical at up to 30 deg/s, nodding up to 4 degrees, never nearer than 0.5 m to a surface "
                 "(in a scene file also within 0.5 m and 25 degrees of its camera); frame 0 is the scene's own "
                 "view. The walk and frame 0's noise depend on the scene's seed (--seed for scene files), frame k's "
                 "noise on that seed + k * 0x9E3779B97F4A7C15. Sensor models none and kinect (default both)")
      ->check(CLI::Range(1, kMaxSequenceFrames));
  app.add_flag("--look-away", options.look_away,
               "With --sequence: now and then the camera turns away from the way it walks and back, as a head "
               "does, so that surfaces leave the view and return (re-entries for plane tracking): after 1-2.5 s "
               "of looking ahead a glance of 60-90 degrees to a random side at 180 deg/s, held 0.1-0.3 s; a small "
               "surface in the "
               "middle of the view is out of it for about 13-29 frames. The positions stay those of the walk "
               "without it; the glances depend on the same seed and are listed in <scene>.poses.json. Default off");
  app.add_option("--sensor", options.sensor,
                 "Sensor model: none (exact), kinect, scanner (close-range structured light; random scanner "
                 "scenes are 512x512), both (none and kinect) or all; default both for scene files and --sequence, "
                 "all for --random (both for --random --family boards)")
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
}

// What is written besides each frame's PCD and ground truth, and how.
void addOutputFlags(CLI::App& app, Options& options) {
  floodplane::cli::addAsciiFlag(app, options.ascii, "the PCDs");
  app.add_flag("--png", options.png,
               "Also write <scene>.<sensor>.labels.png, the ground truth as pcd_segment --png draws labels, " +
                   floodplane::cli::labelImageHelp());
  app.add_flag("--write-scene", options.write_scene,
               "With --random, also save each generated scene as a scene file: <scene>.room.json, "
               "<scene>.blocks.json (<scene>.boards.json with --family boards)");
  app.add_flag("-q,--quiet", options.quiet, "Print only errors");
}

// A real sensor's quirks (synth/scanner_model.h, synth/sensor_model.h, synth/depth_warp.h).
void addQuirkOptions(CLI::App& app, Options& options) {
  app.add_option("--quantize-bits", options.quantize_bits,
                 "Scanner: report the range as an N-bit code over the working window 0.7-1.5 m, uniform in "
                 "depth, in place of the scanner's inverse-depth lattice (8 bits: 3.1 mm steps, a staircase on "
                 "oblique planes); depths outside the window return nothing. 1-16; default off")
      ->check(CLI::Range(1, kMaxQuantizeBits))
      ->type_name("N");
  app.add_option("--warp", options.warp_mm,
                 "Scanner and kinect: a calibration warp, a smooth depth error over the field of view (a bowl, a "
                 "weaker saddle and a tilt, its shape fixed by the seed, the same in every frame of a sequence) "
                 "with a peak of MM millimetres, moving each point along its ray. Above 0, at most 50; default off")
      ->type_name("MM");
  app.add_flag("--speckle", options.speckle,
               "Scanner: near depth discontinuities and shadow edges (within 2 pixels), isolated spurious returns "
               "(label 0) and short stripes of lost returns down the image's columns; default off");
  app.add_option("--bend", options.bend_per_m,
                 "Kinect: a radial depth distortion that bends a flat wall facing the camera at 3.5 m to a "
                 "curvature of PER_M per metre (PER_M * z / 3.5 m at depth z; the depth error is "
                 "PER_M / 2 * rho^2 * z^3 / 3.5 m, rho the ray's tangent from the image centre; positive: the "
                 "corners read far). Between -1 and 1, not 0; 0.02 moves the corners of a wall at 3.5 m by 7 "
                 "cm; default off")
      ->type_name("PER_M");
}

// What the parsed options cannot do together, and what -o names, checked before any work; fills
// in the default sensor models. An empty string when they are fine, else the usage error.
std::string problemWith(Options& options) {
  if (const std::string problem = inconsistency(options); !problem.empty()) return problem;
  if (!options.sensor) {
    options.sensor = options.random_count && !options.sequence_frames && !boardsFamily(options) ? "all" : "both";
  }
  if (const std::string problem = quirkInconsistency(options); !problem.empty()) return problem;
  try {
    floodplane::cli::outputKind("-o", options.output_dir, {},
                                "-o names a directory: pcd_synth writes several files per scene");
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

// Says which scenes or seeds failed, if any; the exit code.
int reportFailures(const std::vector<std::string>& failed, const Options& options) {
  if (failed.empty()) return 0;
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

}  // namespace

int main(int argc, char** argv) {
  // First, before any thread starts (see there): Ctrl-C leaves no temporary file behind.
  floodplane::cli::removeTemporariesOnInterrupt("pcd_synth");
  Options options;
  CLI::App app{kDescription, "pcd_synth"};
  floodplane::cli::addVersionFlag(app);
  addSceneOptions(app, options);
  addOutputFlags(app, options);
  addQuirkOptions(app, options);
  if (const std::optional<int> done = floodplane::cli::parseCommandLine(app, argc, argv)) return *done;
  if (const std::string problem = problemWith(options); !problem.empty()) {
    return floodplane::cli::usageError(app, problem);
  }
  try {
    fs::create_directories(options.output_dir);
  } catch (const fs::filesystem_error& error) {
    std::cerr << "pcd_synth: error: cannot create output directory '" << options.output_dir
              << "': " << error.code().message() << "\n";
    return 1;
  }
  return reportFailures(options.random_count ? renderRandomScenes(options) : renderSceneFiles(options), options);
}
