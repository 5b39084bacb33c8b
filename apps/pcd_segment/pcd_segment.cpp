// pcd_segment: segments organized PCD files into planes and writes the labels (PCD, and
// optionally PNG and a JSON report). Argument parsing and file I/O only; the segmentation is
// floodplane::FloodFillPlaneSegmentation.

#include <CLI/CLI.hpp>
#include <pcl/console/print.h>
#include <unistd.h>

#include <pcl/common/io.h>

#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "io/atomic_file.h"
#include "io/label_palette.h"
#include "io/png_file.h"
#include "floodplane/version.h"
#include "inputs.h"
#include "label_pcd.h"
#include "load_cloud.h"
#include "planes_json.h"
#include "progress.h"

namespace {

namespace fs = std::filesystem;
using Segmentation = floodplane::FloodFillPlaneSegmentation<pcl::PointXYZ>;

struct Options {
  std::vector<std::string> inputs;
  std::string output;
  floodplane::Params params;
  bool ascii = false;
  bool png = false;
  bool json = false;
  bool quiet = false;
};

struct FileResult {
  std::size_t planes = 0;
  double segmentation_ms = 0.0;
  std::size_t width = 0;
  std::size_t height = 0;
};

// The label cloud in the input's grid and pose: x y z [rgb] label.
template <typename PointOut, typename PointIn>
pcl::PointCloud<PointOut> labelledCloud(const pcl::PointCloud<PointIn>& points,
                                        const pcl::PointCloud<pcl::Label>& labels) {
  pcl::PointCloud<PointOut> out;
  pcl::copyPointCloud(points, out);  // keeps the grid, is_dense and the sensor pose
  for (std::size_t i = 0; i < out.size(); ++i) out[i].label = labels[i].label;
  return out;
}

// Reads, segments and writes one input; throws std::runtime_error saying what went wrong.
FileResult segmentFile(const std::string& input, const pcd_segment::OutputPaths& paths,
                       Segmentation& segmentation, const Options& options) {
  const pcd_segment::LoadedCloud cloud = pcd_segment::loadOrganizedCloud(input);
  const auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(cloud.xyz);
  segmentation.setInputCloud(points);

  Segmentation::Regions regions;
  std::vector<pcl::ModelCoefficients> coefficients;
  std::vector<pcl::PointIndices> inliers;
  std::vector<pcl::PointIndices> label_indices;
  std::vector<pcl::PointIndices> boundaries;
  Segmentation::PointCloudLPtr labels;
  const auto start = std::chrono::steady_clock::now();
  segmentation.segmentAndRefine(regions, coefficients, inliers, labels, label_indices, boundaries);
  const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - start;
  if (!labels || labels->size() != points->size()) {
    // The loader only passes organized clouds, so this is a library failure, not bad data.
    throw std::runtime_error("the segmentation returned no labels");
  }

  if (cloud.has_color) {
    pcd_segment::writeLabelPcd(paths.pcd, labelledCloud<pcl::PointXYZRGBL>(cloud.xyzrgb, *labels), options.ascii);
  } else {
    pcd_segment::writeLabelPcd(paths.pcd, labelledCloud<pcl::PointXYZL>(cloud.xyz, *labels), options.ascii);
  }
  if (options.png) {
    std::vector<std::uint32_t> grid(labels->size());
    for (std::size_t i = 0; i < grid.size(); ++i) grid[i] = (*labels)[i].label;
    floodplane::io::writePng(paths.png, floodplane::io::labelImage(grid, labels->width, labels->height));
  }
  if (options.json) {
    pcd_segment::Report report;
    report.input = input;
    report.width = points->width;
    report.height = points->height;
    report.params = segmentation.getParams();
    report.segmentation_ms = elapsed.count();
    report.planes = pcd_segment::planeRecords(coefficients, regions, inliers, boundaries, points->width);
    floodplane::io::writeBytesAtomically(paths.json, pcd_segment::reportJson(report).dump(2) + "\n");
  }
  return {coefficients.size(), elapsed.count(), points->width, points->height};
}

// Feeds the options to the library's setters, which reject bad values with a message naming
// the setter; the app reports that message rather than repeating the rules here.
void applyParams(Segmentation& segmentation, const floodplane::Params& params) {
  segmentation.setDistanceThreshold(params.distance_threshold);
  segmentation.setSeedSize(params.seed_size);
  segmentation.setAngularThreshold(params.angular_threshold);
  segmentation.setMergeDistance(params.merge_distance);
  segmentation.setMinInliers(params.min_inliers);
  segmentation.setSubsampling(params.subsampling);
  segmentation.setMaximumCurvature(params.maximum_curvature);
  segmentation.setDepthNoiseCoefficient(params.depth_noise_coefficient);
}

int usageError(const CLI::App& app, const std::string& message) {
  std::cerr << "pcd_segment: error: " << message << "\n\n" << app.help();
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  // Only pcd_segment's own messages: PCL's reader logs its failures, which are reported here.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);

  Options options;
  floodplane::Params& params = options.params;
  CLI::App app{
      "Segments organized point clouds into planes (flood fill, Roychoudhury et al.). Each "
      "INPUT is a PCD file with x y z fields, or a directory of them. Writes per input a "
      "labelled cloud (x y z [rgb] label: 0 no plane, 1..K planes by size, largest first): "
      "OUT itself for one input and OUT ending in .pcd, otherwise OUT/<name>.labels.pcd.",
      "pcd_segment"};
  app.set_version_flag("--version", FLOODPLANE_VERSION_STRING);
  app.add_option("inputs", options.inputs, "PCD files or directories of PCD files")->required();
  app.add_option("-o,--output", options.output,
                 "Output .pcd file (one input) or directory (created if missing)")
      ->required();
  app.add_option("--distance-threshold", params.distance_threshold,
                 "sigma_plane [m]: largest point-to-plane distance in the flood (Eq. 2)")
      ->capture_default_str();
  app.add_option("--seed-size", params.seed_size, "sigma_seed [m]: side of the seed cube")
      ->capture_default_str();
  app.add_option("--angular-threshold", params.angular_threshold,
                 "theta_angle [rad]: largest angle between normals in the seed and merge tests")
      ->capture_default_str();
  app.add_option("--merge-distance", params.merge_distance,
                 "sigma_plane-merge [m]: largest centroid-to-plane distance of merging planes")
      ->capture_default_str();
  app.add_option("--min-inliers", params.min_inliers, "Smallest number of points of a plane")
      ->capture_default_str();
  app.add_option("--subsample", params.subsampling,
                 "Segment every n-th pixel of every n-th row (1, 2, 4 or 8); labels stay full size")
      ->capture_default_str();
  app.add_option("--maximum-curvature", params.maximum_curvature,
                 "Largest curvature of a plane (1/3 accepts every plane)")
      ->capture_default_str();
  app.add_option("--depth-noise-coefficient", params.depth_noise_coefficient,
                 "c [1/m] of the depth noise c r^2 (0: fixed thresholds, for exact data)")
      ->capture_default_str();
  app.add_flag("--ascii", options.ascii, "Write the label PCD as text (default: binary compressed)");
  app.add_flag("--png", options.png, "Also write <name>.labels.png (a colour per plane)");
  app.add_flag("--json", options.json,
               "Also write <name>.planes.json (planes, parameters, time)");
  app.add_flag("-q,--quiet", options.quiet, "Print only errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return usageError(app, e.what());
  }

  Segmentation segmentation;
  try {
    applyParams(segmentation, params);
  } catch (const std::invalid_argument& e) {
    return usageError(app, e.what());
  }

  const std::vector<pcd_segment::InputFile> files = pcd_segment::expandInputs(options.inputs);
  const bool single_file = pcd_segment::namesPcdFile(options.output) && files.size() == 1;
  if (pcd_segment::namesPcdFile(options.output) && files.size() > 1) {
    // A directory called "x.pcd" is almost surely a mistake, so this is refused.
    return usageError(app, "-o " + options.output + " names one .pcd file, but there are " +
                               std::to_string(files.size()) + " inputs; give a directory");
  }
  const fs::path output_dir =
      single_file ? fs::path(options.output).parent_path() : fs::path(options.output);
  if (!output_dir.empty()) {
    std::error_code error;
    fs::create_directories(output_dir, error);
    if (error || !fs::is_directory(output_dir)) {
      std::cerr << "pcd_segment: error: cannot create output directory '" << output_dir.string()
                << "': " << (error ? error.message() : "not a directory") << "\n";
      return 1;
    }
  }

  pcd_segment::ProgressBar progress(files.size(), !options.quiet && files.size() > 3 && ::isatty(2));
  std::map<std::string, std::string> file_of_name;  // two inputs of one name, one output
  std::size_t failed = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    progress.show(i);
    const pcd_segment::InputFile& file = files[i];
    try {
      if (!file.error.empty()) throw std::runtime_error(file.error);
      const std::string name = pcd_segment::outputName(file.path);
      const auto [previous, inserted] = file_of_name.emplace(name, file.path);
      if (!inserted) {
        throw std::runtime_error("has the same name as " + previous->second +
                                 ", whose outputs it would overwrite");
      }
      const pcd_segment::OutputPaths paths = pcd_segment::outputPaths(file.path, options.output, single_file);
      const FileResult result = segmentFile(file.path, paths, segmentation, options);
      progress.clear();
      if (!options.quiet) {
        std::cout << fs::path(file.path).filename().string() << ": " << result.width << "x" << result.height
                  << ", " << result.planes << (result.planes == 1 ? " plane, " : " planes, ")
                  << std::fixed << std::setprecision(1) << result.segmentation_ms << " ms -> " << paths.pcd << std::endl;
      }
    } catch (const std::exception& error) {
      progress.clear();
      std::cerr << "pcd_segment: error: " << file.path << ": " << error.what() << "\n";
      ++failed;
    }
  }
  progress.clear();
  if (failed > 0 && files.size() > 1) {
    std::cerr << "pcd_segment: " << failed << " of " << files.size() << " inputs failed\n";
  }
  return failed > 0 ? 1 : 0;
}
