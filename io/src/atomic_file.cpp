// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <unordered_set>
#include <utility>

namespace floodplane::io {
namespace {

std::string systemError(int error) { return std::strerror(error); }

std::runtime_error writeError(const std::string& path, const std::string& reason) {
  return std::runtime_error("cannot write '" + path + "': " + reason);
}

// The temporaries that exist right now, so that abandonAtomicWrites can remove them. Creating
// a temporary, removing one and renaming one all happen under the lock, which
// abandonAtomicWrites takes and never gives back: after it, no temporary appears or moves.
struct LiveTemporaries {
  std::mutex mutex;
  std::unordered_set<std::string> paths;
};

LiveTemporaries& liveTemporaries() {
  // Never destroyed: a signal may arrive while static objects are being destroyed at exit.
  static LiveTemporaries* const live = new LiveTemporaries;
  return *live;
}

// Creates an empty, uniquely named file next to `path`, registered as live, and returns its
// name and an open descriptor. The name starts with a dot and ends in ".tmp.<pid>.<n>" so a
// leftover (after a crash) is easy to recognise, and O_EXCL makes sure two writers never share
// one temporary.
std::pair<std::string, int> createTemporaryNextTo(const std::string& path) {
  static unsigned counter = 0;  // guarded by the lock
  const std::filesystem::path target(path);
  const std::filesystem::path directory = target.parent_path();
  LiveTemporaries& live = liveTemporaries();
  const std::lock_guard<std::mutex> lock(live.mutex);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name =
        "." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
    const std::string temporary = (directory / name).string();
    // 0666 and the process umask give the final file the permissions an ordinary write would.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      live.paths.insert(temporary);
      return {temporary, fd};
    }
    if (errno != EEXIST) throw writeError(path, systemError(errno));
  }
  throw writeError(path, "no free temporary file name");
}

void removeTemporaries(const std::vector<std::string>& temporaries) noexcept {
  LiveTemporaries& live = liveTemporaries();
  const std::lock_guard<std::mutex> lock(live.mutex);
  for (const std::string& temporary : temporaries) {
    ::unlink(temporary.c_str());
    live.paths.erase(temporary);
  }
}

// Flushes `fd`'s data to the disk and closes it; throws naming `path` and the system's reason,
// with `fd` closed. Before the rename: a crash or power loss after it then finds the new file
// whole under the path, never an empty or partial one (the rename can reach the disk before
// the data otherwise, as on ext4 with delalloc or XFS).
void syncAndClose(int fd, const std::string& path) {
  while (::fsync(fd) != 0) {
    if (errno == EINTR) continue;
    const int error = errno;
    ::close(fd);
    throw writeError(path, systemError(error));
  }
  // Some file systems (NFS) report a failed write only here. EINTR: the descriptor is closed
  // all the same on Linux, and the data was written.
  if (::close(fd) != 0 && errno != EINTR) throw writeError(path, systemError(errno));
}

// Writes all of `bytes` to `fd`, flushes them to the disk and closes it; throws naming `path`
// and the system's reason (ENOSPC: "No space left on device"), with `fd` closed.
void writeAndClose(int fd, std::string_view bytes, const std::string& path) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t count = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (count < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      throw writeError(path, systemError(error));
    }
    written += static_cast<std::size_t>(count);
  }
  syncAndClose(fd, path);
}

