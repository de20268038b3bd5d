// Counter-based random numbers: every value is a pure function of (seed, stream, integer
// coordinates), so results never depend on thread count, evaluation order or tiling.
//
// Bits: SplitMix64 (Steele, Lea, Flood 2014; finaliser "Mix13" by Stafford) applied to
// key + packed_coordinates * golden_gamma, i.e. the SplitMix64 sequence of the stream's key
// indexed by the packed coordinates. Gaussians: the inverse normal CDF of a 23-bit uniform,
// via Giles' single-precision erfinv ("Approximating the erfinv function", GPU Computing Gems,
// 2011) with our own logarithm. Only +, -, *, / and sqrt are used (all correctly rounded in
// IEEE 754), never libm, so the same seed gives the same bytes on every platform and compiler,
// scalar or vectorised. Never use std::*_distribution here: their algorithms differ between
// standard libraries.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace sansui::rng {

inline constexpr std::uint64_t golden_gamma = 0x9E3779B97F4A7C15ull;

/// SplitMix64's finaliser: a bijection of 64-bit words with full avalanche.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// The key of one random stream: independent streams for every (seed, stream) pair.
constexpr std::uint64_t stream_key(std::uint64_t seed, std::uint64_t stream) {
  return mix64(mix64(seed ^ 0x5A4E5355492D3031ull) + stream * 0xD1B54A32D192ED03ull);
}

/// 2-D coordinates packed into one counter: any 32-bit x and y.
constexpr std::uint64_t pack(std::int32_t x, std::int32_t y) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) | (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) << 32);
}
/// 3-D coordinates packed into one counter. [Range: 0 <= x, y, z < 2^21]
constexpr std::uint64_t pack(std::int32_t x, std::int32_t y, std::int32_t z) {
  constexpr std::uint64_t mask = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(x) & mask) | ((static_cast<std::uint64_t>(y) & mask) << 21) |
         ((static_cast<std::uint64_t>(z) & mask) << 42);
}

/// 64 random bits for one counter of one stream.
constexpr std::uint64_t bits(std::uint64_t key, std::uint64_t counter) {
  return mix64(key + counter * golden_gamma);
}

/// Uniform double in [0, 1) from the top 53 bits.
constexpr double to_uniform(std::uint64_t b) {
  return static_cast<double>(b >> 11) * 0x1.0p-53;
}

/// Natural logarithm of a positive normal float, from its exponent and an atanh series
/// (relative error below 1e-7). Written out so that it rounds identically everywhere.
inline float log_positive(float v) {
  std::uint32_t u = std::bit_cast<std::uint32_t>(v);
  int exponent = static_cast<int>(u >> 23) - 127;
  float m = std::bit_cast<float>((u & 0x007FFFFFu) | 0x3F800000u);  // in [1, 2)
  const bool high = m > 1.41421356f;
  m = high ? m * 0.5f : m;  // in [0.707, 1.414): keeps the series short
  exponent += high ? 1 : 0;
  const float s = (m - 1.0f) / (m + 1.0f);
  const float s2 = s * s;
  const float series = 2.0f + s2 * (0.666666667f + s2 * (0.4f + s2 * (0.285714286f + s2 * 0.222222222f)));
  return static_cast<float>(exponent) * 0.693147181f + s * series;
}

/// Standard normal float from 64 random bits: inverse CDF of u = (2k+1)/2^24, k the top 23 bits.
/// Range about [-5.3, 5.3]; mean 0, variance 1.
inline float to_gaussian(std::uint64_t b) {
  const std::int32_t k = static_cast<std::int32_t>(b >> 41);               // 23 bits
  const float x = static_cast<float>(2 * k + 1 - (1 << 23)) * 0x1.0p-23f;  // 2u - 1, exact
  const float one_minus_x_squared = static_cast<float>(2 * k + 1) * static_cast<float>((1 << 24) - 2 * k - 1) * 0x1.0p-46f;
  const float w = -log_positive(one_minus_x_squared);
  // Giles' two polynomials (central region w < 5, tails) evaluated as one Horner loop whose
  // coefficients are selected per value: no branch, so loops over many values vectorise, and
  // each value goes through exactly the operations of its own branch.
  const bool central = w < 5.0f;
  const float v = central ? w - 2.5f : std::sqrt(w) - 3.0f;
  static constexpr float central_coefficients[9] = {2.81022636e-08f, 3.43273939e-07f, -3.5233877e-06f, -4.39150654e-06f, 0.00021858087f,
                                                    -0.00125372503f, -0.00417768164f, 0.246640727f,    1.50140941f};
  static constexpr float tail_coefficients[9] = {-0.000200214257f, 0.000100950558f, 0.00134934322f, -0.00367342844f, 0.00573950773f,
                                                 -0.0076224613f,   0.00943887047f,  1.00167406f,    2.83297682f};
  float p = central ? central_coefficients[0] : tail_coefficients[0];
  for (int i = 1; i < 9; ++i) p = (central ? central_coefficients[i] : tail_coefficients[i]) + p * v;
  return 1.41421356f * (p * x);  // sqrt(2) * erfinv(2u - 1)
}

/// Uniform in [0, 1) at integer coordinates of a stream.
inline double uniform(std::uint64_t seed, std::uint64_t stream, std::int32_t x, std::int32_t y) {
  return to_uniform(bits(stream_key(seed, stream), pack(x, y)));
}
inline double uniform(std::uint64_t seed, std::uint64_t stream, std::int32_t x, std::int32_t y, std::int32_t z) {
  return to_uniform(bits(stream_key(seed, stream), pack(x, y, z)));
}
/// Standard normal at integer coordinates of a stream.
inline float gaussian(std::uint64_t seed, std::uint64_t stream, std::int32_t x, std::int32_t y) {
  return to_gaussian(bits(stream_key(seed, stream), pack(x, y)));
}
inline float gaussian(std::uint64_t seed, std::uint64_t stream, std::int32_t x, std::int32_t y, std::int32_t z) {
  return to_gaussian(bits(stream_key(seed, stream), pack(x, y, z)));
}

}  // namespace sansui::rng
