// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The lists of parameters that other languages need are written from src/params/params_table.h
// by the build (codegen/param_lists.h): the Python stubs' keywords and the ROS node's
// dynamic_reconfigure entries. Here they are held to the table and Params: each keyword has the
// member's type, each entry its type, default and a range (and choices) the library accepts, and
// the templates hold no parameter of their own. The nodelet's reading of the config stays
// hand-written (settingsFromConfig): every parameter read from its namesake, 0 taken as
// "derived" where the config says so. Each check is also run on doctored input, to show that
// it finds what it is for.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "floodplane/params.h"
#include "param_lists.h"
#include "params/params_table.h"

namespace floodplane {
namespace {

using param_lists::IsOptional;
using param_lists::ReconfigureEntry;
using param_lists::Unwrapped;

// ---- the table ----------------------------------------------------------------------------

// A parameter as the table and Params give it.
struct Parameter {
  std::string name;
  std::string kind;                // the table's tag: Length, Angle, ...
  bool optional = false;           // unset is a value of its own (derived or measured)
  bool integral = false;           // int or std::uint32_t, not double
  std::optional<double> fallback;  // Params' default; none when unset
  // Params with this parameter set to `value`, the rest at their defaults.
  Params (*with)(double value) = nullptr;
};

template <typename T>
std::optional<double> defaultOf(const T& value) {
  if constexpr (IsOptional<T>::value) {
    return value ? std::optional<double>(static_cast<double>(*value)) : std::nullopt;
  } else {
    return static_cast<double>(value);
  }
}

#define FLOODPLANE_PARAMETER_ENTRY(field, kind, flag, setter, help)                        \
  Parameter{#field,                                                                        \
            #kind,                                                                         \
            IsOptional<decltype(Params::field)>::value,                                    \
            std::is_integral_v<Unwrapped<decltype(Params::field)>::type>,                  \
            defaultOf(Params().field),                                                     \
            [](double value) {                                                             \
              Params params;                                                               \
              params.field = static_cast<Unwrapped<decltype(Params::field)>::type>(value); \
              return params;                                                               \
            }},
const std::vector<Parameter>& table() {
  static const std::vector<Parameter> parameters = {FLOODPLANE_PARAMETERS(FLOODPLANE_PARAMETER_ENTRY)};
  return parameters;
}
#undef FLOODPLANE_PARAMETER_ENTRY

const Parameter* findParameter(const std::string& name) {
  for (const Parameter& parameter : table())
    if (parameter.name == name) return &parameter;
  return nullptr;
}

// ---- text ---------------------------------------------------------------------------------

std::string readSource(const std::string& path) {
  std::ifstream file(std::string(FLOODPLANE_SOURCE_DIR) + "/" + path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

std::string shown(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& problem : problems) text += "\n  " + problem;
  return text;
}

bool mentions(const std::vector<std::string>& problems, const std::string& part) {
  return std::any_of(problems.begin(), problems.end(),
                     [&part](const std::string& problem) { return problem.find(part) != std::string::npos; });
}

// Replaces the first `from` in `text` by `to`; the test fails if there is none.
std::string doctored(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not found: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

const char* const kStubsTemplate = "python/floodplane/__init__.pyi.in";
const char* const kCfgTemplate = "ros/floodplane_ros/cfg/Segmentation.cfg.in";
const char* const kNodelet = "ros/floodplane_ros/src/segmentation_nodelet.cpp";

// ---- the Python stubs ---------------------------------------------------------------------

std::string pythonType(const Parameter& parameter) {
  const std::string type = parameter.integral ? "int" : "float";
  return parameter.optional ? "Optional[" + type + "]" : type;
}

TEST(ParamLists, TheTableHasEveryParameterOnce) {
  ASSERT_EQ(table().size(), static_cast<std::size_t>(params_table::kCount));
  std::set<std::string> names;
  for (const Parameter& parameter : table()) EXPECT_TRUE(names.insert(parameter.name).second) << parameter.name;
}

TEST(ParamLists, TheStubKeywordsAreTheTablesInItsOrderWithTheMembersTypes) {
  const std::vector<std::string> lines = param_lists::stubKeywordLines();
  ASSERT_EQ(lines.size(), table().size());
  for (std::size_t k = 0; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k], table()[k].name + ": " + pythonType(table()[k]) + " = ...,");
  }
}

TEST(ParamLists, TheStubsGetTheKeywordsAtEachMarkerAndSpellOutNoneByHand) {
  const std::string stubs = readSource(kStubsTemplate);
  ASSERT_FALSE(stubs.empty()) << kStubsTemplate;
  // Segmenter(), segment(), segment_depth() twice, segment_file().
  const std::size_t markers = occurrences(stubs, param_lists::kStubKeywordsMarker);
  EXPECT_EQ(markers, 5u);
  for (const Parameter& parameter : table()) {
    EXPECT_EQ(occurrences(stubs, " " + parameter.name + ":"), 0u)
        << kStubsTemplate << " spells out " << parameter.name << " by hand";
  }
  const std::string written = param_lists::filled(stubs);
  EXPECT_EQ(occurrences(written, param_lists::kStubKeywordsMarker), 0u);
  // Every keyword at every marker, at the marker's indentation: 8 spaces in the method
  // (Segmenter.__init__), 4 in the functions.
  for (const std::string& keyword : param_lists::stubKeywordLines()) {
    EXPECT_EQ(occurrences(written, "\n        " + keyword + "\n"), 1u) << keyword;
    EXPECT_EQ(occurrences(written, "\n    " + keyword + "\n"), markers - 1) << keyword;
  }
}

// ---- the ROS node's dynamic_reconfigure list ----------------------------------------------

// The differences of the entries from the table and Params.
std::vector<std::string> entryProblems(const std::vector<ReconfigureEntry>& entries) {
  std::vector<std::string> problems;
  std::map<std::string, const ReconfigureEntry*> named;
  for (const ReconfigureEntry& entry : entries) {
    if (!named.emplace(entry.name, &entry).second) problems.push_back("twice: " + entry.name);
    if (entry.name != "measure_noise" && findParameter(entry.name) == nullptr) {
      problems.push_back(entry.name + " is neither in params_table.h nor measure_noise");
    }
  }
  const auto measure_noise = named.find("measure_noise");
  if (measure_noise == named.end() || measure_noise->second->type != "bool_t" ||
      (measure_noise->second->fallback != 0.0) != Params().estimatesNoise()) {
    problems.push_back(std::string("measure_noise must be a bool_t defaulting to ") +
                       (Params().estimatesNoise() ? "True" : "False"));
  }
  for (const Parameter& parameter : table()) {
    const auto found = named.find(parameter.name);
    if (found == named.end()) {
      problems.push_back("no entry for " + parameter.name);
      continue;
    }
    const ReconfigureEntry& entry = *found->second;
    const std::string type = parameter.integral ? "int_t" : "double_t";
    if (entry.type != type) problems.push_back(parameter.name + " is " + entry.type + ", the table's " + type);
    // dynamic_reconfigure has no "unset": 0 stands for a length or count the frame derives,
    // and the noise model's values count only with measure_noise false.
    const bool zero_is_unset = parameter.optional && parameter.kind != "Noise";
    if (entry.zero_is_unset != zero_is_unset) problems.push_back(parameter.name + " takes 0 otherwise");
    const double expected = parameter.fallback.value_or(0.0);
    if (!same(entry.fallback, expected)) {
      problems.push_back(parameter.name + " defaults to " + shown(entry.fallback) + ", Params to " +
                         (parameter.fallback ? shown(*parameter.fallback) : "unset (0 in the config)"));
    }
    if (!(entry.lowest <= entry.fallback && entry.fallback <= entry.highest)) {
      problems.push_back(parameter.name + "'s default is outside its range");
    }
    // Every value the range or the choices offer is one the library takes ...
    std::vector<double> offered = {entry.lowest, entry.highest};
    for (const param_lists::Choice& choice : entry.choices) offered.push_back(choice.value);
    for (const double value : offered) {
      if (zero_is_unset && value == 0.0) continue;
      const std::string problem = parameter.with(value).problem();
      if (!problem.empty()) {
        problems.push_back(parameter.name + " offers " + shown(value) + ", which Params refuses: " + problem);
      }
    }
    // ... and the choices, where there are, every value of the range the library takes.
    for (double value = std::ceil(entry.lowest); !entry.choices.empty() && value <= entry.highest; ++value) {
      const bool chosen = std::any_of(entry.choices.begin(), entry.choices.end(),
                                      [value](const param_lists::Choice& choice) { return choice.value == value; });
      if (parameter.with(value).problem().empty() && !chosen) {
        problems.push_back(parameter.name + ": the choices lack " + shown(value));
      }
    }
  }
  return problems;
}

TEST(ParamLists, TheRosEntriesOfferEveryParameterWithItsTypeDefaultAndAcceptedValues) {
  const std::vector<std::string> problems = entryProblems(param_lists::reconfigureEntries());
  EXPECT_TRUE(problems.empty()) << "the dynamic_reconfigure entries differ from src/params/params_table.h:"
                                << joined(problems);
}

TEST(ParamLists, AnEntryMissingMistypedOrOfferingWhatParamsRefusesIsFound) {
  const std::vector<ReconfigureEntry> entries = param_lists::reconfigureEntries();
  // Whether the check finds `problem` once `change` is made to the entry `name`.
  const auto finds = [&entries](const std::string& name, const auto& change, const std::string& problem) {
    std::vector<ReconfigureEntry> changed = entries;
    const auto entry =
        std::find_if(changed.begin(), changed.end(), [&name](const ReconfigureEntry& e) { return e.name == name; });
    if (entry == changed.end()) return ::testing::AssertionFailure() << "no entry " << name;
    change(*entry);
    const std::vector<std::string> problems = entryProblems(changed);
    if (mentions(problems, problem)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "changing " << name << ", no \"" << problem
                                         << "\" among:" << joined(problems);
  };
  EXPECT_TRUE(finds(
      "seed_size", [](ReconfigureEntry& e) { e.name = "seed_sizes"; }, "no entry for seed_size"));
  EXPECT_TRUE(finds(
      "seed_size", [](ReconfigureEntry& e) { e.name = "seed_sizes"; }, "seed_sizes is neither"));
  EXPECT_TRUE(finds(
      "min_inliers", [](ReconfigureEntry& e) { e.type = "double_t"; }, "min_inliers is double_t, the table's int_t"));
  EXPECT_TRUE(finds(
      "angular_threshold", [](ReconfigureEntry& e) { e.fallback = 0.2; },
      "angular_threshold defaults to 0.2, Params to 0.1"));
  EXPECT_TRUE(finds(
      "distance_threshold", [](ReconfigureEntry& e) { e.fallback = 0.01; },
      "distance_threshold defaults to 0.01, Params to unset (0 in the config)"));
  EXPECT_TRUE(finds(
      "angular_threshold", [](ReconfigureEntry& e) { e.highest = 1.6; },
      "angular_threshold offers 1.6, which Params refuses"));
  EXPECT_TRUE(finds(
      "subsampling", [](ReconfigureEntry& e) { e.choices.back().value = 6; },
      "subsampling offers 6, which Params refuses"));
  EXPECT_TRUE(finds(
      "subsampling", [](ReconfigureEntry& e) { e.choices.pop_back(); }, "the choices lack 8"));
  EXPECT_TRUE(finds(
      "measure_noise", [](ReconfigureEntry& e) { e.fallback = 0.0; },
      "measure_noise must be a bool_t defaulting to True"));
}

// The value after the description of a gen.add line: its default, min and max as written.
std::vector<double> writtenValues(const std::string& line) {
  std::string rest = line.substr(line.rfind('"') + 1);
  rest = rest.substr(0, rest.find(", edit_method"));
  std::vector<double> values;
  std::stringstream parts(rest);
  for (std::string part; std::getline(parts, part, ',');) {
    part = trimmed(part);
    if (part.empty() || part == ")") continue;
    if (part.back() == ')') part.pop_back();
    std::size_t used = 0;
    values.push_back(part == "True" ? 1.0 : part == "False" ? 0.0 : std::stod(part, &used));
    if (part != "True" && part != "False") {
      EXPECT_EQ(used, part.size()) << "not a number: " << part << " in " << line;
    }
  }
  return values;
}

TEST(ParamLists, TheRosConfigGetsTheEntriesAsWrittenAndHoldsOnlyTheStreamOptionsByHand) {
  const std::string cfg = readSource(kCfgTemplate);
  ASSERT_FALSE(cfg.empty()) << kCfgTemplate;
  EXPECT_EQ(occurrences(cfg, param_lists::kReconfigureEntriesMarker), 1u);
  // By hand: the stream's options alone (floodplane::conversion::SegmentationSettings).
  std::set<std::string> by_hand;
  for (const std::string& line : linesOf(cfg)) {
    if (line.rfind("gen.add(\"", 0) == 0) by_hand.insert(line.substr(9, line.find('"', 9) - 9));
  }
  EXPECT_EQ(by_hand, (std::set<std::string>{"head_start", "tracking"}));

  const std::string written = param_lists::filled(cfg);
  EXPECT_EQ(occurrences(written, param_lists::kReconfigureEntriesMarker), 0u);
  const std::vector<std::string> lines = linesOf(written);
  for (const ReconfigureEntry& entry : param_lists::reconfigureEntries()) {
    const std::string start = "gen.add(\"" + entry.name + "\", " + entry.type + ", 0, ";
    const auto line =
        std::find_if(lines.begin(), lines.end(), [&start](const std::string& l) { return l.rfind(start, 0) == 0; });
    ASSERT_NE(line, lines.end()) << "no line starts with " << start;
    // The numbers read back as the entry's (1/3 to the last bit).
    const std::vector<double> values = writtenValues(*line);
    const std::vector<double> expected = entry.type == "bool_t"
                                             ? std::vector<double>{entry.fallback}
                                             : std::vector<double>{entry.fallback, entry.lowest, entry.highest};
    EXPECT_EQ(values, expected) << *line;
    EXPECT_NE(line->find("\"" + entry.description + "\""), std::string::npos) << *line;
    EXPECT_EQ(line->find("edit_method") != std::string::npos, !entry.choices.empty()) << *line;
  }
  EXPECT_NE(written.find("gen.const(\"quarter\", int_t, 4, \"4 x 4 blocks first (the default)\")"), std::string::npos)
      << written;
}

TEST(ParamLists, ATemplateWithoutAMarkerOrWithAnUnknownOneIsRefused) {
  EXPECT_THROW(param_lists::filled("gen = ParameterGenerator()\n"), std::runtime_error);
  EXPECT_THROW(param_lists::filled("@PARAMETER_ENTRIES@\n  @PARAMETER_KEYWORD@\n"), std::runtime_error);
  // A marker's list takes its indentation; the rest stays as it is, the last line too.
  const std::string written = param_lists::filled("a\n  @PARAMETER_KEYWORDS@\nb");
  EXPECT_EQ(written.rfind("a\n  " + param_lists::stubKeywordLines().front() + "\n", 0), 0u) << written;
  EXPECT_EQ(written.substr(written.size() - 2), "\nb");
}

// ---- the nodelet's reading of the config ---------------------------------------------------

// settingsFromConfig's assignments to params.<field>, each with whether it is taken only
// with measure_noise false.
struct Assignment {
  std::string statement;
  bool noise_not_measured = false;
};

std::string identifierAt(const std::string& text, std::size_t at) {
  std::size_t end = at;
  while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) != 0 || text[end] == '_')) ++end;
  return text.substr(at, end - at);
}

