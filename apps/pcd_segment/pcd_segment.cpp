// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// pcd_segment: segments organized PCD files and 16-bit depth PNG images into planes and
// writes the labels (PCD, and optionally PNG and a JSON report). Argument parsing and file
// I/O only; the segmentation is floodplane::FloodFillPlaneSegmentation.

#include <pcl/console/print.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera_poses.h"
#include "cli/cli.h"
#include "cli/depth_input.h"
#include "cli/interrupt_cleanup.h"
#include "cli/output_target.h"
#include "cli/param_options.h"
#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/io/atomic_file.h"
#include "floodplane/io/input_files.h"
#include "floodplane/io/input_frame.h"
#include "floodplane/io/json_text.h"
#include "floodplane/io/label_palette.h"
#include "floodplane/io/labelled_cloud.h"
#include "floodplane/io/output_rule.h"
#include "floodplane/io/png_file.h"
#include "floodplane/plane_classes.h"
#include "label_pcd.h"
#include "ordered_batch.h"
#include "output_paths.h"
#include "planes_json.h"
#include "progress.h"
#include "track_summary.h"
#include "view/display_check.h"
#include "view/plane_view.h"
#include "view_output.h"

namespace {

namespace fs = std::filesystem;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Segmentation = floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>;

constexpr const char* kDescription =
    "Segments organized point clouds into planes (flood fill, Roychoudhury et al.). Each "
    "INPUT is a PCD file with x y z fields, a 16-bit depth image (.png, 0 = no return; needs "
    "--intrinsics), or a directory of them. Writes per input a labelled cloud (x y z [rgb] "
    "label: 0 no plane, 1..K planes by size, largest first; a depth image's back-projected "
    "points). With --track the inputs are one sequence of frames and the labels are track ids. A frame with no "
    "finite point (all NaN, a depth image of zeros) is valid: written with no planes, with a note. An input's outputs "
    "appear together once all are written, or not at all: an input that fails leaves none, and on Ctrl-C or "
    "SIGTERM the unfinished ones are removed and pcd_segment ends by that signal (a shell's status 130 or 143).";

// What -o names, for its help and for the error of an -o that is neither (cli/output_target.h).
constexpr const char* kOutputMeaning =
    "-o names the labelled cloud (a .pcd file) or the label image (a .png file), for one input, or a directory";

struct Options {
  std::vector<std::string> inputs;
  std::string output;
  floodplane::Params params;
  floodplane::cli::DepthInputOptions depth;
  std::optional<floodplane::io::DepthCamera> camera;  ///< from `depth`, when given
  bool ascii = false;
  bool png = false;
  bool overlay = false;
  bool json = false;
  bool objects = false;                         ///< --objects: the objects on the planes too
  std::vector<std::string> up;                  ///< --up X,Y,Z or --up viewpoint, or empty
  bool up_from_viewpoint = false;               ///< --up viewpoint: each input's own
  std::vector<double> gravity;                  ///< --gravity X,Y,Z, or empty
  std::optional<Eigen::Vector3d> up_direction;  ///< from `up` or `gravity`, checked
  bool quiet = false;
  bool track = false;                          ///< the inputs are one sequence; labels are track ids
  bool cold_starts = false;                    ///< --cold-starts: with --track, no head start
  std::optional<std::string> poses;            ///< --poses: the inputs' camera poses (JSON), with --track
  unsigned jobs = pcd_segment::defaultJobs();  ///< inputs segmented at once
  bool view = false;
  std::optional<std::string> snapshot;  ///< given: the file, or empty for <name>.snapshot.png
  pcd_segment::SnapshotSettings snapshot_settings;
};

void addInputOutputOptions(CLI::App& app, Options& options) {
  app.add_option("INPUT", options.inputs,
                 "PCD files, depth PNG files or directories of them (PNG only with --intrinsics); a directory's "
                 "entry named so that is not a file (a directory x.pcd) is reported as a failed input")
      ->required();
  app.add_option("-o,--output", options.output,
                 "A .pcd file, a .png file or a directory, by one rule in every mode. OUT ending in .pcd: the "
                 "labelled cloud when the inputs come to one file (refused for more), with --png, --json, "
                 "--overlay, --snapshot and --track --json writing OUT's stem + .png, .json, .overlay.png, "
                 ".snapshot.png, .tracks.json beside it. OUT ending in .png: the label image of --png instead "
                 "of the labelled cloud (no .pcd written), for one input as .pcd, the other outputs beside it "
                 "alike. OUT ending in / or without an extension, or an "
                 "existing directory: a directory (created if missing) receiving <name>.labels.pcd, "
                 ".labels.png, .planes.json, .overlay.png, .snapshot.png per input (<name>: the input's file "
                 "name without .pcd or .png) and tracks.json with --track --json. Any other extension "
                 "(out.txt) is refused; a new directory whose name has a dot is given with a trailing /")
      ->required();
}

void addOutputFlags(CLI::App& app, Options& options) {
  floodplane::cli::addAsciiFlag(app, options.ascii, "the label PCD");
  app.add_flag("--png", options.png, "Also write <name>.labels.png, " + floodplane::cli::labelImageHelp());
  app.add_flag("--overlay", options.overlay,
               "Also write <name>.overlay.png: the input's own colours (its rgb field) with each plane's colour "
               "blended half over its pixels, white where there is no point. An input without colour (no rgb "
               "field) gets a note instead; depth images have none");
  app.add_flag("--json", options.json, "Also write <name>.planes.json (planes, parameters, time)");
  app.add_flag("--objects", options.objects,
               "Also find the objects standing on the planes (floodplane::segmentObjects) and write "
               "<name>.objects.pcd (x y z label: object ids 1..K, largest first, 0 no object; <stem>.objects.pcd "
               "beside a single output file); with --json, each object's size, centroid, bounding box and "
               "supporting plane (its label: with --track, its track id) in <name>.planes.json's \"objects\"");
  app.add_flag("-q,--quiet", options.quiet, "Print only errors");
  app.add_flag("--track", options.track,
               "The inputs are one sequence of frames, in the order given (a directory's files sorted by name): "
               "each plane keeps an id while its surface stays in view, and the label field holds these track "
               "ids (0 no plane) instead of size ranks; with --json, each plane's \"track\" in <name>.planes.json "
               "and a summary of the tracks in OUT/tracks.json. Segments the frames in order on one thread (-j "
               "above 1 is refused); a frame that cannot be read is reported and skipped");
  app.add_flag("--cold-starts", options.cold_starts,
               "With --track: segment every frame from nothing. By default each frame continues from the one "
               "before (a head start: the previous frame's sensor noise model is taken again instead of measured, "
               "anew every 30 frames), which is faster on a stream");
  app.add_option_function<std::string>(
         "--poses", [&options](const std::string& path) { options.poses = path; },
         "With --track: the camera pose of each input, so that a plane keeps its id however the camera moved: "
         "before input k the tracker takes the motion inverse(W[j]) * W[k] from the last input segmented, j "
         "(k-1 unless that one failed). FILE is a JSON object whose \"poses\" array has one entry per input, in "
         "input order, each with \"world_from_camera\": the 4x4 rigid transform W from the camera's frame (the "
         "cloud's axes) to a fixed world frame, in metres, as 4 rows of 4 numbers; other keys are ignored. "
         "pcd_synth --sequence writes such a file (<scene>.poses.json)")
      ->type_name("FILE");
  app.add_option("-j,--jobs", options.jobs,
                 "Inputs segmented at once, each on a thread of its own (default: one per core); "
                 "outputs and messages are those of -j 1, in input order")
      ->check(CLI::Range(1u, 1024u))
      ->capture_default_str();
}

// The up direction the planes of --json are classed by (floodplane/plane_classes.h).
void addUpOptions(CLI::App& app, Options& options, CLI::Option* json) {
  // One token (allow_extra_args(false)), so that "--up viewpoint scene.pcd" leaves the input.
  CLI::Option* up =
      app.add_option("--up", options.up,
                     "With --json: the up direction (against gravity) in the cloud's frame, e.g. 0,-1,0 for a level "
                     "camera with y down (PCL's and ROS's optical frames), any length; each plane in "
                     "<name>.planes.json then has a \"class\" (floor, ceiling, wall, horizontal_surface or other) "
                     "and its \"height_above_floor\" in metres (null when no floor is in view). An IMU at rest "
                     "measures this direction. viewpoint: each input's own, from its PCD header's VIEWPOINT "
                     "rotation, the camera's orientation in a world whose z is up (as pcd_synth writes it; its "
                     "<scene>.planes.json has the same \"up\"); an input whose VIEWPOINT has no rotation (the "
                     "identity: most files) or a depth image fails with the reason")
          ->delimiter(',')
          ->allow_extra_args(false)
          ->type_name("X,Y,Z|viewpoint")
          ->needs(json);
  app.add_option("--gravity", options.gravity,
                 "The same as --up given the other way round: the direction gravity pulls (down) in the cloud's "
                 "frame, e.g. 0,1,0 for a level camera with y down")
      ->delimiter(',')
      ->expected(3)
      ->type_name("X,Y,Z")
      ->needs(json)
      ->excludes(up);
}

// The up direction of --up or --gravity, or nothing; throws std::invalid_argument naming the
// flag of a vector that is no direction.
// The numbers of --up X,Y,Z; throws std::invalid_argument naming the flag for anything else.
std::vector<double> upNumbers(const std::vector<std::string>& texts) {
  std::string given;
  for (const std::string& text : texts) given += (given.empty() ? "" : ",") + text;
  const std::invalid_argument error("--up takes X,Y,Z (three numbers) or viewpoint, not '" + given + "'");
  if (texts.size() != 3) throw error;
  std::vector<double> values;
  for (const std::string& text : texts) {
    std::size_t used = 0;
    try {
      values.push_back(std::stod(text, &used));
    } catch (const std::exception&) {
      throw error;
    }
    if (used != text.size()) throw error;
  }
  return values;
}

// --up viewpoint is each input's own: upFromViewpoint.
std::optional<Eigen::Vector3d> upDirection(const Options& options) {
  const bool from_gravity = !options.gravity.empty();
  if (!from_gravity && (options.up.empty() || options.up_from_viewpoint)) return std::nullopt;
  const std::vector<double> values = from_gravity ? options.gravity : upNumbers(options.up);
  if (values.empty()) return std::nullopt;
  const Eigen::Vector3d vector(values.at(0), values.at(1), values.at(2));
  if (!vector.allFinite() || vector.isZero(0.0)) {
    throw std::invalid_argument(std::string(from_gravity ? "--gravity" : "--up") +
                                " X,Y,Z must be a direction: three finite numbers, not all zero");
  }
  return from_gravity ? Eigen::Vector3d(-vector) : vector;
}

// The up direction of --up viewpoint for `points`: the world's z turned back by the camera's
// orientation in the world, the rotation of the file's VIEWPOINT. Throws std::runtime_error
// when it has none (the identity, which PCL writes for a cloud without a pose).
Eigen::Vector3d upFromViewpoint(const Cloud& points) {
  const Eigen::Quaterniond world_from_camera = points.sensor_orientation_.cast<double>().normalized();
  if (!world_from_camera.coeffs().allFinite() ||
      world_from_camera.angularDistance(Eigen::Quaterniond::Identity()) < 1e-6) {
    throw std::runtime_error(
        "--up viewpoint: the input has no VIEWPOINT rotation (the identity) to take the up direction from; give "
        "--up X,Y,Z");
  }
  return world_from_camera.conjugate() * Eigen::Vector3d::UnitZ();
}

// The 3-D outputs. The checks run while parsing, so a bad value fails before any work.
void addViewOptions(CLI::App& app, Options& options) {
  app.add_flag("--view", options.view,
               "Show the result in 3-D in a window (one input): points coloured as in the PNG, normals as "
               "arrows, outlines; keys n, z, b toggle normals, unlabelled points, outlines; v switches the camera "
               "between the sensor's view and an oblique one");
  CLI::Option* snapshot =
      app.add_option_function<std::string>(
             "--snapshot", [&options](const std::string& path) { options.snapshot = path; },
             "Also render that 3-D view, without a window, to FILE.png (one input) or, given no FILE, to "
             "<name>.snapshot.png beside the other outputs. Needs an X display: on a machine without "
             "one, run under xvfb-run -a")
          ->expected(0, 1)
          ->type_name("[FILE.png]")
          ->check([](const std::string& path) -> std::string {
            const bool png = path.size() > 4 && path.compare(path.size() - 4, 4, ".png") == 0;
            return path.empty() || png ? "" : "takes a file name ending in .png, not '" + path + "'";
          });
  app.add_option_function<std::string>(
         "--snapshot-size",
         [&options](const std::string& text) {
           const auto size = pcd_segment::parseImageSize(text);
           options.snapshot_settings.width = size->first;
           options.snapshot_settings.height = size->second;
         },
         "Snapshot width x height in pixels, each 16..8192 (default 800x600)")
      ->type_name("WxH")
      ->check([](const std::string& text) -> std::string {
        return pcd_segment::parseImageSize(text) ? "" : "'" + text + "' is not WxH with sides 16..8192";
      })
      ->needs(snapshot);
  app.add_option_function<std::string>(
         "--snapshot-camera",
         [&options](const std::string& name) {
           options.snapshot_settings.camera = *floodplane::view::parseCameraView(name);
         },
         "oblique (default: above and to the right of the sensor, so that the planes' tilt shows) or "
         "sensor (the label image's view)")
      ->check(CLI::IsMember({"oblique", "sensor"}))
      ->needs(snapshot);
}

// Everything segmentAndRefine gives for one cloud, and the time it took.
struct Segmented {
  Segmentation::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  std::vector<pcl::PointIndices> label_indices;
  std::vector<pcl::PointIndices> boundaries;
  Segmentation::PointCloudLPtr labels;
  floodplane::NoiseModel noise;
  bool head_start = false;  // continued from the previous frame (--track)
  double segmentation_ms = 0.0;
  std::optional<floodplane::ObjectSegmentation> objects;  // --objects
  double objects_ms = 0.0;                                // segmentObjects alone
};

Segmented segment(Segmentation& segmentation, const Cloud::ConstPtr& points, bool objects) {
  Segmented out;
  segmentation.setInputCloud(points);
  const auto start = std::chrono::steady_clock::now();
  segmentation.segmentAndRefine(out.regions, out.coefficients, out.inliers, out.labels, out.label_indices,
                                out.boundaries);
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  out.segmentation_ms = elapsed.count();
  out.noise = segmentation.getLastSegmentation().noise;
  out.head_start = segmentation.getLastSegmentation().stats.head_start;
  if (!out.labels || out.labels->size() != points->size()) {
    // The loader only passes organized clouds, so this is a library failure, not bad data.
    throw std::runtime_error("the segmentation returned no labels");
  }
  if (objects) {
    pcl::PointCloud<pcl::Label> object_labels;
    std::vector<pcl::PointIndices> object_indices;
    const auto objects_start = std::chrono::steady_clock::now();
    segmentation.segmentObjects(object_labels, object_indices);
    const std::chrono::duration<double, std::milli> objects_elapsed = std::chrono::steady_clock::now() - objects_start;
    out.objects_ms = objects_elapsed.count();
    out.objects = segmentation.getLastObjects();
  }
  return out;
}

// The JSON report's text. `track_ids`: each plane's track id with --track, empty without. With
// `up`, the planes are classed by it; `planes` are the core's planes (in the order of segmented's).
std::string reportText(const std::string& input, const Cloud& points, const floodplane::Params& params,
                       const Segmented& segmented, const std::vector<std::uint32_t>& track_ids,
                       const std::optional<Eigen::Vector3d>& up,
                       const std::vector<floodplane::SegmentedPlane>& planes) {
  pcd_segment::Report report;
  report.input = input;
  report.width = points.width;
  report.height = points.height;
  report.params = params;
  report.noise = segmented.noise;
  report.head_start = segmented.head_start;
  report.segmentation_ms = segmented.segmentation_ms;
  if (segmented.objects) {
    // In the cloud's frame, as the planes' figures: the core measured from the sensor origin.
    const Eigen::Vector3d origin = points.sensor_origin_.head<3>().cast<double>();
    report.objects = segmented.objects->objects;
    for (floodplane::SegmentedObject& object : *report.objects) {
      object.centroid += origin;
      object.min += origin;
      object.max += origin;
    }
    report.objects_ms = segmented.objects_ms;
  }
  report.planes = pcd_segment::planeRecords(segmented.coefficients, segmented.regions, segmented.inliers,
                                            segmented.boundaries, points.width);
  for (std::size_t k = 0; k < track_ids.size() && k < report.planes.size(); ++k) report.planes[k].track = track_ids[k];
  if (report.objects && !track_ids.empty()) {
    // With --track the labels hold track ids: an object's support names its plane the same way,
    // so that support 17 is the plane labelled 17.
    for (floodplane::SegmentedObject& object : *report.objects) {
      if (object.support > 0 && object.support <= track_ids.size()) object.support = track_ids[object.support - 1];
    }
  }
  if (up) {
    report.up = up->normalized();
    pcd_segment::describeRecords(report.planes, floodplane::describePlanes(planes, *up));
  }
  return floodplane::io::jsonText(pcd_segment::reportJson(report));
}

struct FileResult {
  std::size_t planes = 0;
  double segmentation_ms = 0.0;
  std::size_t width = 0;
  std::size_t height = 0;
  std::optional<floodplane::view::PlaneScene> scene;  ///< for --view
  std::vector<std::string> notes;  ///< said on stderr unless --quiet: an empty frame, an output not written
  /// The input's outputs, written to temporaries; renamed into place together once the
  /// snapshot, drawn on the main thread, has joined them: all of an input's outputs or none.
  floodplane::io::AtomicFileGroup outputs;
};

// Reads, segments and writes one input, the index-th, to temporaries (FileResult::outputs);
// throws std::runtime_error saying what went wrong, having removed them. With --track,
// `summary` takes the frame once it is segmented (the tracker has then seen it, whatever
// happens to the outputs), and with --poses the tracker takes the camera's motion from `motions`.
FileResult segmentFile(const std::string& input, std::size_t index, const pcd_segment::OutputPaths& paths,
                       Segmentation& segmentation, const Options& options, pcd_segment::TrackSummary* summary,
                       pcd_segment::CameraMotions* motions) {
  floodplane::io::InputFrame frame = floodplane::io::loadInputFrame(input, options.camera);
  const auto points = std::make_shared<Cloud>(std::move(frame.xyz));
  const std::optional<Eigen::Vector3d> up =
      options.json && options.up_from_viewpoint ? std::optional(upFromViewpoint(*points)) : options.up_direction;
  const std::size_t frames_taken = segmentation.getTracker().frameCount();
  if (motions) {
    if (const std::optional<Eigen::Matrix4d> motion = motions->motionTo(index)) segmentation.setCameraMotion(*motion);
  }
  const Segmented segmented = segment(segmentation, points, options.objects);
  if (motions && segmentation.getTracker().frameCount() > frames_taken) motions->taken(index);
  std::vector<std::uint32_t> track_labels;
  if (segmentation.getTracking()) {
    segmentation.getTracker().relabel(segmentation.getLastSegmentation().labels, track_labels);
    if (summary) summary->addFrame(input, segmentation.getTracker());
  }
  // The label cloud in the input's grid and pose (x y z [rgb] label), as the Python module writes it.
  const std::vector<std::uint32_t>& labels =
      segmentation.getTracking() ? track_labels : segmentation.getLastSegmentation().labels;
  FileResult result{
      segmented.coefficients.size(), segmented.segmentation_ms, points->width, points->height, {}, {}, {}};
  floodplane::io::AtomicFileGroup& outputs = result.outputs;
  if (paths.pcd.empty()) {
    // -o NAME.png: the label image instead of the cloud.
  } else if (frame.xyzrgb) {
    outputs.add(paths.pcd, pcd_segment::labelPcdBytes(
                               floodplane::io::labelledCloud<pcl::PointXYZRGBL>(*frame.xyzrgb, labels), options.ascii));
  } else {
    outputs.add(paths.pcd, pcd_segment::labelPcdBytes(floodplane::io::labelledCloud<pcl::PointXYZL>(*points, labels),
                                                      options.ascii));
  }
  if (segmented.objects) {
    outputs.add(paths.objects,
                pcd_segment::labelPcdBytes(
                    floodplane::io::labelledCloud<pcl::PointXYZL>(*points, segmented.objects->labels), options.ascii));
  }
  const std::vector<std::uint8_t> has_point = floodplane::io::finitePoints(*points);
  if (options.png || paths.pcd.empty()) {
    outputs.add(paths.png, floodplane::io::encodePng(
                               floodplane::io::labelImage(labels, has_point, points->width, points->height)));
  }
  if (std::find(has_point.begin(), has_point.end(), 1) == has_point.end()) {
    result.notes.push_back(floodplane::cli::kEmptyFrameNote);
  }
  if (options.overlay) {
    if (const std::optional<floodplane::io::RgbImage> colours = floodplane::io::frameColours(frame)) {
      outputs.add(paths.overlay, floodplane::io::encodePng(floodplane::io::overlayImage(labels, has_point, *colours)));
    } else {
      result.notes.push_back("no colour (rgb field) to lay the labels over: " + paths.overlay + " not written");
    }
  }
  if (options.json) {
    outputs.add(paths.json, reportText(input, *points, segmentation.getParams(), segmented, segmentation.getTrackIds(),
                                       up, segmentation.getLastSegmentation().planes));
  }
  if (options.snapshot || options.view) {
    result.scene = pcd_segment::planeScene(points, *segmented.labels, segmented.regions, segmented.coefficients,
                                           segmentation.getTrackIds());
  }
  return result;
}

// The snapshot of one input, when asked for, added to its outputs; drawn on the main thread
// (VTK renders from one thread).
void addSnapshotOf(const pcd_segment::OutputPaths& paths, FileResult& result, const Options& options) {
  if (!options.snapshot || !result.scene) return;
  const std::string& path = options.snapshot->empty() ? paths.snapshot : *options.snapshot;
  result.outputs.add(path, pcd_segment::snapshotPng(*result.scene, options.snapshot_settings));
}

// Whether two paths name one existing file (a symbolic or hard link to it too).
bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  return fs::equivalent(a, b, error) && !error;
}

