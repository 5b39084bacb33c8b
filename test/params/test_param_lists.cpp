// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The parameters are one list, src/params/params_table.h; validation, JSON, the command line and
// Python's keywords follow from it, but three lists beside it are written by hand. Each must
// agree with the table, read here through the table itself (names, the member's type, Params'
// defaults, Params::problem for the values a range offers):
// - python/floodplane/__init__.pyi: every signature that spells out the keywords has them all,
//   with the member's type (Optional[...] where unset means "derived") and, where it states a
//   default, Params' default;
// - ros/floodplane_ros/cfg/Segmentation.cfg: every parameter, with its type, its default (0 for
//   a length or count the frame derives, measure_noise for the noise model), and a range and
//   choices the library accepts; besides, only the node's stream options;
// - ros/floodplane_ros/src/segmentation_nodelet.cpp, settingsFromConfig: every parameter read
//   from its namesake, 0 taken as "derived" where the config says so.
// The checks are also run on doctored copies, to show that each difference is found.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "floodplane/params.h"
#include "params/params_table.h"

namespace floodplane {
namespace {

// ---- the table ----------------------------------------------------------------------------

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <typename T>
struct Unwrapped {
  using type = T;
};
template <typename T>
struct Unwrapped<std::optional<T>> {
  using type = T;
};

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

// ---- reading the hand-written lists -------------------------------------------------------

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

std::size_t lineOf(const std::string& text, std::size_t at) {
  return static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
}

// Walks Python or C++ text a character at a time, knowing whether it is inside a quoted
// literal and how deep inside brackets.
struct TextWalk {
  int depth = 0;
  char quote = 0;