std::vector<std::string> nodeletProblems(const std::string& text) {
  const std::size_t function = text.find("settingsFromConfig(");
  const std::size_t open = function == std::string::npos ? function : text.find('{', function);
  if (open == std::string::npos) return {"segmentation_nodelet.cpp has no settingsFromConfig"};
  std::map<std::string, std::vector<Assignment>> assignments;
  std::vector<std::string> headers;
  std::string current;
  for (std::size_t i = open + 1; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '{') {
      headers.push_back(trimmed(current));
      current.clear();
    } else if (c == '}') {
      if (headers.empty()) break;  // the function's end
      headers.pop_back();
      current.clear();
    } else if (c != ';') {
      current += c;
    } else {
      const std::size_t at = current.find("params.");
      const std::size_t equals = current.find('=', at);
      if (at != std::string::npos && equals != std::string::npos && current.compare(equals, 2, "==") != 0) {
        const bool not_measured = std::any_of(headers.begin(), headers.end(), [](const std::string& header) {
          return header.find("!config.measure_noise") != std::string::npos;
        });
        assignments[identifierAt(current, at + 7)].push_back({trimmed(current), not_measured});
      }
      current.clear();
    }
  }
  std::vector<std::string> problems;
  for (const auto& [field, found] : assignments) {
    if (findParameter(field) == nullptr) {
      problems.push_back("settingsFromConfig sets params." + field + ", which is not in params_table.h");
    }
  }
  for (const Parameter& parameter : table()) {
    const auto found = assignments.find(parameter.name);
    if (found == assignments.end()) {
      problems.push_back("settingsFromConfig does not set params." + parameter.name);
      continue;
    }
    for (const Assignment& assignment : found->second) {
      const std::string& statement = assignment.statement;
      for (std::size_t at = statement.find("config."); at != std::string::npos;
           at = statement.find("config.", at + 1)) {
        const std::string read = identifierAt(statement, at + 7);
        if (read != parameter.name) {
          problems.push_back("settingsFromConfig sets params." + parameter.name + " from config." + read);
        }
      }
      if (statement.find("config." + parameter.name) == std::string::npos) {
        problems.push_back("settingsFromConfig does not read config." + parameter.name);
      }
      if (parameter.kind == "Noise" && !assignment.noise_not_measured) {
        problems.push_back("settingsFromConfig sets params." + parameter.name + " whether or not measure_noise");
      } else if (parameter.optional && parameter.kind != "Noise" &&
                 statement.find("OrDerived(config." + parameter.name + ")") == std::string::npos &&
                 statement.find("config." + parameter.name + " > 0") == std::string::npos) {
        problems.push_back("settingsFromConfig takes config." + parameter.name +
                           " = 0 as a value, not as \"derived\" (lengthOrDerived, or a test for > 0)");
      }
    }
  }
  return problems;
}