// Every file the run would write (cf. segmentFile, addSnapshotOf, writeTrackSummary), for the
// check that none of them is an input.
std::vector<std::string> outputsOfRun(const std::vector<floodplane::io::InputFile>& files, const Options& options,
                                      bool single_file) {
  std::vector<std::string> outputs;
  // An input of a name already seen is refused on its own (batchItems), and a --snapshot file
  // for several inputs by checkViewOptions: neither is a collision of the run's outputs.
  std::set<std::string> names;
  for (const floodplane::io::InputFile& file : files) {
    if (!file.error.empty() || !names.insert(pcd_segment::outputName(file.path)).second) continue;
    const pcd_segment::OutputPaths paths = pcd_segment::outputPaths(file.path, options.output, single_file);
    if (!paths.pcd.empty()) outputs.push_back(paths.pcd);
    if (options.png || paths.pcd.empty()) outputs.push_back(paths.png);
    if (options.json) outputs.push_back(paths.json);
    if (options.overlay) outputs.push_back(paths.overlay);
    if (options.objects) outputs.push_back(paths.objects);
    if (options.snapshot && (options.snapshot->empty() || names.size() == 1)) {
      outputs.push_back(options.snapshot->empty() ? paths.snapshot : *options.snapshot);
    }
  }
  if (options.track && options.json) outputs.push_back(pcd_segment::tracksPath(options.output, single_file));
  return outputs;
}