  // Steps over text[i] (a backslash in a literal takes the next character along, moving i);
  // whether text[i] is outside any literal (a literal's quote marks are inside it).
  bool outside(const std::string& text, std::size_t& i) {
    const char c = text[i];
    if (quote != 0) {
      if (c == '\\' && i + 1 < text.size()) {
        ++i;
      } else if (c == quote) {
        quote = 0;
      }
      return false;
    }
    if (c == '"' || c == '\'') {
      quote = c;
      return false;
    }
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    return true;
  }
};

// The text between the bracket at `open` and its match (quotes and nesting respected), and the
// index after the match; npos when it has none.
std::pair<std::string, std::size_t> bracketed(const std::string& text, std::size_t open) {
  TextWalk walk;
  for (std::size_t i = open; i < text.size(); ++i) {
    if (walk.outside(text, i) && walk.depth == 0) return {text.substr(open + 1, i - open - 1), i + 1};
  }
  return {{}, std::string::npos};
}

// `text` split at the separators outside brackets and quotes, each part trimmed.
std::vector<std::string> topLevelParts(const std::string& text, char separator = ',') {
  std::vector<std::string> parts;
  TextWalk walk;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (walk.outside(text, i) && walk.depth == 0 && text[i] == separator) {
      parts.push_back(trimmed(text.substr(start, i - start)));
      start = i + 1;
    }
  }
  if (!trimmed(text.substr(std::min(start, text.size()))).empty()) parts.push_back(trimmed(text.substr(start)));
  return parts;
}

// A number as Python writes a constant: 0.1, 10000000, 1.0 / 3.0.
std::optional<double> pythonNumber(const std::string& text) {
  const std::vector<std::string> quotient = topLevelParts(text, '/');
  if (quotient.empty() || quotient.size() > 2) return std::nullopt;
  double value = 0.0;
  for (std::size_t k = 0; k < quotient.size(); ++k) {
    std::size_t used = 0;
    double number = 0.0;
    try {
      number = std::stod(quotient[k], &used);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != quotient[k].size()) return std::nullopt;
    value = k == 0 ? number : value / number;
  }
  return value;
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }

std::string shown(const std::optional<double>& value) {
  if (!value) return "unset";
  std::ostringstream text;
  text << *value;
  return text.str();
}

const Parameter* findParameter(const std::string& name) {
  for (const Parameter& parameter : table())
    if (parameter.name == name) return &parameter;
  return nullptr;
}

// ---- the Python stubs ---------------------------------------------------------------------

std::string pythonType(const Parameter& parameter) {
  const std::string type = parameter.integral ? "int" : "float";
  return parameter.optional ? "Optional[" + type + "]" : type;
}

// The differences of each stub signature that spells out any parameter from the table.
// `signatures` counts those signatures.
std::vector<std::string> stubProblems(const std::string& text, std::size_t& signatures) {
  std::vector<std::string> problems;
  signatures = 0;
  static const std::regex definition(R"((^|\n)[ \t]*def[ \t]+(\w+)[ \t]*\()");
  for (auto match = std::sregex_iterator(text.begin(), text.end(), definition); match != std::sregex_iterator();
       ++match) {
    const std::size_t open = static_cast<std::size_t>(match->position(0) + match->length(0)) - 1;
    const std::string where = (*match)[2].str() + " (__init__.pyi line " +
                              std::to_string(lineOf(text, static_cast<std::size_t>(match->position(2)))) + ")";
    std::map<std::string, std::pair<std::string, std::string>> keywords;  // name: type, default
    for (const std::string& argument : topLevelParts(bracketed(text, open).first)) {
      const std::vector<std::string> assigned = topLevelParts(argument, '=');
      const std::vector<std::string> annotated = topLevelParts(assigned.empty() ? "" : assigned[0], ':');
      if (annotated.empty()) continue;
      keywords[annotated[0]] = {annotated.size() > 1 ? annotated[1] : "", assigned.size() > 1 ? assigned[1] : ""};
    }
    const bool spells_them_out =
        std::any_of(table().begin(), table().end(), [&](const Parameter& p) { return keywords.count(p.name) != 0; });
    if (!spells_them_out) continue;
    ++signatures;
    for (const Parameter& parameter : table()) {
      const auto keyword = keywords.find(parameter.name);
      if (keyword == keywords.end()) {
        problems.push_back(where + " lacks " + parameter.name);
        continue;
      }
      const auto& [type, fallback] = keyword->second;
      if (type != pythonType(parameter)) {
        problems.push_back(where + ": " + parameter.name + " is " + (type.empty() ? "unannotated" : type) +
                           ", the table's " + pythonType(parameter));
      }
      if (fallback.empty() || fallback == "...") continue;
      const std::optional<double> stated = fallback == "None" ? std::nullopt : pythonNumber(fallback);
      const bool agrees =
          stated ? parameter.fallback && same(*stated, *parameter.fallback) : fallback == "None" && !parameter.fallback;
      if (!agrees) {
        problems.push_back(where + ": " + parameter.name + " defaults to " + fallback + ", Params to " +
                           shown(parameter.fallback));
      }
    }
  }
  return problems;
}

// ---- the ROS node's dynamic_reconfigure list ----------------------------------------------

// The node's options that are not Params fields: whether the noise model is measured (the
// parameters of kind Noise are taken only when it is not), and the stream's options
// (floodplane::conversion::SegmentationSettings).
const std::set<std::string> kStreamOptions = {"measure_noise", "head_start", "tracking"};

struct CfgEntry {
  std::size_t line = 0;
  std::vector<std::string> arguments;  // name, type, level, description, default, min, max, ...
  std::string edit_method;
};

// The calls `<call>(...)` of `text`, each as its arguments, by where they start.
std::map<std::size_t, std::vector<std::string>> calls(const std::string& text, const std::string& call) {
  std::map<std::size_t, std::vector<std::string>> found;
  for (std::size_t at = text.find(call + "("); at != std::string::npos; at = text.find(call + "(", at + 1)) {
    found[at] = topLevelParts(bracketed(text, at + call.size()).first);
  }
  return found;
}

std::string unquoted(const std::string& text) {
  return text.size() >= 2 && (text.front() == '"' || text.front() == '\'') ? text.substr(1, text.size() - 2) : text;
}

std::vector<std::string> cfgProblems(const std::string& text) {
  std::vector<std::string> problems;
  std::map<std::string, CfgEntry> entries;
  for (const auto& [at, arguments] : calls(text, "gen.add")) {
    CfgEntry entry{lineOf(text, at), {}, {}};
    for (const std::string& argument : arguments) {
      if (argument.rfind("edit_method", 0) == 0) {
        entry.edit_method = trimmed(argument.substr(argument.find('=') + 1));
      } else {
        entry.arguments.push_back(argument);
      }
    }
    if (entry.arguments.empty()) continue;
    entries[unquoted(entry.arguments[0])] = entry;
  }
  // The choices of each enum: its variable's name, then the values of its constants.
  std::map<std::string, std::vector<double>> choices;
  static const std::regex enumeration(R"((\w+)[ \t]*=[ \t]*gen\.enum\()");
  for (auto match = std::sregex_iterator(text.begin(), text.end(), enumeration); match != std::sregex_iterator();
       ++match) {
    const std::string body = bracketed(text, static_cast<std::size_t>(match->position(0) + match->length(0)) - 1).first;
    for (const auto& [at, constant] : calls(body, "gen.const")) {
      if (constant.size() >= 3) choices[(*match)[1].str()].push_back(pythonNumber(constant[2]).value_or(NAN));
    }
  }
  for (const auto& [name, entry] : entries) {
    if (findParameter(name) == nullptr && kStreamOptions.count(name) == 0) {
      problems.push_back("Segmentation.cfg line " + std::to_string(entry.line) + " offers " + name +
                         ", which is neither in params_table.h nor a stream option of the node");
    }
  }
  const auto measure_noise = entries.find("measure_noise");
  const bool measures_noise_by_default = measure_noise != entries.end() && measure_noise->second.arguments.size() > 4 &&
                                         measure_noise->second.arguments[4] == "True";
  if (measures_noise_by_default != Params().estimatesNoise()) {
    problems.push_back(std::string("Segmentation.cfg: measure_noise must default to ") +
                       (Params().estimatesNoise() ? "True" : "False") + ", as Params measures the noise " +
                       (Params().estimatesNoise() ? "unless told" : "only when told"));
  }
  for (const Parameter& parameter : table()) {
    const auto entry = entries.find(parameter.name);
    if (entry == entries.end()) {
      problems.push_back("Segmentation.cfg lacks " + parameter.name);
      continue;
    }
    const std::vector<std::string>& arguments = entry->second.arguments;
    const std::string where = "Segmentation.cfg line " + std::to_string(entry->second.line) + ": " + parameter.name;
    const std::string type = parameter.integral ? "int_t" : "double_t";
    if (arguments.size() < 7) {
      problems.push_back(where + " has no default, min and max");
      continue;
    }
    if (arguments[1] != type) problems.push_back(where + " is " + arguments[1] + ", the table's " + type);
    const std::optional<double> fallback = pythonNumber(arguments[4]);
    const std::optional<double> lowest = pythonNumber(arguments[5]);
    const std::optional<double> highest = pythonNumber(arguments[6]);
    if (!fallback || !lowest || !highest) {
      problems.push_back(where + ": default, min or max is not a number");
      continue;
    }
    // The config has no "unset": 0 stands for a length or count the frame derives, and the
    // noise model's values count only with measure_noise false (checked above).
    const bool zero_is_unset = parameter.optional && parameter.kind != "Noise";
    if (zero_is_unset ? *fallback != 0.0 || parameter.fallback
                      : parameter.kind != "Noise" && (!parameter.fallback || !same(*fallback, *parameter.fallback))) {
      problems.push_back(where + " defaults to " + arguments[4] + ", Params to " + shown(parameter.fallback) +
                         (zero_is_unset ? " (0 in the config)" : ""));
    }
    // Every value the range or the choices offer is one the library takes.
    std::vector<double> offered = {*lowest, *highest};
    const auto listed = choices.find(entry->second.edit_method);
    if (listed != choices.end()) {
      offered.insert(offered.end(), listed->second.begin(), listed->second.end());
      // ... and the choices offer every value of the range the library takes.
      for (double value = std::ceil(*lowest); parameter.integral && value <= *highest; ++value) {
        const bool taken = parameter.with(value).problem().empty();
        const bool chosen = std::find(listed->second.begin(), listed->second.end(), value) != listed->second.end();
        if (taken && !chosen) problems.push_back(where + ": the choices lack " + shown(value));
      }
    }
    for (const double value : offered) {
      if (zero_is_unset && value == 0.0) continue;
      const std::string problem = parameter.with(value).problem();
      if (!problem.empty())
        problems.push_back(where + " offers " + shown(value) + ", which Params refuses: " + problem);
    }
  }
  return problems;
}

// ---- the nodelet's reading of the config ---------------------------------------------------

struct Assignment {
  std::string statement;  // with an `if (...)` in front of it, when it has one
  std::string context;    // the headers of the blocks around it
};

std::vector<std::string> nodeletProblems(const std::string& text) {
  const std::size_t function = text.find("settingsFromConfig(");
  if (function == std::string::npos) return {"segmentation_nodelet.cpp has no settingsFromConfig"};
  const std::string body = bracketed(text, text.find('{', function)).first;
  // Statements and the headers of the blocks they are in.
  std::map<std::string, std::vector<Assignment>> assignments;  // by params field
  std::vector<std::string> headers;
  std::string current;
  static const std::regex assigned(R"(\bparams\.(\w+)\s*=[^=])");
  for (const char c : body) {
    if (c == '{') {
      headers.push_back(trimmed(current));
      current.clear();
    } else if (c == '}') {
      if (!headers.empty()) headers.pop_back();
      current.clear();
    } else if (c == ';') {
      std::smatch match;
      if (std::regex_search(current, match, assigned)) {
        std::string context;
        for (const std::string& header : headers) context += header + " ";
        assignments[match[1].str()].push_back({trimmed(current), context});
      }
      current.clear();
    } else {
      current += c;
    }
  }
  std::vector<std::string> problems;
  for (const auto& [field, found] : assignments) {
    if (findParameter(field) == nullptr) {
      problems.push_back("settingsFromConfig sets params." + field + ", which is not in params_table.h");
    }
  }
  static const std::regex read(R"(\bconfig\.(\w+))");
  for (const Parameter& parameter : table()) {
    const auto found = assignments.find(parameter.name);
    if (found == assignments.end()) {
      problems.push_back("settingsFromConfig does not set params." + parameter.name + " from config." + parameter.name);
      continue;
    }
    for (const Assignment& assignment : found->second) {
      const std::string value = assignment.statement.substr(assignment.statement.find("params." + parameter.name));
      bool namesake = false;
      for (auto name = std::sregex_iterator(value.begin(), value.end(), read); name != std::sregex_iterator(); ++name) {
        if ((*name)[1].str() == parameter.name) {
          namesake = true;
        } else {
          problems.push_back("settingsFromConfig sets params." + parameter.name + " from config." + (*name)[1].str());
        }
      }
      if (!namesake) {
        problems.push_back("settingsFromConfig sets params." + parameter.name + " from something else than config." +
                           parameter.name);
      }
      // The config's 0 is "derived" for the lengths and counts the frame derives; the noise
      // model's values count only when it is not measured.
      const std::string around = assignment.context + assignment.statement;
      if (parameter.kind == "Noise" && around.find("measure_noise") == std::string::npos) {
        problems.push_back("settingsFromConfig sets params." + parameter.name + " whether or not measure_noise");
      } else if (parameter.optional && parameter.kind != "Noise" &&
                 around.find("OrDerived(config." + parameter.name + ")") == std::string::npos &&
                 !std::regex_search(around, std::regex("config\\." + parameter.name + "\\s*>\\s*0\\b"))) {
        problems.push_back("settingsFromConfig takes config." + parameter.name +
                           " = 0 as a value, not as \"derived\" (lengthOrDerived, or a test for > 0)");
      }
    }
  }
  return problems;
}

std::string joined(const std::vector<std::string>& problems) {
  std::string text;
  for (const std::string& problem : problems) text += "\n  " + problem;
  return text;
}

// Replaces the first `from` in `text` by `to`; the test fails if there is none.
std::string doctored(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "not found: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

bool mentions(const std::vector<std::string>& problems, const std::string& part) {
  return std::any_of(problems.begin(), problems.end(),
                     [&part](const std::string& problem) { return problem.find(part) != std::string::npos; });
}

const char* const kStubs = "python/floodplane/__init__.pyi";
const char* const kCfg = "ros/floodplane_ros/cfg/Segmentation.cfg";
const char* const kNodelet = "ros/floodplane_ros/src/segmentation_nodelet.cpp";

// ---- the lists as they are ----------------------------------------------------------------

TEST(ParamLists, TheTableHasEveryParameterOnce) {
  ASSERT_EQ(table().size(), static_cast<std::size_t>(params_table::kCount));
  std::set<std::string> names;
  for (const Parameter& parameter : table()) EXPECT_TRUE(names.insert(parameter.name).second) << parameter.name;
}

TEST(ParamLists, EveryPythonStubThatSpellsOutTheKeywordsHasThemAllWithTheirTypes) {
  const std::string stubs = readSource(kStubs);
  ASSERT_FALSE(stubs.empty()) << kStubs;
  std::size_t signatures = 0;
  const std::vector<std::string> problems = stubProblems(stubs, signatures);
  EXPECT_TRUE(problems.empty()) << kStubs << " differs from src/params/params_table.h:" << joined(problems);
  // Segmenter(), segment(), segment_depth() twice, segment_file(): the reader found them.
  EXPECT_GE(signatures, 5u);
}

TEST(ParamLists, TheRosConfigOffersEveryParameterWithItsTypeDefaultAndAcceptedValues) {
  const std::string cfg = readSource(kCfg);
  ASSERT_FALSE(cfg.empty()) << kCfg;
  const std::vector<std::string> problems = cfgProblems(cfg);
  EXPECT_TRUE(problems.empty()) << kCfg << " differs from src/params/params_table.h:" << joined(problems);
}

TEST(ParamLists, TheRosNodeletReadsEveryParameterFromItsNamesake) {
  const std::string nodelet = readSource(kNodelet);
  ASSERT_FALSE(nodelet.empty()) << kNodelet;
  const std::vector<std::string> problems = nodeletProblems(nodelet);
  EXPECT_TRUE(problems.empty()) << kNodelet << " differs from src/params/params_table.h:" << joined(problems);
}

// ---- the checks find each kind of difference ----------------------------------------------

// Whether `check` finds `problem` in `text` once `from` is replaced by `to`.
template <typename Check>
::testing::AssertionResult finds(const Check& check, const std::string& text, const std::string& from,
                                 const std::string& to, const std::string& problem) {
  const std::vector<std::string> problems = check(doctored(text, from, to));
  if (mentions(problems, problem)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "with '" << from << "' as '" << to << "', no \"" << problem
                                       << "\" among:" << joined(problems);
}

std::vector<std::string> stubProblemsOf(const std::string& text) {
  std::size_t signatures = 0;
  return stubProblems(text, signatures);
}

TEST(ParamLists, AStubThatLacksAKeywordOrMistypesOneIsFound) {
  const std::string stubs = readSource(kStubs);
  const std::vector<std::string> lacking =
      stubProblemsOf(doctored(stubs, "        seed_size: Optional[float] = ...,\n", ""));
  ASSERT_EQ(lacking.size(), 1u) << joined(lacking);
  EXPECT_EQ(lacking[0].rfind("__init__ (__init__.pyi line ", 0), 0u) << lacking[0];
  EXPECT_TRUE(mentions(lacking, ") lacks seed_size")) << lacking[0];
  const auto stubFinds = [&stubs](const std::string& from, const std::string& to, const std::string& problem) {
    return finds(stubProblemsOf, stubs, from, to, problem);
  };
  EXPECT_TRUE(stubFinds("subsampling: int = ...", "subsampling: float = ...", "subsampling is float, the table's int"));
  EXPECT_TRUE(stubFinds("min_inliers: Optional[int] = ...", "min_inliers: int = ...",
                        "min_inliers is int, the table's Optional[int]"));
  EXPECT_TRUE(stubFinds("angular_threshold: float = ...", "angular_threshold: float = 0.2",
                        "angular_threshold defaults to 0.2, Params to 0.1"));
  // A default stated as Params has it is no difference.
  EXPECT_TRUE(
      stubProblemsOf(doctored(stubs, "angular_threshold: float = ...", "angular_threshold: float = 0.1")).empty());
}

TEST(ParamLists, AConfigEntryMissingMistypedOrDefaultingOtherwiseIsFound) {
  const std::string cfg = readSource(kCfg);
  const auto cfgFinds = [&cfg](const std::string& from, const std::string& to, const std::string& problem) {
    return finds(cfgProblems, cfg, from, to, problem);
  };
  EXPECT_TRUE(cfgFinds("gen.add(\"seed_size\"", "gen.add(\"seed_sizes\"", "Segmentation.cfg lacks seed_size"));
  EXPECT_TRUE(cfgFinds("gen.add(\"seed_size\"", "gen.add(\"seed_sizes\"", "offers seed_sizes, which is neither"));
  EXPECT_TRUE(
      cfgFinds("\"min_inliers\", int_t", "\"min_inliers\", double_t", "min_inliers is double_t, the table's int_t"));
  EXPECT_TRUE(cfgFinds("in merging\", 0.1,", "in merging\", 0.2,", "angular_threshold defaults to 0.2, Params to 0.1"));
  EXPECT_TRUE(cfgFinds("3 noise deviations\", 0.0,", "3 noise deviations\", 0.01,",
                       "distance_threshold defaults to 0.01, Params to unset (0 in the config)"));
  EXPECT_TRUE(cfgFinds("0.1, 0.001, 1.5)", "0.1, 0.001, 1.6)", "angular_threshold offers 1.6, which Params refuses"));
  EXPECT_TRUE(cfgFinds("gen.const(\"eighth\", int_t, 8,", "gen.const(\"eighth\", int_t, 6,",
                       "subsampling offers 6, which Params refuses"));
  EXPECT_TRUE(cfgFinds("gen.const(\"eighth\", int_t, 8,", "gen.const(\"eighth\", int_t, 4,", "the choices lack 8"));
  EXPECT_TRUE(cfgFinds("(false: use the two values below)\", True)", "(false: use the two values below)\", False)",
                       "measure_noise must default to True"));
}

TEST(ParamLists, ANodeletThatReadsAParameterAmissIsFound) {
  const std::string nodelet = readSource(kNodelet);
  const auto nodeletFinds = [&nodelet](const std::string& from, const std::string& to, const std::string& problem) {
    return finds(nodeletProblems, nodelet, from, to, problem);
  };
  const std::string seed_size = "params.seed_size = conv::lengthOrDerived(config.seed_size);";
  EXPECT_TRUE(nodeletFinds(seed_size, "", "does not set params.seed_size"));
  EXPECT_TRUE(nodeletFinds(seed_size, "params.seed_size = conv::lengthOrDerived(config.merge_distance);",
                           "sets params.seed_size from config.merge_distance"));
  EXPECT_TRUE(nodeletFinds(seed_size, "params.seed_size = config.seed_size;", "takes config.seed_size = 0 as a value"));
  EXPECT_TRUE(nodeletFinds("if (config.min_inliers > 0) params.min_inliers", "params.min_inliers",
                           "takes config.min_inliers = 0 as a value"));
  EXPECT_TRUE(nodeletFinds("if (!config.measure_noise) {", "{",
                           "sets params.depth_noise_coefficient whether or not measure_noise"));
  EXPECT_TRUE(nodeletFinds("params.subsampling = config.subsampling;",
                           "params.subsampling = config.subsampling;\n  params.seeds = 3;",
                           "sets params.seeds, which is not in params_table.h"));
}

}  // namespace
}  // namespace floodplane
