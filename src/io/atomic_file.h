// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing files so that a reader sees either the previous file or the complete new one.

#include <functional>
#include <string>
#include <string_view>

namespace floodplane::io {

/// Writes `path` atomically: `write` fills a temporary file in the same directory (it is
/// handed the temporary's path, so writers that insist on opening a path themselves, such as
/// PCL's and libpng's, can be used), and the temporary is then renamed over `path`.
/// If `write` throws or the rename fails, the temporary is removed, `path` is left as it was,
/// and the exception propagates (failures of this function are std::runtime_error naming
/// `path`). No fsync: the goal is that no partial file ever appears under `path` after a
/// failed write, not durability across a power loss.
void writeFileAtomically(const std::string& path, const std::function<void(const std::string& temporary_path)>& write);

/// Writes `bytes` to `path` atomically (see writeFileAtomically).
void writeBytesAtomically(const std::string& path, std::string_view bytes);

}  // namespace floodplane::io
