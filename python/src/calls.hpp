// How a call into the library runs from Python: without the GIL (other Python threads go on),
// under the thread limit of sansui.set_threads(), with progress reported to a Python callable,
// and cancelled by Ctrl-C (KeyboardInterrupt) or by an exception the callable raises, at the
// library's next progress check. Errors become Python's: InputError is ValueError.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/context.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::python {

namespace py = pybind11;

/// The thread count of set_threads() (0: all cores).
int thread_count();
void set_thread_count(int threads);

/// The state of one call: its cancel flag, the progress callable, and why it was cancelled.
class CallState {
 public:
  /// `progress`: None, or a callable (stage: str, fraction: float). Installs a SIGINT handler
  /// for the call when Python's own default one is in place and this is the main thread.
  /// `notes`: where the library's notes go (a repair made to an input, a default assumed), for
  /// the caller to raise as Python warnings once the call is over; null: they are dropped.
  explicit CallState(py::object progress, std::vector<std::string>* notes = nullptr);
  ~CallState();
  CallState(const CallState&) = delete;
  CallState& operator=(const CallState&) = delete;

  const Context& context() const { return context_; }
  /// Gives SIGINT back to Python, then raises what stopped the call (KeyboardInterrupt, or the
  /// callable's exception) if anything did; called with the GIL held once the work has ended or
  /// thrown Cancelled.
  void raise_if_stopped();

 private:
  void on_progress(std::string_view stage, double fraction);
  void restore_sigint();

  py::object progress_;
  std::vector<std::string>* notes_;
  std::mutex notes_mutex_;
  std::atomic<bool> cancel_{false};
  std::optional<py::error_already_set> error_;
  bool handles_sigint_ = false;
  bool interrupted_ = false;  // a SIGINT came while this call held it
  Context context_;
};

/// Runs work(context) without the GIL, under the thread limit; turns Cancelled into the Python
/// exception that caused it. The library's notes go into `notes` when it is given.
template <class Work>
auto run_released(const py::object& progress, Work&& work, std::vector<std::string>* notes = nullptr) {
  CallState state(progress, notes);
  using Result = decltype(work(state.context()));
  std::optional<Result> result;
  try {
    py::gil_scoped_release release;
    const ThreadLimit limit(thread_count());
    result.emplace(work(state.context()));
  } catch (const Cancelled&) {
    state.raise_if_stopped();
    throw;
  }
  state.raise_if_stopped();  // Ctrl-C during the last stretch, after the last check
  return std::move(*result);
}

}  // namespace sansui::python
