// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The segmentation parameters (floodplane::Params) as command-line options, and the one
// mapping from the library's names for them (Params fields, FloodFillPlaneSegmentation
// setters) to the flags: the library's messages name its own fields and setters, a user of the
// apps knows the flags.

#include <string>

#include "floodplane/params.h"

namespace CLI {
class App;
}

namespace floodplane::cli {

/// Adds an option per field of `params` (--distance-threshold, --seed-size, ...), each writing
/// into it; the fields the library derives from each frame stay unset unless given.
void addParameterOptions(CLI::App& app, Params& params);

/// `message` from the library (Params::problem(), or the std::invalid_argument of a
/// FloodFillPlaneSegmentation setter) in the apps' terms: the "floodplane::...: " prefix
/// dropped and every Params field or setter name replaced by its flag, as in
/// "--subsample must be 1, 2, 4 or 8, got 3".
std::string inFlagTerms(const std::string& message);

}  // namespace floodplane::cli
