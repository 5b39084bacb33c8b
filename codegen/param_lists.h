// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The lists of parameters that other languages need, written from src/params/params_table.h
// and Params' defaults: the keywords of the Python stubs (python/floodplane/__init__.pyi.in) and
// the ROS node's dynamic_reconfigure entries (ros/floodplane_ros/cfg/Segmentation.cfg.in). A
// template names where a list goes by a line holding its marker alone; floodplane_param_lists
// fills the templates at build time.

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace floodplane::param_lists {

/// The marker of the stubs' keyword lines; the lines take its indentation.
inline constexpr const char* kStubKeywordsMarker = "@PARAMETER_KEYWORDS@";
/// The marker of the dynamic_reconfigure entries.
inline constexpr const char* kReconfigureEntriesMarker = "@PARAMETER_ENTRIES@";

/// Whether a field of Params is optional (unset is a value of its own), and its value type.
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

/// One choice of a parameter that takes a few values (an enum in dynamic_reconfigure).
struct Choice {
  std::string name;
  int value = 0;
  std::string description;
};

/// One entry of the ROS node's dynamic_reconfigure list. dynamic_reconfigure has no "unset": a
/// length or count the frame derives is 0, and the noise model's values count only with
/// measure_noise false (itself an entry, true where Params measures the noise).
struct ReconfigureEntry {
  std::string name;
  std::string type;  // int_t, double_t or bool_t
  std::string description;
  double fallback = 0.0;  // the default; for bool_t 1 (True) or 0
  double lowest = 0.0;
  double highest = 0.0;
  bool zero_is_unset = false;  // 0 stands for Params' unset (derived from the frame)
  std::vector<Choice> choices;
};

/// Every parameter of the table, in its order, as a keyword of the Python stubs:
/// "name: type = ...," (Optional[...] where None unsets it).
std::vector<std::string> stubKeywordLines();

/// Every parameter of the table as dynamic_reconfigure offers it, in the table's order, with
/// measure_noise before the first parameter of the noise model.
std::vector<ReconfigureEntry> reconfigureEntries();

/// The entries as Python statements of a cfg script (gen.add, gen.enum for the choices).
std::vector<std::string> reconfigureLines();

/// `text` with every line that holds a marker alone replaced by its list, each line at the
/// marker's indentation. Throws std::runtime_error when there is no marker, or a line holds
/// another @NAME@ alone.
std::string filled(const std::string& text);

}  // namespace floodplane::param_lists