// Every file the run reads.
std::vector<std::string> inputsOfRun(const std::vector<floodplane::io::InputFile>& files, const Options& options) {
  std::vector<std::string> inputs;
  for (const floodplane::io::InputFile& file : files) {
    if (file.error.empty()) inputs.push_back(file.path);
  }
  if (options.poses) inputs.push_back(*options.poses);
  return inputs;
}

bool createOutputDirectory(const fs::path& directory) {
  if (directory.empty()) return true;
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory)) {
    std::cerr << "pcd_segment: error: cannot create output directory '" << directory.string()
              << "': " << (error ? error.message() : "not a directory") << "\n";
    return false;
  }
  return true;
}

void printResult(const std::string& input, const FileResult& result, const std::string& output) {
  std::cout << fs::path(input).filename().string() << ": " << result.width << "x" << result.height << ", "
            << result.planes << (result.planes == 1 ? " plane, " : " planes, ") << std::fixed << std::setprecision(1)
            << result.segmentation_ms << " ms -> " << output << std::endl;
}

// One input of a batch: where its outputs go, and why it cannot be segmented if it cannot.
struct BatchItem {
  const floodplane::io::InputFile* file = nullptr;
  pcd_segment::OutputPaths paths;
  std::string error;
};

// The batch's items in input order. Refused here, before any work, so that the outcome does
// not depend on which thread gets there first: inputs the expansion found bad, and an input
// whose outputs would overwrite an earlier one's (two inputs of one name).
std::vector<BatchItem> batchItems(const std::vector<floodplane::io::InputFile>& files, const Options& options,
                                  bool single_file) {
  std::vector<BatchItem> items;
  std::map<std::string, std::string> file_of_name;
  for (const floodplane::io::InputFile& file : files) {
    BatchItem item;
    item.file = &file;
    item.error = file.error;
    if (item.error.empty()) {
      const auto [previous, inserted] = file_of_name.emplace(pcd_segment::outputName(file.path), file.path);
      if (!inserted) item.error = "has the same name as " + previous->second + ", whose outputs it would overwrite";
      item.paths = pcd_segment::outputPaths(file.path, options.output, single_file);
    }
    items.push_back(std::move(item));
  }
  return items;
}

