#include "core/context.hpp"

#include <mutex>

namespace sansui {

void Context::report(std::string_view stage, double fraction) const {
  if (!on_progress) return;
  std::lock_guard lock(*progress_lock);  // progress may come from worker threads
  on_progress(stage, fraction);
}

Context part_of(const Context& whole, std::string stage, double begin, double end) {
  Context part;
  part.cancel = whole.cancel;
  part.on_note = whole.on_note;
  part.progress_lock = whole.progress_lock;
  if (whole.on_progress)
    part.on_progress = [&whole, stage = std::move(stage), begin, end](std::string_view, double fraction) {
      whole.on_progress(stage, begin + fraction * (end - begin));
    };
  return part;
}

}  // namespace sansui
