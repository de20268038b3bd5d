#include "core/context.hpp"

#include <mutex>

namespace sansui {

void Context::report(std::string_view stage, double fraction) const {
  if (!on_progress) return;
  static std::mutex serialise;  // progress may come from worker threads
  std::lock_guard lock(serialise);
  on_progress(stage, fraction);
}

}  // namespace sansui
