// The random streams of contour generation. Every random number is a pure function of
// (seed, stream, level, contour, point index, sub-index) through core/random.hpp, so the same seed
// gives the same contours in any order and with any number of threads.
#pragma once

#include <cstdint>

#include "core/random.hpp"

namespace sansui::contour {

enum class Stream : std::uint64_t { midpoint_sign = 1, midpoint_angle = 2, fourier_phase = 3, roughness = 4, foothills = 5 };

/// The key of one stream for one contour: `level` is its signed level, `contour` a number that
/// tells siblings apart (parent id and island index; see generate.cpp).
inline std::uint64_t contour_key(std::uint64_t seed, Stream stream, int level, std::uint64_t contour) {
  const std::uint64_t where = rng::mix64(rng::pack(level, 0) ^ rng::mix64(contour + 0x636F6E746F7572ull));
  return rng::stream_key(seed, (static_cast<std::uint64_t>(stream) << 56) ^ (where >> 8));
}

/// Uniform in [0, 1) at (index, sub) of a contour's stream.
inline double uniform_at(std::uint64_t key, std::int32_t index, std::int32_t sub) {
  return rng::to_uniform(rng::bits(key, rng::pack(index, sub)));
}

}  // namespace sansui::contour
