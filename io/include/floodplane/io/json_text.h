// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// JSON files as the apps write them, file names in them that are not UTF-8 included.

#include <string>

namespace floodplane::io {

/// `json` (an nlohmann::json or ordered_json) as the text of a JSON file: indented by 2 and
/// ending in a newline. A string that is not UTF-8 (a file name is any bytes but / and NUL)
/// has each ill-formed sequence, the longest start of a character that does not go on,
/// replaced with U+FFFD: the rule of Python's bytes.decode("utf-8", "replace"), which a
/// Python script applies to a name (os.fsencode) to find it in the file. Without it the
/// writer would fail with the JSON library's message instead of writing the file.
template <typename Json>
std::string jsonText(const Json& json) {
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace floodplane::io
