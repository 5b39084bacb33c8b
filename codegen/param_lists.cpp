// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "param_lists.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "floodplane/params.h"
#include "params/params_table.h"

namespace floodplane::param_lists {
namespace {

// How dynamic_reconfigure shows each kind of value: the range of its slider (every value in it
// one that Params::problem accepts, 0 standing for unset where the kind has one) and what the
// description adds to the flag's help. A new kind does not compile until it is given here.
struct Presentation {
  double lowest;
  double highest;
  const char* note;
};
Presentation presentationOf(params_table::Length) { return {0.0, 2.0, "; 0: the default"}; }
Presentation presentationOf(params_table::Angle) { return {0.001, 1.5, ""}; }
Presentation presentationOf(params_table::Count) { return {0.0, 10000000.0, "; 0: the default"}; }
// Curvature's largest value: 1/3.
Presentation presentationOf(params_table::Fraction) { return {0.0, 1.0 / 3.0, ""}; }
Presentation presentationOf(params_table::Subsampling) { return {1.0, 8.0, ""}; }
Presentation presentationOf(params_table::Noise) { return {0.0, 1.0, "; taken with measure_noise false"}; }

template <typename Kind>
constexpr bool kIsNoise = std::is_same_v<Kind, params_table::Noise>;

// The values a kind offers as named choices, none where a slider does.
template <typename Kind>
std::vector<Choice> choicesOf(int fallback) {
  std::vector<Choice> choices;
  if constexpr (std::is_same_v<Kind, params_table::Subsampling>) {
    for (int factor = 1; factor <= 8; ++factor) {
      if (!isValidSubsampling(factor)) continue;
      const std::string block = std::to_string(factor) + " x " + std::to_string(factor);
      const std::string name = factor == 1   ? "full"
                               : factor == 2 ? "half"
                               : factor == 4 ? "quarter"
                               : factor == 8 ? "eighth"
                                             : "by_" + std::to_string(factor);
      choices.push_back({name, factor,
                         (factor == 1 ? std::string("every pixel from the start") : block + " blocks first") +
                             (factor == fallback ? " (the default)" : "")});
    }
  }
  return choices;
}

template <typename Kind, typename Member>
ReconfigureEntry entryOf(const char* name, const char* help, const Member& fallback) {
  using Value = typename Unwrapped<Member>::type;
  const Presentation presentation = presentationOf(Kind{});
  ReconfigureEntry entry;
  entry.name = name;
  entry.type = std::is_integral_v<Value> ? "int_t" : "double_t";
  entry.description = std::string(help) + presentation.note;
  entry.lowest = presentation.lowest;
  entry.highest = presentation.highest;
  if constexpr (IsOptional<Member>::value) {
    entry.fallback = fallback ? static_cast<double>(*fallback) : 0.0;
    entry.zero_is_unset = !kIsNoise<Kind>;
  } else {
    entry.fallback = static_cast<double>(fallback);
  }
  if constexpr (std::is_integral_v<Value>) entry.choices = choicesOf<Kind>(static_cast<int>(entry.fallback));
  return entry;
}

template <typename Member>
std::string stubKeyword(const char* name) {
  const std::string type = std::is_integral_v<typename Unwrapped<Member>::type> ? "int" : "float";
  return std::string(name) + ": " + (IsOptional<Member>::value ? "Optional[" + type + "]" : type) + " = ...,";
}

// A Python string literal.
std::string quoted(const std::string& text) {
  std::string literal = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') literal += '\\';
    literal += c;
  }
  return literal + "\"";
}

// A Python number that reads back as `value`: an int for int_t, the shortest float otherwise.
std::string number(double value, bool integral) {
  if (integral) return std::to_string(static_cast<long long>(std::llround(value)));
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof(text), value);
  if (error != std::errc()) throw std::runtime_error("param_lists: cannot write a number");
  std::string written(text, end);
  if (written.find_first_of(".en") == std::string::npos) written += ".0";
  return written;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

std::vector<std::string> stubKeywordLines() {
  std::vector<std::string> lines;
#define FLOODPLANE_STUB_KEYWORD(field, kind, flag, setter, help) \
  lines.push_back(stubKeyword<decltype(Params::field)>(#field));
  FLOODPLANE_PARAMETERS(FLOODPLANE_STUB_KEYWORD)
#undef FLOODPLANE_STUB_KEYWORD
  return lines;
}

std::vector<ReconfigureEntry> reconfigureEntries() {
  std::vector<ReconfigureEntry> entries;
  bool noise_switch = false;
  const Params defaults;
  // The noise model's values count only when it is not measured: a switch before the first.
  const auto addNoiseSwitch = [&](bool noise) {
    if (!noise || noise_switch) return;
    noise_switch = true;
    ReconfigureEntry entry;
    entry.name = "measure_noise";
    entry.type = "bool_t";
    entry.description = "measure the depth noise on each frame (false: take the noise model's values below)";
    entry.fallback = defaults.estimatesNoise() ? 1.0 : 0.0;
    entry.highest = 1.0;
    entries.push_back(entry);
  };
#define FLOODPLANE_RECONFIGURE_ENTRY(field, kind, flag, setter, help) \
  addNoiseSwitch(kIsNoise<params_table::kind>);                       \
  entries.push_back(entryOf<params_table::kind>(#field, help, defaults.field));
  FLOODPLANE_PARAMETERS(FLOODPLANE_RECONFIGURE_ENTRY)
#undef FLOODPLANE_RECONFIGURE_ENTRY
  return entries;
}

std::vector<std::string> reconfigureLines() {
  std::vector<std::string> lines;
  for (const ReconfigureEntry& entry : reconfigureEntries()) {
    const std::string add = "gen.add(" + quoted(entry.name) + ", " + entry.type + ", 0, " + quoted(entry.description);
    if (entry.type == "bool_t") {
      lines.push_back(add + ", " + (entry.fallback != 0.0 ? "True" : "False") + ")");
      continue;
    }
    const bool integral = entry.type == "int_t";
    std::string values = ", " + number(entry.fallback, integral) + ", " + number(entry.lowest, integral) + ", " +
                         number(entry.highest, integral);
    if (!entry.choices.empty()) {
      std::string constants;
      for (const Choice& choice : entry.choices) {
        constants += std::string(constants.empty() ? "" : ", ") + "gen.const(" + quoted(choice.name) + ", " +
                     entry.type + ", " + std::to_string(choice.value) + ", " + quoted(choice.description) + ")";
      }
      lines.push_back(entry.name + "_choices = gen.enum([" + constants + "], " + quoted(entry.description) + ")");
      values += ", edit_method=" + entry.name + "_choices";
    }
    lines.push_back(add + values + ")");
  }
  return lines;
}

std::string filled(const std::string& text) {
  std::string result;
  int markers = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    const std::string content = trimmed(line);
    const std::string indentation = line.substr(0, line.find_first_not_of(" \t"));
    const bool newline = end != std::string::npos;
    std::vector<std::string> list;
    if (content == kStubKeywordsMarker) {
      list = stubKeywordLines();
    } else if (content == kReconfigureEntriesMarker) {
      list = reconfigureLines();
    } else if (content.size() > 2 && content.front() == '@' && content.back() == '@' &&
               content.find(' ') == std::string::npos) {
      throw std::runtime_error("unknown marker " + content + " (known: " + kStubKeywordsMarker + ", " +
                               kReconfigureEntriesMarker + ")");
    } else {
      result += line + (newline ? "\n" : "");
      start = newline ? end + 1 : text.size();
      continue;
    }
    ++markers;
    for (const std::string& listed : list) result += indentation + listed + "\n";
    start = newline ? end + 1 : text.size();
  }
  if (markers == 0) {
    throw std::runtime_error(std::string("no marker (") + kStubKeywordsMarker + " or " + kReconfigureEntriesMarker +
                             " on a line of its own)");
  }
  return result;
}

}  // namespace floodplane::param_lists
