#include "core/gaussian_row.hpp"

#include <algorithm>
#include <cstring>

#include "core/random.hpp"
#include "core/simd_dispatch.hpp"

namespace sansui::rng {

namespace {

[[gnu::always_inline]] inline void gaussian_row_body(std::uint64_t base, std::uint64_t step, int count, float scale,
                                                     float* __restrict out) {
  // In chunks, so the tail flags stay in L1 and a chunk without tails (most of them when the
  // chunk is short) skips the second pass.
  constexpr int chunk = 256;
  alignas(64) std::uint8_t tail[chunk];
  for (int begin = 0; begin < count; begin += chunk) {
    const int n = std::min(chunk, count - begin);
    const std::uint64_t first = base + static_cast<std::uint64_t>(begin) * step;
    float* __restrict values = out + begin;
    unsigned any = 0;
    std::uint64_t counter = first;  // an induction variable: no 64-bit multiply per value
    for (int t = 0; t < n; ++t, counter += step) {
      const ErfinvArgument a = erfinv_argument(mix64(counter));
      values[t] = scale * gaussian_central(a);
      tail[t] = in_gaussian_tail(a) ? 1 : 0;
      any |= tail[t];
    }
    if (any == 0) continue;
    for (int t = 0; t < n; t += 8) {  // eight flags at a time: tails are rare
      std::uint64_t word = 0;
      std::memcpy(&word, tail + t, static_cast<std::size_t>(std::min(8, n - t)));
      if (word == 0) continue;
      for (int u = t; u < std::min(t + 8, n); ++u)
        if (tail[u] != 0) values[u] = scale * gaussian_tail(erfinv_argument(mix64(first + static_cast<std::uint64_t>(u) * step)));
    }
  }
}

[[gnu::always_inline]] inline void gaussian_pair_row_body(std::uint64_t base, std::uint64_t step, int pairs, float scale,
                                                          float* __restrict out) {
  // In whole groups of 16 pairs: the compiler then emits only the full-width vector loop (a
  // scalar remainder costs as much as a group); callers leave room for the extra pairs. (A last
  // group of 8 where that covers the rest measured no faster.)
  constexpr int group = gaussian_pair_group;
  std::uint64_t counter = base;
  for (int g = 0; g < pairs; g += group, out += 2 * group)
    for (int i = 0; i < group; ++i, counter += step) {
      const GaussianPair value = gaussian_pair(mix64(counter));
      out[2 * i] = scale * value.first;
      out[2 * i + 1] = scale * value.second;
    }
}

}  // namespace

// Each compiled for AVX-512, AVX2 and the baseline, chosen at run time (core/simd_dispatch.hpp):
// the same bytes on every path.
SANSUI_SIMD_KERNEL(gaussian_row, gaussian_row_body, (std::uint64_t base, std::uint64_t step, int count, float scale, float* out),
                   (base, step, count, scale, out))
SANSUI_SIMD_KERNEL(gaussian_pair_row, gaussian_pair_row_body, (std::uint64_t base, std::uint64_t step, int pairs, float scale, float* out),
                   (base, step, pairs, scale, out))

}  // namespace sansui::rng
