// The serial back end of core/parallel.hpp (CMake's SANSUI_PARALLEL=serial): every loop on the
// calling thread, in order, as one chunk.
#include "core/parallel.hpp"

namespace sansui {

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

}  // namespace sansui