// What segmenting one input came to: its result, or the error that stopped it.
struct Outcome {
  std::optional<FileResult> result;
  std::string error;
};

// Segments every input, options.jobs at a time, going on past failures; prints results and
// errors in input order and returns the number of inputs that failed. With --track, one
// segmentation takes the inputs in order on this thread, `summary` follows its tracks and
// `motions`, when given (--poses), has one pose per input.
std::size_t segmentAll(const std::vector<floodplane::io::InputFile>& files, const Options& options, bool single_file,
                       const floodplane::Params& params, pcd_segment::TrackSummary* summary,
                       pcd_segment::CameraMotions* motions) {
  const std::vector<BatchItem> items = batchItems(files, options, single_file);
  pcd_segment::ProgressBar progress(items.size(), !options.quiet && items.size() > 3 && ::isatty(2));
  progress.show(0);
  std::size_t failed = 0;
  const auto make_segmentation = [&params, &options]() {
    auto segmentation = std::make_unique<Segmentation>();
    segmentation->setParams(params);
    segmentation->setTracking(options.track);
    segmentation->setHeadStart(options.track && !options.cold_starts);
    return segmentation;
  };
  const auto segment_item = [&](std::unique_ptr<Segmentation>& segmentation, std::size_t i) {
    Outcome outcome;
    const BatchItem& item = items[i];
    if (!item.error.empty()) {
      outcome.error = item.error;
      return outcome;
    }
    try {
      outcome.result = segmentFile(item.file->path, i, item.paths, *segmentation, options, summary, motions);
    } catch (const std::exception& error) {
      outcome.error = error.what();
    } catch (...) {
      outcome.error = "unknown error";
    }
    return outcome;
  };
  const auto report = [&](std::size_t i, Outcome& outcome) {
    const BatchItem& item = items[i];
    progress.clear();
    if (outcome.result) {
      try {
        addSnapshotOf(item.paths, *outcome.result, options);
        outcome.result->outputs.commit();
        if (!options.quiet) {
          printResult(item.file->path, *outcome.result, item.paths.pcd.empty() ? item.paths.png : item.paths.pcd);
        }
        for (const std::string& note : outcome.result->notes) {
          if (!options.quiet) std::cerr << "pcd_segment: note: " << item.file->path << ": " << note << "\n";
        }
        if (options.view && outcome.result->scene) {
          floodplane::view::showWindow(*outcome.result->scene, "pcd_segment: " + item.file->path);
        }
      } catch (const std::exception& error) {
        outcome.error = error.what();
      }
    }
    if (!outcome.error.empty()) {
      if (outcome.result) outcome.result->outputs = {};  // none of the input's outputs
      std::cerr << "pcd_segment: error: " << item.file->path << ": " << outcome.error << "\n";
      ++failed;
    }
    progress.show(i + 1);
  };
  // --view opens a window per input on the main thread: one at a time. --track: a tracker
  // takes the frames in order, so one segmentation does them all, here.
  const unsigned jobs = options.view || options.track ? 1u : options.jobs;
  pcd_segment::runInOrder(items.size(), jobs, make_segmentation, segment_item, report);
  progress.clear();
  return failed;
}

