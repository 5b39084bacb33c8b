// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing files so that a reader sees either the previous file or the complete new one, and
// a group of files (one input's outputs) all or none.

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace floodplane::io {

/// Files written together, all or none: add() writes each file's bytes at once to a temporary
/// next to it (a hidden ".NAME.tmp.<pid>.<n>"), checking every write, so that an error such as
/// a full disk shows there with the system's reason; commit() then renames them all over their
/// paths. Until commit() no path has changed; a group destroyed before it (an error, an
/// exception) removes its temporaries and leaves the paths as they were. commit() replaces all
/// of the previous files or none: it keeps each previous file under a second name (a hard link)
/// until every new one is in place, and if a path cannot be replaced (a directory there, an
/// immutable file) or a rename fails part-way, every path gets its previous file back (or none,
/// if it had none): nothing of the group is left and nothing of the old set is lost.
/// Each temporary is flushed to the disk (fsync) before any rename, and the directories after
/// them: after a crash or a power loss a path holds its previous file or the whole new one,
/// never an empty or partial file.
class AtomicFileGroup {
 public:
  AtomicFileGroup() = default;
  AtomicFileGroup(AtomicFileGroup&& other) noexcept;
  AtomicFileGroup& operator=(AtomicFileGroup&& other) noexcept;
  AtomicFileGroup(const AtomicFileGroup&) = delete;
  AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
  ~AtomicFileGroup();

  /// Writes `bytes` to a new temporary for `path`. Throws std::runtime_error naming `path` and
  /// the system's reason if it cannot, std::invalid_argument for an empty path or a path the
  /// group already holds.
  void add(const std::string& path, std::string_view bytes);

  /// Adds `path` written by `write`, which is handed the temporary's path, for writers that
  /// insist on opening a path themselves (see writeFileAtomically). Throws what `write` throws,
  /// having removed the temporary.
  void addWrittenBy(const std::string& path, const std::function<void(const std::string& temporary_path)>& write);

  /// Renames every temporary over its path; throws std::runtime_error naming the path that
  /// failed, having removed every temporary and whatever the group had already put in place.
  void commit();

  /// The paths added and not yet committed, in the order they were added.
  std::vector<std::string> paths() const;

 private:
  struct Pending {
    std::string path;
    std::string temporary;
  };
  void checkNewPath(const std::string& path) const;
  void renameAll();
  void discard() noexcept;
  std::vector<Pending> pending_;
};

/// Writes `bytes` to `path` atomically: a group of one file (AtomicFileGroup).
void writeBytesAtomically(const std::string& path, std::string_view bytes);

/// Writes `path` atomically for writers that insist on opening a path themselves: `write`
/// fills a temporary file in the same directory (it is handed the temporary's path), and the
/// temporary is then renamed over `path`. If `write` throws or the rename fails, the temporary
/// is removed, `path` is left as it was, and the exception propagates (failures of this
/// function are std::runtime_error naming `path`). Prefer writeBytesAtomically: the writer
/// here reports its errors in its own words, and it may open the path again after
/// abandonAtomicWrites removed it.
void writeFileAtomically(const std::string& path, const std::function<void(const std::string& temporary_path)>& write);

/// For a program ending on a signal (SIGINT, SIGTERM): removes the temporary file of every
/// atomic write under way in the process and stops atomic writes for good, so that none
/// creates a temporary or renames one after this returns (a thread that tries waits until the
/// process ends). Returns the number of temporaries removed. Call it from an ordinary thread
/// (it takes a lock and allocates: not async-signal-safe), and end the process after it.
std::size_t abandonAtomicWrites();

}  // namespace floodplane::io