TEST(ParamLists, TheRosNodeletReadsEveryParameterFromItsNamesake) {
  const std::string nodelet = readSource(kNodelet);
  ASSERT_FALSE(nodelet.empty()) << kNodelet;
  const std::vector<std::string> problems = nodeletProblems(nodelet);
  EXPECT_TRUE(problems.empty()) << kNodelet << " differs from src/params/params_table.h:" << joined(problems);
}

TEST(ParamLists, ANodeletThatReadsAParameterAmissIsFound) {
  const std::string nodelet = readSource(kNodelet);
  const auto finds = [&nodelet](const std::string& from, const std::string& to, const std::string& problem) {
    const std::vector<std::string> problems = nodeletProblems(doctored(nodelet, from, to));
    if (mentions(problems, problem)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "with '" << from << "' as '" << to << "', no \"" << problem
                                         << "\" among:" << joined(problems);
  };
  const std::string seed_size = "params.seed_size = conv::lengthOrDerived(config.seed_size);";
  EXPECT_TRUE(finds(seed_size, "", "does not set params.seed_size"));
  EXPECT_TRUE(finds(seed_size, "params.seed_size = conv::lengthOrDerived(config.merge_distance);",
                    "sets params.seed_size from config.merge_distance"));
  EXPECT_TRUE(finds(seed_size, "params.seed_size = config.seed_size;", "takes config.seed_size = 0 as a value"));
  EXPECT_TRUE(finds("if (config.min_inliers > 0) params.min_inliers", "params.min_inliers",
                    "takes config.min_inliers = 0 as a value"));
  EXPECT_TRUE(
      finds("if (!config.measure_noise) {", "{", "sets params.depth_noise_coefficient whether or not measure_noise"));
  EXPECT_TRUE(finds("params.subsampling = config.subsampling;",
                    "params.subsampling = config.subsampling;\n  params.seeds = 3;",
                    "sets params.seeds, which is not in params_table.h"));
}

}  // namespace
}  // namespace floodplane
