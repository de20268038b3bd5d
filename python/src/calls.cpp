#include "calls.hpp"

#include <csignal>
#include <stdexcept>
#include <string>

namespace sansui::python {

namespace {

std::atomic<int> threads{0};

/// Set on a thread while it runs a call's progress callable. A call made from there would run
/// its parallel loops inside one of the outer call's (on the same worker, whose per-thread
/// scratch the outer loop still holds): refused with a clear error instead.
thread_local bool in_progress_callable = false;

// The flag of the call that handles SIGINT now (one at a time: the main thread's).
std::atomic<std::atomic<bool>*> sigint_target{nullptr};
std::atomic<bool> sigint_seen{false};
struct sigaction python_sigint_action;

extern "C" void cancel_on_sigint(int) {
  sigint_seen.store(true);
  if (std::atomic<bool>* target = sigint_target.load()) target->store(true);
}

/// Whether SIGINT is Python's default KeyboardInterrupt and we are on the main thread: then a
/// call may take the signal over while it runs. A program with its own handler keeps it.
bool may_handle_sigint() {
  const py::module_ signal = py::module_::import("signal");
  const py::module_ threading = py::module_::import("threading");
  return threading.attr("current_thread")().is(threading.attr("main_thread")()) &&
         signal.attr("getsignal")(signal.attr("SIGINT")).is(signal.attr("default_int_handler"));
}

}  // namespace

int thread_count() {
  return threads.load();
}

void set_thread_count(int count) {
  threads.store(count);
}

CallState::CallState(py::object progress, std::vector<std::string>* notes) : progress_(std::move(progress)), notes_(notes) {
  if (in_progress_callable)
    throw std::runtime_error(
        "a sansui function was called from inside a progress callable of another sansui call: the progress callable may "
        "record, print or raise, but cannot run Sansui again; make the second call after the first returns (or from another thread)");
  context_.cancel = &cancel_;
  // Progress comes from any one worker thread at a time (Context::report serialises it); the
  // callable runs with the GIL taken for it.
  if (!progress_.is_none()) context_.on_progress = [this](std::string_view stage, double fraction) { on_progress(stage, fraction); };
  if (notes_ != nullptr)
    context_.on_note = [this](std::string_view note) {
      const std::lock_guard lock(notes_mutex_);
      notes_->emplace_back(note);
    };
  if (sigint_target.load() == nullptr && may_handle_sigint()) {
    sigint_seen.store(false);
    sigint_target.store(&cancel_);
    struct sigaction action {};
    action.sa_handler = cancel_on_sigint;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &python_sigint_action);
    handles_sigint_ = true;
  }
}

CallState::~CallState() {
  restore_sigint();
}

void CallState::restore_sigint() {
  if (!handles_sigint_) return;
  sigaction(SIGINT, &python_sigint_action, nullptr);
  sigint_target.store(nullptr);
  handles_sigint_ = false;
  interrupted_ = sigint_seen.exchange(false);
}

void CallState::on_progress(std::string_view stage, double fraction) {
  if (cancel_.load()) return;
  const py::gil_scoped_acquire gil;
  in_progress_callable = true;
  struct Reset {
    ~Reset() { in_progress_callable = false; }
  } reset;
  try {
    progress_(std::string(stage), fraction);
  } catch (py::error_already_set& error) {
    error_.emplace(std::move(error));
    cancel_.store(true);
  }
}

void CallState::raise_if_stopped() {
  // Python's handler first, so that no Ctrl-C falls between our check and its return.
  restore_sigint();
  if (error_) {
    py::error_already_set error = std::move(*error_);
    error_.reset();
    throw error;
  }
  if (interrupted_) {
    interrupted_ = false;
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
}

}  // namespace sansui::python
