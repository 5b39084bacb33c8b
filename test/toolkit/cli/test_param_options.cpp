// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The library's messages about parameters in the apps' terms: the flag of every field.

#include "cli/param_options.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "floodplane/flood_fill_plane_segmentation.h"
#include "floodplane/io/params_json.h"
#include "params/params_table.h"

namespace floodplane::test {
namespace {

struct BadValue {
  std::string flag;
  std::function<void(Params&)> spoil;
};

// One bad value per field that can have one, with the flag the message must name.
const std::vector<BadValue>& badValues() {
  static const std::vector<BadValue> values = {
      {"--distance-threshold", [](Params& p) { p.distance_threshold = -0.01; }},
      {"--seed-size", [](Params& p) { p.seed_size = 0.0; }},
      {"--angular-threshold", [](Params& p) { p.angular_threshold = 2.0; }},
      {"--merge-distance", [](Params& p) { p.merge_distance = std::nan(""); }},
      {"--subsample", [](Params& p) { p.subsampling = 3; }},
      {"--maximum-curvature", [](Params& p) { p.maximum_curvature = -1.0; }},
      {"--depth-noise-coefficient", [](Params& p) { p.depth_noise_coefficient = -1.0; }},
      {"--depth-noise-constant", [](Params& p) { p.depth_noise_constant = -1.0; }},
  };
  return values;
}

void expectInFlagTerms(const std::string& message, const std::string& flag) {
  EXPECT_EQ(message.rfind(flag + " ", 0), 0u) << message;
  for (const std::string library_name :
       {"floodplane::", "distance_threshold", "seed_size", "angular_threshold", "merge_distance", "subsampling",
        "maximum_curvature", "depth_noise", "setSubsampling", "setParams"}) {
    EXPECT_EQ(message.find(library_name), std::string::npos) << message;
  }
}

TEST(InFlagTerms, NamesTheFlagOfEveryFieldParamsProblemNames) {
  for (const BadValue& bad : badValues()) {
    SCOPED_TRACE(bad.flag);
    Params params;
    bad.spoil(params);
    ASSERT_FALSE(params.problem().empty());
    expectInFlagTerms(cli::inFlagTerms(params.problem()), bad.flag);
  }
  EXPECT_EQ(cli::inFlagTerms(Params().problem()), "");
}

TEST(InFlagTerms, NamesTheFlagInPlaceOfTheSetterThatRefusedTheValue) {
  for (const BadValue& bad : badValues()) {
    SCOPED_TRACE(bad.flag);
    Params params;
    bad.spoil(params);
    try {
      FloodFillPlaneSegmentation<pcl::PointXYZ>().setParams(params);
      ADD_FAILURE() << "setParams took a bad value";
    } catch (const std::invalid_argument& error) {
      expectInFlagTerms(cli::inFlagTerms(error.what()), bad.flag);
    }
  }
  try {
    FloodFillPlaneSegmentation<pcl::PointXYZ>().setSubsampling(3);
    ADD_FAILURE() << "setSubsampling took 3";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(cli::inFlagTerms(error.what()), "--subsample must be 1, 2, 4 or 8, got 3");
  }
}

TEST(InFlagTerms, LeavesWordsThatOnlyContainAFieldsNameAlone) {
  EXPECT_EQ(cli::inFlagTerms("subsamplings and my_seed_size stay"), "subsamplings and my_seed_size stay");
}

// The mapping's flags are the options' names: every flag a message can name is an option.
TEST(AddParameterOptions, AddsAnOptionForEveryFlagTheMessagesName) {
  CLI::App app;
  Params params;
  cli::addParameterOptions(app, params);
  for (const BadValue& bad : badValues()) EXPECT_NO_THROW(app.get_option(bad.flag)) << bad.flag;
  EXPECT_NO_THROW(app.get_option("--min-inliers"));
}

// ---- the list of params_table.h reaches every field through every interface ---------------

// The list has every field of Params: the structured binding names exactly as many as the
// struct has (it does not compile otherwise), the list counts as many entries.
TEST(ParamsTable, ListsEveryFieldOfParams) {
  [[maybe_unused]] const auto& [f1, f2, f3, f4, f5, f6, f7, f8, f9] = Params();
  static_assert(params_table::kCount == 9, "a Params field missing from params_table.h, or one too many");
}

// A value of each kind that differs from its default and passes Params::problem().
double valueOf(params_table::Length) { return 0.02; }
double valueOf(params_table::Angle) { return 0.2; }
unsigned valueOf(params_table::Count) { return 50; }
double valueOf(params_table::Fraction) { return 0.01; }
int valueOf(params_table::Subsampling) { return 2; }
double valueOf(params_table::Noise) { return 0.001; }

template <typename T>
std::string asText(T value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Every parameter through its flag, its PCL setter and JSON: each lands in its own field.
// Python's keywords are tested by test_api.py (PARAMETER_NAMES are the fields of params.h).
TEST(ParamsTable, EveryParameterIsReachableFromEachInterface) {
  int checked = 0;
#define FLOODPLANE_REACH(field, kind, flag, setter, help)                                        \
  {                                                                                              \
    SCOPED_TRACE(#field);                                                                        \
    const auto value = valueOf(params_table::kind{});                                            \
    CLI::App app;                                                                                \
    Params from_flag;                                                                            \
    cli::addParameterOptions(app, from_flag);                                                    \
    const std::vector<std::string> arguments = {asText(value), flag};                            \
    std::vector<std::string> reversed = arguments;                                               \
    app.parse(reversed);                                                                         \
    EXPECT_TRUE(from_flag.field == value) << flag;                                               \
    FloodFillPlaneSegmentation<pcl::PointXYZ> segmentation;                                      \
    segmentation.setter(value);                                                                  \
    EXPECT_TRUE(segmentation.getParams().field == value) << #setter;                             \
    const nlohmann::ordered_json json = io::paramsJson(from_flag);                               \
    ASSERT_TRUE(json.contains(#field));                                                          \
    EXPECT_TRUE(json[#field] == value);                                                          \
    EXPECT_NE(cli::inFlagTerms(std::string(#field) + " must be").find(flag), std::string::npos); \
    ++checked;                                                                                   \
  }
  FLOODPLANE_PARAMETERS(FLOODPLANE_REACH)
#undef FLOODPLANE_REACH
  EXPECT_EQ(checked, params_table::kCount);
  EXPECT_EQ(io::paramsJson(Params()).size(), static_cast<std::size_t>(params_table::kCount));
}

}  // namespace
}  // namespace floodplane::test
