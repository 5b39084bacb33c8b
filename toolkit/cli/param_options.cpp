// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cli/param_options.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <optional>

#include "params/params_table.h"

namespace floodplane::cli {
namespace {

// Every parameter: its Params field, its flag and its FloodFillPlaneSegmentation setter.
struct ParameterName {
  const char* field;
  const char* flag;
  const char* setter;
};

#define FLOODPLANE_NAMES(field, kind, flag, setter, help) {#field, flag, #setter},
constexpr ParameterName kParameterNames[] = {FLOODPLANE_PARAMETERS(FLOODPLANE_NAMES)};
#undef FLOODPLANE_NAMES

// An option writing into `member`; a field with a default shows it in --help, one the library
// derives from the frame stays unset unless given.
template <typename T>
void addOption(CLI::App& app, const char* flag, std::optional<T>& member, const char* help) {
  app.add_option(flag, member, help);
}
template <typename T>
void addOption(CLI::App& app, const char* flag, T& member, const char* help) {
  app.add_option(flag, member, help)->capture_default_str();
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
#define FLOODPLANE_OPTION(field, kind, flag, setter, help) addOption(app, flag, params.field, help);
  FLOODPLANE_PARAMETERS(FLOODPLANE_OPTION)
#undef FLOODPLANE_OPTION
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

}  // namespace floodplane::cli
