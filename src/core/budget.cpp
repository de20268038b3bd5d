// The one budget check (see budget.hpp).
#include "core/budget.hpp"

#include "core/error.hpp"
#include "core/memory.hpp"

namespace sansui::budget {

std::string format_bytes(double bytes) {
  if (bytes >= 1e12) return fmt::format("{:.3g} TB", bytes / 1e12);
  return fmt::format("{:.3g} GB", bytes / 1e9);
}

std::string format_seconds(double seconds) {
  if (!(seconds < 1e12)) return "forever";
  if (seconds < 120.0) return fmt::format("{:.0f} s", seconds);
  if (seconds < 3.0 * 3600.0) return fmt::format("{:.0f} minutes", seconds / 60.0);
  return fmt::format("{:.3g} hours", seconds / 3600.0);
}

void check(const Cost& cost, bool forced) {
  const double allowed = static_cast<double>(memory_limit_bytes());
  if (!(cost.bytes <= allowed))  // NaN is refused too
    fail("{} needs {}, more than the memory limit of {} (raise it with --max-memory GB{}{})", cost.what, format_bytes(cost.bytes),
         format_bytes(allowed), cost.smaller.empty() ? "" : ", or ", cost.smaller);
  if (forced && !cost.force.empty()) return;
  if (cost.seconds <= work_limit_s) return;
  std::string way_out = cost.smaller;
  if (!cost.force.empty()) way_out += fmt::format("{}pass {} to run it", way_out.empty() ? "" : ", or ", cost.force);
  fail("{} would take about {}, more than the work limit of {}{}{}", cost.what, format_seconds(cost.seconds), format_seconds(work_limit_s),
       way_out.empty() ? "" : ": ", way_out);
}

}  // namespace sansui::budget
