// Which vector instructions the hot loops use, chosen at run time: one portable binary (x86-64's
// baseline, SSE2) runs its loops with AVX2 or AVX-512 where the CPU has them. Every path gives the
// same bytes (no FMA contraction, no reassociation: the kernels are compiled per target from one
// body, core/simd_dispatch.hpp), so the choice only changes the speed. SANSUI_SIMD=sse2|avx2|avx512
// in the environment, or force_simd_level() in a test, picks a lower one (never one the CPU lacks).
#pragma once

#include <optional>
#include <string_view>

namespace sansui::simd {

enum class Level { sse2, avx2, avx512 };

/// The level the kernels run at now: the best the CPU has, or a lower one forced.
Level level();

/// The best level this CPU (and the build's target) has.
Level best_level();

/// Forces `level` (clamped to best_level()), or with nullopt goes back to the environment's
/// SANSUI_SIMD or the best. For tests that compare the bytes of every path.
void force_level(std::optional<Level> level);

std::string_view name(Level level);

}  // namespace sansui::simd
