#include "io/atomic_file.hpp"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>
#include <system_error>

#include <unistd.h>

#include <fcntl.h>

#include "core/error.hpp"

namespace sansui::io {
namespace {

// ---- the registry of live temporary files, read by the signal handler ----------------------

enum SlotState : int { free_slot = 0, filling = 1, live = 2 };

struct Slot {
  std::atomic<int> state{free_slot};
  char path[4096] = {};
};

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");

std::array<Slot, 64> slots;

extern "C" void remove_temporaries_and_end(int signal_number) {
  const int saved = errno;
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == live) ::unlink(slot.path);
  errno = saved;
  // SA_RESETHAND restored the default action; the signal is blocked until this handler returns,
  // then ends the process with it (exit status 128 + signal).
  ::raise(signal_number);
}

// ---- the active batch ------------------------------------------------------------------------

std::mutex batch_mutex;
OutputBatch* active_batch = nullptr;  // guarded by batch_mutex

void remove_quietly(const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  detail::untrack_temporary(temporary);
}

/// fsync of the finished temporary: a full disk or an I/O error that the writer's close did not
/// report (delayed allocation, network file systems) shows here, before the rename.
void sync_to_disk(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  const int descriptor = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) fail("cannot write {}: {}", path.string(), std::strerror(errno));
  const bool synced = ::fsync(descriptor) == 0;
  const int error = errno;
  if (::close(descriptor) != 0 && synced) fail("cannot write {}: {}", path.string(), std::strerror(errno));
  if (!synced) fail("cannot write {}: {}", path.string(), std::strerror(error));
}

void rename_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) fail("cannot write {}: {}", path.string(), error.message());
  detail::untrack_temporary(temporary);
}

}  // namespace

namespace detail {

void track_temporary(const std::filesystem::path& temporary) {
  const std::string& name = temporary.native();
  if (name.size() >= sizeof(Slot::path)) return;
  for (Slot& slot : slots) {
    int expected = free_slot;
    if (!slot.state.compare_exchange_strong(expected, filling, std::memory_order_acq_rel)) continue;
    std::memcpy(slot.path, name.c_str(), name.size() + 1);
    slot.state.store(live, std::memory_order_release);
    return;
  }
}

void untrack_temporary(const std::filesystem::path& temporary) {
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == live && temporary.native() == slot.path) {
      slot.state.store(free_slot, std::memory_order_release);
      return;
    }
}

}  // namespace detail

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_end;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;
  for (const int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction previous {};
    // A signal the caller's parent set to be ignored (nohup, a shell's background job) stays so.
    if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
    ::sigaction(signal_number, &action, nullptr);
  }
}

void check_writable(const std::filesystem::path& path) {
  if (path.empty()) fail("output path is empty");
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    fail("cannot write {}: directory {} does not exist", path.string(), directory.string());
  if (::access(directory.c_str(), W_OK) != 0)
    fail("cannot write {}: directory {} is not writable ({})", path.string(), directory.string(), std::strerror(errno));
  if (std::filesystem::is_directory(path, error)) fail("cannot write {}: it is a directory", path.string());
}

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path& temporary)>& write) {
  check_writable(path);
  // Process id and a counter: unique even when two threads of one process write the same name,
  // and never the name of a temporary a killed run left behind (other process id).
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  detail::track_temporary(temporary);
  try {
    write(temporary);
    sync_to_disk(temporary, path);
    if (!OutputBatch::defer(temporary, path)) rename_into_place(temporary, path);
  } catch (...) {
    remove_quietly(temporary);
    throw;
  }
}

OutputBatch::OutputBatch() {
  const std::lock_guard lock(batch_mutex);
  if (active_batch != nullptr) return;  // joins the outer batch
  active_batch = this;
  outermost_ = true;
}

OutputBatch::~OutputBatch() {
  if (!outermost_) return;
  {
    const std::lock_guard lock(batch_mutex);
    active_batch = nullptr;
  }
  for (const auto& [temporary, path] : pending_) remove_quietly(temporary);
}

bool OutputBatch::defer(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  const std::lock_guard lock(batch_mutex);
  if (active_batch == nullptr) return false;
  const std::lock_guard pending_lock(active_batch->mutex_);
  active_batch->pending_.emplace_back(temporary, path);
  return true;
}

void OutputBatch::commit() {
  if (!outermost_) return;
  {
    const std::lock_guard lock(batch_mutex);
    active_batch = nullptr;
  }
  const std::lock_guard lock(mutex_);
  std::size_t done = 0;
  try {
    for (; done < pending_.size(); ++done) rename_into_place(pending_[done].first, pending_[done].second);
  } catch (...) {
    for (std::size_t k = done; k < pending_.size(); ++k) remove_quietly(pending_[k].first);
    pending_.clear();
    throw;
  }
  pending_.clear();
}

}  // namespace sansui::io
