// The per-point rules of midpoint displacement with additions, shared by the fast generator and
// the plain reference in bench/, so that both round identically. Everything here is what one
// point's value depends on: which random stream, which scale, and the order of the sums.
#pragma once

#include <cstdint>
#include <vector>

#include "core/random.hpp"

namespace sansui::terrain::rules {

/// The two half-steps of a stage and the two things each does.
enum class HalfStep : int { square = 0, diamond = 1 };
enum class Operation : int { create = 0, add = 1 };

/// Stream of random numbers for one operation of one half-step of stage s (1-based).
/// Stream 0 holds the four corners.
constexpr std::uint64_t stream(int stage, HalfStep half, Operation op) {
  return 4u * static_cast<std::uint64_t>(stage) + 2u * static_cast<std::uint64_t>(half) + static_cast<std::uint64_t>(op);
}

/// The random number of the point at stage coordinates (x, y) of one stream: a Box-Muller pair
/// (rng::gaussian_pair) is drawn for every two neighbouring points of a row, at counter
/// (q >> 1, y), and the point takes lane q & 1, where q = x >> 1 numbers the stream's points of
/// the row densely (they all have x of one parity). One draw makes two values, which is what
/// makes the terrain fast.
inline float gaussian(std::uint64_t key, int x, int y) {
  const int q = x >> 1;
  const rng::GaussianPair pair = rng::gaussian_pair(rng::bits(key, rng::pack(q >> 1, y)));
  return (q & 1) != 0 ? pair.second : pair.first;
}
/// The four corners (stage 0, x and y in {0, 1}): both corners of row y from one pair.
inline float corner_gaussian(std::uint64_t key, int x, int y) {
  const rng::GaussianPair pair = rng::gaussian_pair(rng::bits(key, rng::pack(0, y)));
  return x != 0 ? pair.second : pair.first;
}

/// Mean of four neighbours in a fixed order (the float sum is not associative).
inline float mean4(float a, float b, float c, float d) {
  return ((a + b) + (c + d)) * 0.25f;
}
/// Mean of three neighbours, for points on the world's border.
inline float mean3(float a, float b, float c) {
  return (a + b + c) / 3.0f;
}

/// Displacement scales: delta(stage, half) = sigma * r^(2*stage - 1 + half), r = 0.5^(H/2),
/// computed by repeated multiplication as the algorithm is written (and with exact_exp2, so
/// that r is the same everywhere).
std::vector<float> displacement_scales(double sigma_m, double hurst, int stages);
inline float scale_of(const std::vector<float>& scales, int stage, HalfStep half) {
  return scales[static_cast<std::size_t>(2 * stage - 1 + static_cast<int>(half))];
}

}  // namespace sansui::terrain::rules
