// The per-node rules of the octree midpoint displacement (Okada et al. 1990, Sec. 2 and 4.1;
// SPEC 2), shared by all four evaluators so that they round identically: which random number a
// node gets, which level and parents it has, and the fixed order of the sums.
//
// A node's Gaussian is a pure function of (seed, x, y, z): the paper's Type III idea (eq. 12,
// "seed the generator with the node's position") made exact with a counter-based hash. The
// coordinates are hashed on the deepest lattice (2^20 per side), so a lattice of fewer levels is
// exactly the deeper one sampled at every 2^k-th point: R is a resolution, not a new field.
#pragma once

#include <bit>
#include <cstdint>

#include "core/random.hpp"
#include "solid/field.hpp"

namespace sansui::solid::rules {

/// The random stream of the field's Gaussians.
inline constexpr std::uint64_t stream = 2;

/// Shift from a lattice of `levels` to the deepest one.
constexpr int world_shift(int levels) {
  return max_levels - levels;
}

/// The counter of node (x, y, z) of a lattice with `levels` levels.
constexpr std::uint64_t counter(int x, int y, int z, int levels) {
  return rng::pack(x, y, z) << world_shift(levels);
}

/// The node's standard normal number g.
inline float gaussian(std::uint64_t key, std::uint64_t counter) {
  return rng::to_gaussian(rng::bits(key, counter));
}

/// Level of one coordinate (paper eq. 8: n = R - b, b the lowest set bit); 0 on the outer faces.
inline int axis_level(int c, int levels) {
  return (c == 0 || c == (1 << levels)) ? 0 : levels - std::countr_zero(static_cast<unsigned>(c));
}

/// The displacement step: mean of the parents plus g * L(n), always in this order.
inline float displace(float mean, float g, float scale) {
  return mean + g * scale;
}

/// Means of the parents. Parents come in pairs (minus, plus) along each active axis, axes in the
/// order x, y, z; the sums are grouped as written (float addition is not associative).
inline float mean2(float a, float b) {
  return (a + b) * 0.5f;
}
inline float mean4(float a, float b, float c, float d) {
  return ((a + b) + (c + d)) * 0.25f;
}
inline float mean6(float a, float b, float c, float d, float e, float f) {
  return (((a + b) + (c + d)) + (e + f)) / 6.0f;
}

}  // namespace sansui::solid::rules
