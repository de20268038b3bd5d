// oneTBB's worker threads, joined before the process exits.
#pragma once

#include <new>

#include <tbb/global_control.h>

namespace sansui {

/// One at the top of main(): when main returns, it waits until oneTBB's worker threads have
/// ended. Without it they end on their own while the process is exiting, and LeakSanitizer's
/// exit-time check, whose tracer reads every thread's TLS, can crash on a thread caught halfway
/// through its exit ("LeakSanitizer has encountered a fatal error": flaky, more so under load).
class WorkerThreadsJoinedAtExit {
 public:
  WorkerThreadsJoinedAtExit() : handle_(tbb::attach{}) {}
  ~WorkerThreadsJoinedAtExit() { (void)tbb::finalize(handle_, std::nothrow); }
  WorkerThreadsJoinedAtExit(const WorkerThreadsJoinedAtExit&) = delete;
  WorkerThreadsJoinedAtExit& operator=(const WorkerThreadsJoinedAtExit&) = delete;

 private:
  tbb::task_scheduler_handle handle_;
};

}  // namespace sansui
