// The back ends of core/parallel.hpp: oneTBB, or plain loops when built with
// SANSUI_PARALLEL_SERIAL (CMake's SANSUI_PARALLEL=serial).
#include "core/parallel.hpp"

#ifndef SANSUI_PARALLEL_SERIAL
#include <algorithm>
#include <new>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

namespace sansui {

#ifndef SANSUI_PARALLEL_SERIAL

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

#else  // serial: every loop on the calling thread, in order

namespace parallel_detail {

void for_chunks(std::int64_t begin, std::int64_t end, std::int64_t, ChunkBody body) {
  if (begin < end) body(begin, end);
}
int thread_slot() {
  return 0;
}
int thread_slots() {
  return 1;
}

}  // namespace parallel_detail

struct ThreadLimit::Control {};
ThreadLimit::ThreadLimit(int) {}
ThreadLimit::~ThreadLimit() = default;

struct WorkerThreadsJoinedAtExit::Handle {};
WorkerThreadsJoinedAtExit::WorkerThreadsJoinedAtExit() = default;
WorkerThreadsJoinedAtExit::~WorkerThreadsJoinedAtExit() = default;

#endif

}  // namespace sansui
