#include "io/atomic_file.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>
#include <unordered_map>
#include <vector>

#include <unistd.h>

#include <fcntl.h>

#include "core/error.hpp"

namespace sansui::io {
namespace {

// ---- the registry of live temporary files, read by the signal handler ----------------------
//
// A singly linked list of nodes, pushed at its head and never freed (the handler may be reading
// any node at any time), so there is no fixed number of slots. track() and untrack() are ordinary
// code and take a mutex; they reuse a node freed earlier whose buffer is large enough, so the
// list grows only to the largest number of temporaries alive at once. The handler takes no lock:
// it walks the list and reads each live name seqlock-style (copy it, then check that the node's
// generation did not change), so a node that another thread frees and reuses meanwhile is
// skipped, never half read.

struct TemporaryNode {
  TemporaryNode(TemporaryNode* next_node, std::size_t size) : next(next_node), capacity(size), name(new std::atomic<char>[size]) {}
  TemporaryNode* const next;            ///< set before the node is published; never changes
  const std::size_t capacity;           ///< bytes of `name`, its NUL included
  std::atomic<unsigned> generation{0};  ///< odd while the name is a live temporary
  std::atomic<char>* const name;        ///< never freed, like the node
};

static_assert(std::atomic<unsigned>::is_always_lock_free && std::atomic<char>::is_always_lock_free &&
                  std::atomic<TemporaryNode*>::is_always_lock_free,
              "the signal handler reads the registry's atomics");

/// The registry's state that only track() and untrack() use, under `mutex`.
struct TemporaryRegistry {
  std::mutex mutex;
  std::unordered_map<std::string, TemporaryNode*> live;
  std::vector<TemporaryNode*> free;
};

std::atomic<TemporaryNode*> temporaries_head{nullptr};

TemporaryRegistry& temporary_registry() {
  static auto* registry = new TemporaryRegistry;  // never destroyed: a signal may come during exit
  return *registry;
}

/// The longest name the handler copies (PATH_MAX on Linux): longer ones cannot be unlinked anyway.
constexpr std::size_t longest_tracked_name = 4096;

extern "C" void remove_temporaries_and_end(int signal_number) {
  const int saved = errno;
  std::array<char, longest_tracked_name> copy{};
  for (TemporaryNode* node = temporaries_head.load(std::memory_order_acquire); node != nullptr; node = node->next) {
    const unsigned generation = node->generation.load(std::memory_order_acquire);
    if (generation % 2 == 0) continue;
    std::size_t length = 0;
    for (; length + 1 < copy.size() && length < node->capacity; ++length) {
      copy[length] = node->name[length].load(std::memory_order_relaxed);
      if (copy[length] == '\0') break;
    }
    copy[length] = '\0';
    std::atomic_thread_fence(std::memory_order_acquire);
    if (node->generation.load(std::memory_order_relaxed) == generation) ::unlink(copy.data());
  }
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
  if (name.size() >= longest_tracked_name) return;
  TemporaryRegistry& registry = temporary_registry();
  const std::lock_guard lock(registry.mutex);
  if (registry.live.contains(name)) return;
  TemporaryNode* node = nullptr;
  const auto fits =
      std::find_if(registry.free.begin(), registry.free.end(), [&](const TemporaryNode* n) { return n->capacity > name.size(); });
  const bool reused = fits != registry.free.end();
  if (reused) {
    node = *fits;
    *fits = registry.free.back();
    registry.free.pop_back();
    // The handler must not take the name written below for the node's previous (even: free)
    // generation: this fence orders the name after that generation for a handler that reads it.
    std::atomic_thread_fence(std::memory_order_release);
  } else {
    node = new TemporaryNode(temporaries_head.load(std::memory_order_relaxed), std::max<std::size_t>(name.size() + 1, 256));
  }
  for (std::size_t k = 0; k <= name.size(); ++k) node->name[k].store(name.c_str()[k], std::memory_order_relaxed);
  node->generation.fetch_add(1, std::memory_order_release);  // odd: live
  if (!reused) temporaries_head.store(node, std::memory_order_release);
  registry.live.emplace(name, node);
}

void untrack_temporary(const std::filesystem::path& temporary) {
  TemporaryRegistry& registry = temporary_registry();
  const std::lock_guard lock(registry.mutex);
  const auto found = registry.live.find(temporary.native());
  if (found == registry.live.end()) return;
  TemporaryNode* node = found->second;
  node->generation.fetch_add(1, std::memory_order_release);  // even: free
  registry.live.erase(found);
  registry.free.push_back(node);
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

bool can_create_file_in(const std::filesystem::path& folder) {
  std::string name = (folder / ".sansui-probe-XXXXXX").string();
  const int descriptor = ::mkstemp(name.data());
  if (descriptor < 0) return false;
  ::close(descriptor);
  ::unlink(name.c_str());
  return true;
}

namespace {

/// Where a write to `path` goes: `path`, or when it is a symbolic link (which scene::plan_outputs
/// refuses unless told to follow links), the file the link leads to, so that the rename replaces
/// that file rather than the link.
std::filesystem::path link_target(const std::filesystem::path& path) {
  std::filesystem::path target = path;
  for (int hops = 0; hops < 40; ++hops) {  // 40: Linux's limit of links in a row (ELOOP)
    std::error_code error;
    if (!std::filesystem::is_symlink(target, error)) return target;
    const std::filesystem::path next = std::filesystem::read_symlink(target, error);
    if (error) return target;
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  return target;
}

/// Makes the temporary file a write to `target` goes through, as a new empty file of this
/// process (O_EXCL | O_NOFOLLOW): a link or file planted under the name it will have is never
/// written through, nor truncated. The writer then opens it by name. Tracked for the signal
/// handler from here on.
std::filesystem::path reserve_temporary(const std::filesystem::path& target) {
  // Process id and a counter: unique even when two threads of one process write the same name,
  // and never the name of a temporary a killed run left behind (other process id); a name taken
  // all the same (a planted file) moves on to the next count.
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0;; ++attempt) {
    std::filesystem::path temporary = target;
    temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    detail::track_temporary(temporary);
    const int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor >= 0) {
      ::close(descriptor);
      return temporary;
    }
    const int error = errno;
    detail::untrack_temporary(temporary);
    if (error != EEXIST || attempt >= 100) fail("cannot write {}: {}", target.string(), std::strerror(error));
  }
}

}  // namespace

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path& temporary)>& write) {
  const std::filesystem::path target = link_target(path);
  check_writable(target);
  // Process id and a counter: unique even when two threads of one process write the same name,
  // and never the name of a temporary a killed run left behind (other process id).
  const std::filesystem::path temporary = reserve_temporary(target);
  try {
    write(temporary);
    sync_to_disk(temporary, target);
    if (!OutputBatch::defer(temporary, target)) rename_into_place(temporary, target);
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
