// The small object long-running stages receive: progress reports, notes and cancellation.
// Algorithms call report(); only apps decide whether to draw a progress bar.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "core/error.hpp"

namespace sansui {

struct Context {
  /// Called with the stage name and the fraction done in [0, 1]. May be called from any
  /// thread, but never concurrently (report() serialises calls). Empty: no reports.
  std::function<void(std::string_view stage, double fraction)> on_progress;
  /// Raised by the caller to stop long work; stages throw Cancelled at their next check.
  const std::atomic<bool>* cancel = nullptr;
  /// Called with a note worth telling the user (a repair made to an input, a value chosen from
  /// the data). Empty: notes are dropped.
  std::function<void(std::string_view note)> on_note;

  /// Serialises on_progress calls. Shared by the contexts made from this one (part_of), so
  /// that their reports to the same callable never overlap; a context made anew has its own, so
  /// that a call started from inside a progress callable (Python's) never waits on its caller's.
  std::shared_ptr<std::mutex> progress_lock = std::make_shared<std::mutex>();

  void report(std::string_view stage, double fraction) const;
  void note(std::string_view text) const {
    if (on_note) on_note(text);
  }
  void check_cancelled() const {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed)) throw Cancelled();
  }
};

/// A context for one part of a longer piece of work: its reports, whatever their stage, become
/// `stage` of `whole` at begin + fraction x (end - begin), so that the whole's bar moves in
/// proportion to time and its remaining time stays honest. Notes and cancellation pass through.
/// `whole` must outlive the part.
Context part_of(const Context& whole, std::string stage, double begin, double end);

/// A context that reports nothing and never cancels.
inline const Context& quiet_context() {
  static const Context context;
  return context;
}

}  // namespace sansui
