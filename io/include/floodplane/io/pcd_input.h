// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading any organized PCD file with x y z fields, with the checks that keep PCL's reader
// from crashing or exhausting memory on a truncated or corrupt file.

#include <string>

#include "floodplane/io/input_frame.h"

namespace floodplane::io {

/// Reads `path`: x y z as float or double, the colour of an rgb or rgba field, the `label`
/// field when it is a 32-bit unsigned integer. Throws std::runtime_error with a one-line
/// reason (without the path) when the file is empty, not a PCD file, truncated or corrupt,
/// has no points, has no x y z fields, or is not organized. A cloud whose points are all NaN
/// loads normally. PCL's own log lines are silenced while it reads: the exception says it.
InputFrame readPcdFrame(const std::string& path);

}  // namespace floodplane::io
