// The one seam between Sansui and its thread pool (modelled on pbrt-v4's ParallelFor): parallel
// loops, per-thread values, a thread limit and the workers' exit. The back end is chosen at build
// time (SANSUI_PARALLEL: oneTBB, serial plain loops, or a std::thread pool for the browser);
// sorting is in core/parallel_sort.hpp.
// No oneTBB header here: the loop bodies are passed on type-erased, one call per chunk, so the
// many files that include this one do not parse the scheduler's templates.
#pragma once

#include <concepts>
#include <cstdint>
#include <functional>
#include <memory>
#include <type_traits>
#include <vector>

namespace sansui {

namespace parallel_detail {

/// A borrowed callable body(chunk_begin, chunk_end), called once per chunk.
class ChunkBody {
 public:
  template <class F>
  explicit ChunkBody(F& f) : object_(&f), call_([](void* o, std::int64_t b, std::int64_t e) { (*static_cast<F*>(o))(b, e); }) {}
  void operator()(std::int64_t begin, std::int64_t end) const { call_(object_, begin, end); }

 private:
  void* object_;
  void (*call_)(void*, std::int64_t, std::int64_t);
};

/// Splits [begin, end) into chunks of at least `grain` indices (oneTBB's blocked_range with its
/// auto partitioner; the serial back end makes one chunk) and calls body on each.
void for_chunks(std::int64_t begin, std::int64_t end, std::int64_t grain, ChunkBody body);

/// The calling thread's slot in the pool, in [0, thread_slots()): no two threads running at once
/// share one (oneTBB's thread index in its arena; 0 in the serial back end).
int thread_slot();
int thread_slots();

}  // namespace parallel_detail

/// Calls body(range_begin, range_end) on chunks of [begin, end), in parallel, each chunk at least
/// `grain` long (but the last). For loops that set up scratch once per chunk. The chunk
/// boundaries depend on the scheduling: results must not.
template <std::integral Index, class Body>
void parallel_for_ranges(std::type_identity_t<Index> begin, Index end, std::int64_t grain, Body&& body) {
  auto chunk = [&body](std::int64_t b, std::int64_t e) { body(static_cast<Index>(b), static_cast<Index>(e)); };
  parallel_detail::for_chunks(static_cast<std::int64_t>(begin), static_cast<std::int64_t>(end), grain, parallel_detail::ChunkBody(chunk));
}

/// Calls body(i) for every i in [begin, end), in parallel (grain 1, as oneTBB's parallel_for).
template <std::integral Index, class Body>
void parallel_for(std::type_identity_t<Index> begin, Index end, Body&& body) {
  parallel_for_ranges<Index>(begin, end, 1, [&body](Index b, Index e) {
    for (Index i = b; i < e; ++i) body(i);
  });
}

/// One T per thread, made on a thread's first local() (by `make`, or T's default constructor):
/// per-thread scratch or clones of an object that is not thread-safe. local() is for the bodies
/// of parallel loops; a body must not hold its T across a nested parallel loop (the thread may
/// run another body of the same loop meanwhile, as with oneTBB's enumerable_thread_specific).
template <class T>
class ThreadLocal {
 public:
  ThreadLocal() : ThreadLocal([] { return T(); }) {}
  template <class Make>
  explicit ThreadLocal(Make make) : make_(std::move(make)), slots_(static_cast<std::size_t>(parallel_detail::thread_slots())) {}

  T& local() {
    std::unique_ptr<T>& slot = slots_.at(static_cast<std::size_t>(parallel_detail::thread_slot()));
    if (!slot) slot = std::make_unique<T>(make_());
    return *slot;
  }

 private:
  std::function<T()> make_;
  std::vector<std::unique_ptr<T>> slots_;  // one allocation each: no false sharing between threads
};

/// At most `threads` threads run parallel loops while it lives (0: no limit). Results never
/// depend on the number.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Control;
  std::unique_ptr<Control> control_;
};

/// One at the top of main(): when main returns, it waits until the pool's worker threads have
/// ended. Without it they end on their own while the process is exiting, and LeakSanitizer's
/// exit-time check, whose tracer reads every thread's TLS, can crash on a thread caught halfway
/// through its exit ("LeakSanitizer has encountered a fatal error": flaky, more so under load).
class WorkerThreadsJoinedAtExit {
 public:
  WorkerThreadsJoinedAtExit();
  ~WorkerThreadsJoinedAtExit();
  WorkerThreadsJoinedAtExit(const WorkerThreadsJoinedAtExit&) = delete;
  WorkerThreadsJoinedAtExit& operator=(const WorkerThreadsJoinedAtExit&) = delete;

 private:
  struct Handle;
  std::unique_ptr<Handle> handle_;
};

}  // namespace sansui