// Flushes the directories holding `paths` to the disk, so that the renames into them last
// too; a directory that cannot be flushed (a file system without it) is left as it is, the
// files themselves being flushed already.
void syncDirectoriesOf(const std::vector<std::string>& paths) noexcept {
  std::unordered_set<std::string> done;
  for (const std::string& path : paths) {
    std::string directory = std::filesystem::path(path).parent_path().string();
    if (directory.empty()) directory = ".";
    if (!done.insert(directory).second) continue;
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) continue;
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

AtomicFileGroup::AtomicFileGroup(AtomicFileGroup&& other) noexcept : pending_(std::move(other.pending_)) {
  other.pending_.clear();
}

AtomicFileGroup& AtomicFileGroup::operator=(AtomicFileGroup&& other) noexcept {
  if (this != &other) {
    discard();
    pending_ = std::move(other.pending_);
    other.pending_.clear();
  }
  return *this;
}

AtomicFileGroup::~AtomicFileGroup() { discard(); }

void AtomicFileGroup::discard() noexcept {
  std::vector<std::string> temporaries;
  for (const Pending& pending : pending_) temporaries.push_back(pending.temporary);
  if (!temporaries.empty()) removeTemporaries(temporaries);
  pending_.clear();
}

std::vector<std::string> AtomicFileGroup::paths() const {
  std::vector<std::string> paths;
  for (const Pending& pending : pending_) paths.push_back(pending.path);
  return paths;
}

void AtomicFileGroup::checkNewPath(const std::string& path) const {
  if (path.empty()) throw std::invalid_argument("AtomicFileGroup: empty path");
  if (std::any_of(pending_.begin(), pending_.end(), [&](const Pending& pending) { return pending.path == path; })) {
    throw std::invalid_argument("AtomicFileGroup: '" + path + "' added twice");
  }
}

void AtomicFileGroup::add(const std::string& path, std::string_view bytes) {
  checkNewPath(path);
  pending_.reserve(pending_.size() + 1);  // so that the push_back below cannot throw
  // Written through the descriptor that created it: no one opens the temporary again by path,
  // so once abandonAtomicWrites removed it, it stays removed.
  const auto [temporary, fd] = createTemporaryNextTo(path);
  try {
    writeAndClose(fd, bytes, path);
  } catch (...) {
    removeTemporaries({temporary});
    throw;
  }
  pending_.push_back({path, temporary});
}

void AtomicFileGroup::addWrittenBy(const std::string& path,
                                   const std::function<void(const std::string& temporary_path)>& write) {
  checkNewPath(path);
  pending_.reserve(pending_.size() + 1);
  const auto [temporary, fd] = createTemporaryNextTo(path);
  ::close(fd);
  try {
    write(temporary);
    // Opened again for the flush alone: a writer that failed to write would have thrown.
    const int written = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
    if (written < 0) throw writeError(path, systemError(errno));
    syncAndClose(written, path);
  } catch (...) {
    removeTemporaries({temporary});
    throw;
  }
  pending_.push_back({path, temporary});
}

void AtomicFileGroup::commit() {
  std::vector<std::string> paths;
  for (const Pending& file : pending_) paths.push_back(file.path);
  renameAll();
  // Outside the lock: other threads' writes need not wait for these flushes.
  syncDirectoriesOf(paths);
}

void AtomicFileGroup::renameAll() {
  std::vector<Pending> pending = std::move(pending_);
  pending_.clear();
  LiveTemporaries& live = liveTemporaries();
  const std::lock_guard<std::mutex> lock(live.mutex);
  // Each path's previous file, kept under a second name until every new file is in place, so
  // that a rename failing part-way puts the previous files back: the group replaces all of the
  // old set or none of it. A hard link leaves the path in place meanwhile (a crash still finds
  // the old file or the new one there); where links are refused (a file system without them)
  // the old file is moved aside instead. An old file that cannot be linked nor moved (an
  // immutable one, a directory that cannot change) stops the commit before anything changed.
  struct Kept {
    std::string backup;  // empty: the path had no file
    bool moved = false;  // moved aside rather than linked: the path is empty until the rename
  };
  std::vector<Kept> kept(pending.size());
  const auto give_back = [&](std::size_t renamed) {
    for (std::size_t k = 0; k < pending.size(); ++k) {
      const Kept& old = kept[k];
      if (k < renamed || old.moved) {
        if (old.backup.empty()) {
          ::unlink(pending[k].path.c_str());
        } else {
          ::rename(old.backup.c_str(), pending[k].path.c_str());
        }
      } else if (!old.backup.empty()) {
        ::unlink(old.backup.c_str());
      }
      if (k >= renamed) ::unlink(pending[k].temporary.c_str());
      live.paths.erase(pending[k].temporary);
    }
  };
  // rename() cannot put a file over a directory: found before anything is renamed.
  for (const Pending& file : pending) {
    struct stat status {};
    if (::lstat(file.path.c_str(), &status) == 0 && S_ISDIR(status.st_mode)) {
      give_back(0);
      throw writeError(file.path, systemError(EISDIR));
    }
  }
  for (std::size_t k = 0; k < pending.size(); ++k) {
    struct stat status {};
    if (::lstat(pending[k].path.c_str(), &status) != 0) continue;
    const std::string backup = pending[k].temporary + ".old";
    if (::link(pending[k].path.c_str(), backup.c_str()) == 0) {
      kept[k].backup = backup;
    } else if (::rename(pending[k].path.c_str(), backup.c_str()) == 0) {
      kept[k] = {backup, true};
    } else {
      const int error = errno;
      give_back(0);
      throw writeError(pending[k].path, "cannot replace the previous file: " + systemError(error));
    }
  }
  for (std::size_t k = 0; k < pending.size(); ++k) {
    if (::rename(pending[k].temporary.c_str(), pending[k].path.c_str()) != 0) {
      const int error = errno;
      give_back(k);
      throw writeError(pending[k].path, "rename failed: " + systemError(error));
    }
    kept[k].moved = false;  // the path holds the new file
  }
  for (std::size_t k = 0; k < pending.size(); ++k) {
    if (!kept[k].backup.empty()) ::unlink(kept[k].backup.c_str());
    live.paths.erase(pending[k].temporary);
  }
}

void writeBytesAtomically(const std::string& path, std::string_view bytes) {
  AtomicFileGroup file;
  file.add(path, bytes);
  file.commit();
}

void writeFileAtomically(const std::string& path, const std::function<void(const std::string& temporary_path)>& write) {
  if (path.empty()) throw std::invalid_argument("writeFileAtomically: empty path");
  AtomicFileGroup file;
  file.addWrittenBy(path, write);
  file.commit();
}

std::size_t abandonAtomicWrites() {
  LiveTemporaries& live = liveTemporaries();
  live.mutex.lock();  // never unlocked: the process is ending
  for (const std::string& temporary : live.paths) ::unlink(temporary.c_str());
  return live.paths.size();
}

}  // namespace floodplane::io