// tracks.json, written once the sequence is done (atomically: a reader never sees half of it).
// False after saying why when it cannot be written.
bool writeTrackSummary(const pcd_segment::TrackSummary& summary, const Options& options, bool single_file) {
  const std::string path = pcd_segment::tracksPath(options.output, single_file);
  try {
    floodplane::io::writeBytesAtomically(path, floodplane::io::jsonText(summary.json()));
  } catch (const std::exception& error) {
    std::cerr << "pcd_segment: error: " << path << ": " << error.what() << "\n";
    return false;
  }
  if (!options.quiet) {
    std::cout << summary.tracks().size() << " tracks over " << summary.frames().size() << " frames -> " << path
              << std::endl;
  }
  return true;
}

// --view and --snapshot FILE are about one input, and both need a display: checked before any
// work, so that a batch does not segment everything and then fail on every image. Returns
// the exit code when the program is done.
std::optional<int> checkViewOptions(CLI::App& app, const Options& options, std::size_t inputs) {
  if (options.view && inputs > 1) {
    return floodplane::cli::usageError(app, "--view shows one input, but there are " + std::to_string(inputs));
  }
  if (options.snapshot && !options.snapshot->empty() && inputs > 1) {
    return floodplane::cli::usageError(
        app, "--snapshot " + *options.snapshot + " names one image, but there are " + std::to_string(inputs) +
                 " inputs; give --snapshot without a file name for <name>.snapshot.png in the output directory");
  }
  if (options.view || options.snapshot) {
    if (const std::optional<std::string> reason = floodplane::view::renderingUnavailableReason()) {
      std::cerr << "pcd_segment: error: cannot draw in 3-D: " << *reason << "\n";
      return 1;
    }
  }
  return std::nullopt;
}

