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

/// The inverse normal CDF of to_gaussian in three parts, so that a loop over many values can
/// take the central branch for all of them and redo the rare tail ones (gaussian_row.hpp).
/// x = 2u - 1 and w = -log(1 - x^2) of u = (2k+1)/2^24, k the top 23 bits of b.
struct ErfinvArgument {
  float x = 0.0f;
  float w = 0.0f;
};
inline ErfinvArgument erfinv_argument(std::uint64_t b) {
  const std::int32_t k = static_cast<std::int32_t>(b >> 41);               // 23 bits
  const float x = static_cast<float>(2 * k + 1 - (1 << 23)) * 0x1.0p-23f;  // 2u - 1, exact
  const float one_minus_x_squared = static_cast<float>(2 * k + 1) * static_cast<float>((1 << 24) - 2 * k - 1) * 0x1.0p-46f;
  return {x, -log_positive(one_minus_x_squared)};
}
/// Giles' central region: w < 5.
inline float gaussian_central(ErfinvArgument a) {
  static constexpr float c[9] = {2.81022636e-08f, 3.43273939e-07f, -3.5233877e-06f, -4.39150654e-06f, 0.00021858087f,
                                 -0.00125372503f, -0.00417768164f, 0.246640727f,    1.50140941f};
  const float v = a.w - 2.5f;
  float p = c[0];
  for (int i = 1; i < 9; ++i) p = c[i] + p * v;
  return 1.41421356f * (p * a.x);  // sqrt(2) * erfinv(2u - 1)
}
/// Giles' tails: w >= 5.
inline float gaussian_tail(ErfinvArgument a) {
  static constexpr float c[9] = {-0.000200214257f, 0.000100950558f, 0.00134934322f, -0.00367342844f, 0.00573950773f,
                                 -0.0076224613f,   0.00943887047f,  1.00167406f,    2.83297682f};
  const float v = std::sqrt(a.w) - 3.0f;
  float p = c[0];
  for (int i = 1; i < 9; ++i) p = c[i] + p * v;
  return 1.41421356f * (p * a.x);
}
inline bool in_gaussian_tail(ErfinvArgument a) {
  return !(a.w < 5.0f);
}

/// Standard normal float from 64 random bits: inverse CDF of u = (2k+1)/2^24, k the top 23 bits.
/// Range about [-5.3, 5.3]; mean 0, variance 1. Each value goes through exactly the operations
/// of its own branch, so loops over many values may compute them in any grouping.
inline float to_gaussian(std::uint64_t b) {
  const ErfinvArgument a = erfinv_argument(b);
  return in_gaussian_tail(a) ? gaussian_tail(a) : gaussian_central(a);
}

/// Two independent standard normal floats from 64 random bits, by the Box-Muller transform:
/// the radius sqrt(-2 ln u) from the top 31 bits (u in (0, 1], so |z| reaches 6.66), the angle
/// from the low 32 (its octant from 3 bits, the angle within it from 24). One logarithm, one
/// square root and one sine-cosine pair make two values, with no branch and no table, so loops
/// over many pairs vectorise fully; only +, -, *, / and sqrt (all correctly rounded), so the
/// bytes are the same everywhere. Sine and cosine on [0, pi/4]: Cephes' sinf/cosf (S. Moshier).
/// (A division-free logarithm and a Newton square root were tried: both were slower.)
struct GaussianPair {
  float first = 0.0f;
  float second = 0.0f;
};
inline GaussianPair gaussian_pair(std::uint64_t b) {
  const auto radius_bits = static_cast<std::int32_t>(b >> 33);  // 31 bits
  const float u = (static_cast<float>(radius_bits) + 0.5f) * 0x1.0p-31f;
  const float r = std::sqrt(-2.0f * log_positive(u));
  const auto angle_bits = static_cast<std::uint32_t>(b);
  const float f = (static_cast<float>(static_cast<std::int32_t>((angle_bits >> 5) & 0xFFFFFFu)) + 0.5f) * 0x1.0p-24f;
  const float phi = f * 0.785398163f;  // (0, pi/4)
  const float z = phi * phi;
  const float sine = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z * phi + phi;
  const float cosine = ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
  // The octant: (cos, sin) of the angle in the first, swapped and signed for the other seven;
  // every octant is as likely, so the angle is uniform on the circle.
  const bool swap = (angle_bits >> 29 & 1u) != 0;
  const float a = swap ? sine : cosine;
  const float c = swap ? cosine : sine;
  const float first = r * a, second = r * c;
  return {(angle_bits >> 30 & 1u) != 0 ? -first : first, (angle_bits >> 31 & 1u) != 0 ? -second : second};
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
