// Many Gaussians at once, in the form every stage that draws a row of random numbers from a
// counter-based stream takes. gaussian_row: the same bytes as calling to_gaussian for each, about
// twice as fast: the branch-free central polynomial runs vectorised over all values, and the rare
// tail values (w >= 5, 0.7 %) are redone one by one. gaussian_pair_row: Box-Muller pairs, two
// values per counter, about twice as fast again (the terrain's random numbers).
#pragma once

#include <cstdint>

namespace sansui::rng {

/// out[t] = scale * to_gaussian(mix64(base + t * step)) for t < count.
void gaussian_row(std::uint64_t base, std::uint64_t step, int count, float scale, float* out);

/// Box-Muller pairs (random.hpp gaussian_pair) of the counters base + i * step, i < pairs:
/// out[2i] = scale * first, out[2i + 1] = scale * second. Pairs are made in whole groups of
/// gaussian_pair_group, so `out` must have room for pairs rounded up to a group, times two.
inline constexpr int gaussian_pair_group = 16;
void gaussian_pair_row(std::uint64_t base, std::uint64_t step, int pairs, float scale, float* out);
inline constexpr int gaussian_pair_room(int pairs) {
  return 2 * ((pairs + gaussian_pair_group - 1) / gaussian_pair_group * gaussian_pair_group);
}

}  // namespace sansui::rng
