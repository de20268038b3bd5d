// The std::thread back end of core/parallel.hpp (CMake's SANSUI_PARALLEL=threads): the browser
// build's, on WebAssembly threads, where oneTBB is not available. A fixed pool of
// hardware_concurrency() - 1 workers (at most 15: each is a Web Worker with its own instance of
// the module, which the page makes up front), made at the first loop; the calling thread works too.
//
// A loop is cut into about four chunks a thread, which the threads take in turn from one counter,
// so a slow chunk does not hold the others back. The pool runs one loop at a time: a loop started
// inside the body of a loop the pool runs, or while another thread's loop runs, runs on the thread
// that started it, as one chunk, so a thread never waits on work it could do itself. A loop of
// one chunk runs its body directly, whose own loops may then use the pool (a level of the graph
// evaluator with one node, the erosion inside it).
// The first exception a chunk throws (a cancellation, bad input) stops the loop's chunks not yet
// taken and is thrown again on the calling thread, as oneTBB does.
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/parallel.hpp"

namespace sansui {

namespace {

// The thread's slot: 0 for the thread that started the running loop (and any thread outside the
// pool), k + 1 for worker k. Nonzero depth: the thread is inside a loop's body.
// Loops are started from one thread at a time (the module's, or main()'s), so slot 0 is never
// shared by two threads running at once.
thread_local int this_slot = 0;
thread_local int loop_depth = 0;

// Marks the thread as inside a loop's body while it lives.
struct InsideLoop {
  InsideLoop() { ++loop_depth; }
  ~InsideLoop() { --loop_depth; }
  InsideLoop(const InsideLoop&) = delete;
  InsideLoop& operator=(const InsideLoop&) = delete;
};

class Pool {
 public:
  Pool() : workers_(static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u)) - 1) {}
  ~Pool() {
    {
      const std::scoped_lock lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (auto& thread : threads_) thread.join();
  }
  Pool(const Pool&) = delete;
  Pool& operator=(const Pool&) = delete;

  int slots() const { return workers_ + 1; }
  void limit(int threads) { limit_.store(threads, std::memory_order_relaxed); }

  void run(std::int64_t begin, std::int64_t end, std::int64_t grain, parallel_detail::ChunkBody body) {
    if (begin >= end) return;
    const int helpers = std::min(workers_, std::max(limit_.load(std::memory_order_relaxed), 1) - 1);
    // One chunk (as a graph level of one node): its loops may still use the pool.
    if (helpers == 0 || end - begin <= grain) {
      body(begin, end);
      return;
    }
    std::unique_lock busy(busy_, std::defer_lock);
    if (loop_depth > 0 || !busy.try_lock()) {
      const InsideLoop inside;
      body(begin, end);
      return;
    }
    start_threads();
    const std::int64_t chunks = 4 * (helpers + 1);
    Loop loop{&body, end, std::max<std::int64_t>(grain, (end - begin + chunks - 1) / chunks), {begin}, {}, {}};
    {
      const std::scoped_lock lock(mutex_);
      loop_ = &loop;
      helpers_ = helpers;
      pending_ = helpers;
      ++generation_;
    }
    wake_.notify_all();
    work(loop);
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    loop_ = nullptr;
    lock.unlock();
    if (loop.error) std::rethrow_exception(loop.error);
  }

 private:
  struct Loop {
    parallel_detail::ChunkBody* body;
    std::int64_t end;
    std::int64_t chunk;
    std::atomic<std::int64_t> next;
    std::mutex error_lock;
    std::exception_ptr error;
  };

  // Takes chunks until none is left; the first exception ends the taking for every thread.
  static void work(Loop& loop) {
    const InsideLoop inside;
    for (;;) {
      const std::int64_t begin = loop.next.fetch_add(loop.chunk, std::memory_order_relaxed);
      if (begin >= loop.end) break;
      try {
        (*loop.body)(begin, std::min(begin + loop.chunk, loop.end));
      } catch (...) {
        const std::scoped_lock lock(loop.error_lock);
        if (!loop.error) loop.error = std::current_exception();
        loop.next.store(loop.end, std::memory_order_relaxed);
      }
    }
  }

  void start_threads() {
    if (!threads_.empty()) return;
    threads_.reserve(static_cast<std::size_t>(workers_));
    for (int k = 0; k < workers_; ++k) threads_.emplace_back([this, k] { serve(k); });
  }

  void serve(int k) {
    this_slot = k + 1;
    std::uint64_t seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      if (k >= helpers_) continue;  // this loop runs on fewer threads (ThreadLimit)
      Loop& loop = *loop_;
      lock.unlock();
      work(loop);
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  const int workers_;
  std::atomic<int> limit_{1 << 30};
  std::mutex busy_;  // held by the thread whose loop the pool runs
  std::vector<std::thread> threads_;
  std::mutex mutex_;  // guards what follows
  std::condition_variable wake_;
  std::condition_variable done_;
  Loop* loop_ = nullptr;
  int helpers_ = 0;
  int pending_ = 0;
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

namespace parallel_detail {

void for_chunks(std::int64_t begin, std::int64_t end, std::int64_t grain, ChunkBody body) {
  pool().run(begin, end, std::max<std::int64_t>(grain, 1), body);
}
int thread_slot() {
  return this_slot;
}
int thread_slots() {
  return pool().slots();
}

}  // namespace parallel_detail

// Limits are not nested here: the CLI and the tests set one at a time.
struct ThreadLimit::Control {};
ThreadLimit::ThreadLimit(int threads) {
  if (threads > 0) pool().limit(threads);
}
ThreadLimit::~ThreadLimit() {
  pool().limit(1 << 30);
}

// The pool is a static: its destructor joins the workers when the program exits.
struct WorkerThreadsJoinedAtExit::Handle {};
WorkerThreadsJoinedAtExit::WorkerThreadsJoinedAtExit() = default;
WorkerThreadsJoinedAtExit::~WorkerThreadsJoinedAtExit() = default;

}  // namespace sansui