// The poses of --poses, one per input; throws std::runtime_error with a one-line message.
pcd_segment::CameraMotions readPoses(const std::string& path, std::size_t inputs) {
  std::vector<Eigen::Matrix4d> poses = pcd_segment::readCameraPoses(path);
  if (poses.size() != inputs) {
    throw std::runtime_error(path + ": " + std::to_string(poses.size()) + (poses.size() == 1 ? " pose" : " poses") +
                             " for " + std::to_string(inputs) + (inputs == 1 ? " input" : " inputs") +
                             "; give one per input, in input order");
  }
  return pcd_segment::CameraMotions(std::move(poses));
}

}  // namespace

int main(int argc, char** argv) {
  // First, before any thread starts (see there): Ctrl-C leaves no temporary file behind.
  floodplane::cli::removeTemporariesOnInterrupt("pcd_segment");
  // Only pcd_segment's own messages: PCL's reader logs its failures, which are reported here.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);

  Options options;
  CLI::App app{kDescription, "pcd_segment"};
  floodplane::cli::addVersionFlag(app);
  addInputOutputOptions(app, options);
  floodplane::cli::addParameterOptions(app, options.params);
  floodplane::cli::addDepthInputOptions(app, options.depth);
  addOutputFlags(app, options);
  addUpOptions(app, options, app.get_option("--json"));
  addViewOptions(app, options);
  if (const std::optional<int> exit_code = floodplane::cli::parseCommandLine(app, argc, argv)) return *exit_code;

  try {
    // The library's own check of the values, before any work; its message names its fields.
    Segmentation().setParams(options.params);
  } catch (const std::invalid_argument& e) {
    return floodplane::cli::usageError(app, floodplane::cli::inFlagTerms(e.what()));
  }
  try {
    options.camera = floodplane::cli::depthCamera(options.depth);
    options.up_from_viewpoint = options.up == std::vector<std::string>{"viewpoint"};
    options.up_direction = upDirection(options);
  } catch (const std::invalid_argument& e) {
    return floodplane::cli::usageError(app, e.what());
  }

  const std::vector<floodplane::io::InputFile> files =
      floodplane::cli::expandFrameInputs(options.inputs, options.camera.has_value());
  if (const std::optional<std::string> problem = floodplane::cli::missingCamera(files, options.camera.has_value())) {
    return floodplane::cli::usageError(app, *problem);
  }
  bool single_file = false;
  try {
    single_file = floodplane::cli::outputKind("-o", options.output, {".pcd", ".png"}, kOutputMeaning) ==
                  floodplane::cli::OutputKind::file;
  } catch (const std::invalid_argument& e) {
    return floodplane::cli::usageError(app, e.what());
  }
  const std::string file_kind = pcd_segment::namesLabelImage(options.output) ? ".png" : ".pcd";
  if (single_file && files.size() > 1) {
    // A directory called "x.pcd" is almost surely a mistake, so this is refused.
    return floodplane::cli::usageError(app, "-o " + options.output + " names one " + file_kind +
                                                " file, but there are " + std::to_string(files.size()) +
                                                " inputs; give a directory");
  }
  if (single_file && files.size() == 1 && sameFile(files.front().path, options.output)) {
    return floodplane::cli::usageError(
        app, "-o " + options.output + " is the input itself; give the " + file_kind + " file another name");
  }
  if (const std::optional<std::string> collision =
          floodplane::io::outputCollision(outputsOfRun(files, options, single_file), inputsOfRun(files, options))) {
    return floodplane::cli::usageError(app, *collision + "; nothing written: give another -o");
  }
  if (const std::optional<int> exit_code = checkViewOptions(app, options, files.size())) return *exit_code;
  if (options.overlay && std::all_of(files.begin(), files.end(), [](const floodplane::io::InputFile& file) {
        return floodplane::io::isDepthImagePath(file.path);
      })) {
    return floodplane::cli::usageError(
        app, "--overlay lays the labels over the input's colours, and depth images have none");
  }
  if (options.cold_starts && !options.track) {
    return floodplane::cli::usageError(app, "--cold-starts turns off the head start of --track: it needs --track");
  }
  if (options.poses && !options.track) {
    return floodplane::cli::usageError(app, "--poses gives the camera motion to the tracker: it needs --track");
  }
  if (options.track && options.jobs > 1 && app.get_option("--jobs")->count() > 0) {
    return floodplane::cli::usageError(app, "--track segments the frames in order on one thread; -j " +
                                                std::to_string(options.jobs) + " cannot apply (leave -j out)");
  }
  std::optional<pcd_segment::CameraMotions> motions;
  if (options.poses) {
    try {
      motions.emplace(readPoses(*options.poses, files.size()));
    } catch (const std::runtime_error& error) {
      std::cerr << "pcd_segment: error: --poses " << error.what() << "\n";
      return 1;
    }
  }
  if (!createOutputDirectory(single_file ? fs::path(options.output).parent_path() : fs::path(options.output))) {
    return 1;
  }
  pcd_segment::TrackSummary summary;
  const std::size_t failed = segmentAll(files, options, single_file, options.params, options.track ? &summary : nullptr,
                                        motions ? &*motions : nullptr);
  if (failed > 0 && files.size() > 1) {
    std::cerr << "pcd_segment: " << failed << " of " << files.size() << " inputs failed\n";
  }
  const bool summary_written = !(options.track && options.json) || writeTrackSummary(summary, options, single_file);
  return failed > 0 || !summary_written ? 1 : 0;
}
