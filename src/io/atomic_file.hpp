// Writing files without ever leaving a half-written one: write to a temporary name in the same
// directory (NAME.tmp-PID-N), flush it to disk (fsync), then rename over the target (atomic on
// POSIX). If anything throws before the rename, the temporary file is removed; while it exists,
// its name is in a registry that remove_temporaries_on_signals()'s handler unlinks on SIGINT and
// SIGTERM. A process killed with SIGKILL leaves its NAME.tmp-PID-N behind (nothing can run then):
// later runs ignore such files (they never read or overwrite them; any can be deleted).
//
// While an OutputBatch is alive, finished temporaries are not renamed at once: the batch renames
// them all when it is committed, or removes them all if it is not, so that a command writes all
// its outputs or none.
#pragma once

#include <filesystem>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

namespace sansui::io {

/// Calls write(temporary_path), checks the temporary reached the disk (fsync), then renames it to
/// `path` (or leaves that to the active OutputBatch). Checks first that the directory exists and
/// is writable, with a message naming it. Throws InputError "cannot write PATH: <OS error>".
/// A `path` that is a symbolic link is written through: its target gets the bytes, the link
/// stays (recipes refuse such outputs unless told --follow-symlinks: scene/output_plan.hpp).
void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path& temporary)>& write);

/// Throws InputError unless `path`'s directory exists and is writable: lets commands fail before
/// long work rather than after.
void check_writable(const std::filesystem::path& path);

/// Whether this process can make a file in `folder`: makes one there under a fresh name (mkstemp:
/// O_CREAT | O_EXCL, so never through a link planted under a name a probe would use) and
/// removes it. For folders that other ranks or later runs will write into.
bool can_create_file_in(const std::filesystem::path& folder);

/// All or nothing for the files of one command: while a batch is alive (one per process; a batch
/// made while another is alive joins it and does nothing itself), write_atomically keeps each
/// finished file under its temporary name. commit() renames them all, in the order they were
/// written; the destructor of a batch not committed removes them all. Thread-safe.
class OutputBatch {
 public:
  OutputBatch();
  ~OutputBatch();
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  /// Renames every file written since the batch began into place. Throws InputError naming the
  /// file if a rename fails (the files not yet renamed are removed; those renamed stay).
  void commit();

  /// Used by write_atomically: true if the rename of `temporary` to `path` was taken over by the
  /// active batch (false if there is none).
  static bool defer(const std::filesystem::path& temporary, const std::filesystem::path& path);

 private:
  bool outermost_ = false;
  std::mutex mutex_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> pending_;  // temporary, final
};

/// Installs handlers of SIGINT and SIGTERM that unlink every live temporary file of
/// write_atomically, then end the process by the same signal (exit status 128 + signal, 130 and
/// 143 in a shell). Async-signal-safe: the handler walks a lock-free list of names (atomic loads,
/// unlink, then the default action), which has no fixed size. Called by the CLI's main() and the
/// viewer's; idempotent.
void remove_temporaries_on_signals();

namespace detail {

/// The registry the signal handler reads: a temporary file that exists from track() to untrack().
/// Any number at a time (names of 4096 bytes or more, which the system cannot open, are not
/// tracked). Thread-safe; not for use inside a signal handler.
void track_temporary(const std::filesystem::path& temporary);
void untrack_temporary(const std::filesystem::path& temporary);

}  // namespace detail

}  // namespace sansui::io
