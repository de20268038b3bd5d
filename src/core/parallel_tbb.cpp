// The oneTBB back end of core/parallel.hpp (CMake's SANSUI_PARALLEL=tbb, the default).
#include <algorithm>
#include <new>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "core/parallel.hpp"

namespace sansui {

namespace parallel_detail {

void for_chunks(std::int64_t begin, std::int64_t end, std::int64_t grain, ChunkBody body) {
  if (begin >= end) return;
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(begin, end, static_cast<std::size_t>(grain)),
                    [&body](const tbb::blocked_range<std::int64_t>& range) { body(range.begin(), range.end()); });
}

// Outside any parallel loop a thread may have no index yet (-1): it is then the only one running.
int thread_slot() {
  return std::max(tbb::this_task_arena::current_thread_index(), 0);
}
int thread_slots() {
  return std::max(tbb::this_task_arena::max_concurrency(), 1);
}

}  // namespace parallel_detail

struct ThreadLimit::Control {
  explicit Control(int threads) : control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads)) {}
  tbb::global_control control;
};
ThreadLimit::ThreadLimit(int threads) : control_(threads > 0 ? std::make_unique<Control>(threads) : nullptr) {}
ThreadLimit::~ThreadLimit() = default;

struct WorkerThreadsJoinedAtExit::Handle {
  tbb::task_scheduler_handle handle{tbb::attach{}};
};
WorkerThreadsJoinedAtExit::WorkerThreadsJoinedAtExit() : handle_(std::make_unique<Handle>()) {}
WorkerThreadsJoinedAtExit::~WorkerThreadsJoinedAtExit() {
  (void)tbb::finalize(handle_->handle, std::nothrow);
}

}  // namespace sansui
