// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "common/param_options.h"

#include <CLI/CLI.hpp>

#include <cctype>

namespace floodplane::apps {
namespace {

// Every parameter: its Params field, its flag and its FloodFillPlaneSegmentation setter.
struct ParameterName {
  const char* field;
  const char* flag;
  const char* setter;
};

constexpr ParameterName kParameterNames[] = {
    {"distance_threshold", "--distance-threshold", "setDistanceThreshold"},
    {"seed_size", "--seed-size", "setSeedSize"},
    {"angular_threshold", "--angular-threshold", "setAngularThreshold"},
    {"merge_distance", "--merge-distance", "setMergeDistance"},
    {"min_inliers", "--min-inliers", "setMinInliers"},
    {"subsampling", "--subsample", "setSubsampling"},
    {"maximum_curvature", "--maximum-curvature", "setMaximumCurvature"},
    {"depth_noise_coefficient", "--depth-noise-coefficient", "setDepthNoiseCoefficient"},
    {"depth_noise_constant", "--depth-noise-constant", "setDepthNoiseConstant"},
};

std::string flagOf(const std::string& field) {
  for (const ParameterName& name : kParameterNames) {
    if (field == name.field) return name.flag;
  }
  return field;  // unreachable for the fields listed above; a typo shows in --help
}

bool isWordCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// `text` with every whole-word `word` replaced by `replacement`.
std::string replaceWord(std::string text, const std::string& word, const std::string& replacement) {
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at)) {
    const std::size_t end = at + word.size();
    const bool whole =
        (at == 0 || !isWordCharacter(text[at - 1])) && (end == text.size() || !isWordCharacter(text[end]));
    if (!whole) {
      at = end;
      continue;
    }
    text.replace(at, word.size(), replacement);
    at += replacement.size();
  }
  return text;
}

}  // namespace

// The paper's lengths are left out by default: then they follow the frame's noise and pixel
// footprint (scale-free); given, they are fixed lengths as in the paper.
void addParameterOptions(CLI::App& app, Params& params) {
  app.add_option(flagOf("distance_threshold"), params.distance_threshold,
                 "sigma_plane [m]: largest point-to-plane distance in the flood (Eq. 2); default: "
                 "3 noise deviations (the paper: 0.01)");
  app.add_option(flagOf("seed_size"), params.seed_size,
                 "sigma_seed [m]: side of the seed cube; default: from the noise and the pixel size (the paper: 0.06)");
  app.add_option(flagOf("angular_threshold"), params.angular_threshold,
                 "theta_angle [rad]: largest angle between normals in the seed and merge tests")
      ->capture_default_str();
  app.add_option(flagOf("merge_distance"), params.merge_distance,
                 "sigma_plane-merge [m]: largest centroid-to-plane distance of merging planes; default: "
                 "3 noise deviations (the paper: 0.03)");
  app.add_option(flagOf("min_inliers"), params.min_inliers,
                 "Smallest number of points of a plane; default: one pixel in a thousand");
  app.add_option(flagOf("subsampling"), params.subsampling,
                 "Segment every n-th pixel of every n-th row (1, 2, 4 or 8); labels stay full size")
      ->capture_default_str();
  app.add_option(flagOf("maximum_curvature"), params.maximum_curvature,
                 "Largest curvature of a plane (1/3 accepts every plane)")
      ->capture_default_str();
  app.add_option(flagOf("depth_noise_coefficient"), params.depth_noise_coefficient,
                 "c [1/m] of the depth noise sigma_0 + c r^2; default: measured on each frame");
  app.add_option(flagOf("depth_noise_constant"), params.depth_noise_constant,
                 "sigma_0 [m] of the depth noise sigma_0 + c r^2; default: measured on each frame");
}

std::string inFlagTerms(const std::string& message) {
  std::string text = message;
  // "floodplane::Params: ..." and "floodplane::FloodFillPlaneSegmentation::setSubsampling: ...":
  // the class and setter say where in the library, which a command-line user does not need.
  if (text.rfind("floodplane::", 0) == 0) {
    const std::size_t colon = text.find(": ");
    if (colon != std::string::npos) text.erase(0, colon + 2);
  }
  for (const ParameterName& name : kParameterNames) {
    text = replaceWord(text, name.field, name.flag);
    text = replaceWord(text, name.setter, name.flag);
  }
  return text;
}

}  // namespace floodplane::apps
