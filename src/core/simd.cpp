#include "core/simd.hpp"

#include <atomic>
#include <cstdlib>
#include <string>

namespace sansui::simd {
namespace {

Level detected() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl"))
    return Level::avx512;
  if (__builtin_cpu_supports("avx2")) return Level::avx2;
#endif
  return Level::sse2;
}

Level from_environment() {
  const Level best = best_level();
  const char* text = std::getenv("SANSUI_SIMD");
  if (text == nullptr) return best;
  const std::string wanted(text);
  const Level asked = wanted == "sse2" ? Level::sse2 : wanted == "avx2" ? Level::avx2 : best;
  return asked < best ? asked : best;
}

std::atomic<int>& current() {
  static std::atomic<int> value{static_cast<int>(from_environment())};
  return value;
}

}  // namespace

Level best_level() {
  static const Level best = detected();
  return best;
}

Level level() {
  return static_cast<Level>(current().load(std::memory_order_relaxed));
}

void force_level(std::optional<Level> wanted) {
  const Level best = best_level();
  const Level chosen = !wanted ? from_environment() : (*wanted < best ? *wanted : best);
  current().store(static_cast<int>(chosen), std::memory_order_relaxed);
}

std::string_view name(Level level) {
  switch (level) {
    case Level::sse2:
      return "sse2";
    case Level::avx2:
      return "avx2";
    case Level::avx512:
      return "avx512";
  }
  return "sse2";
}

}  // namespace sansui::simd
