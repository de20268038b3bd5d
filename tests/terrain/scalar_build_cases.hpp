// What the scalar build and the native build both compute, by name, as hashes of their bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/gaussian_row.hpp"
#include "core/random.hpp"
#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {

struct ScalarBuildCase {
  std::string name;
  std::function<std::uint64_t()> hash;
};

inline std::vector<ScalarBuildCase> scalar_build_cases() {
  auto terrain = [](std::uint64_t seed, double hurst, bool additions, terrain::WorldWindow where) {
    return [=] {
      terrain::MidpointParams params;
      params.seed = seed;
      params.hurst = hurst;
      params.additions = additions;
      const Heightfield h = terrain::generate_midpoint(params, where);
      return fnv1a(h.values());
    };
  };
  auto pairs = [] {
    std::vector<float> row(static_cast<std::size_t>(rng::gaussian_pair_room(1000)));
    rng::gaussian_pair_row(rng::stream_key(5, 6), rng::golden_gamma, 1000, 3.0f, row.data());
    return fnv1a(std::span<const float>(row.data(), 2000));
  };
  auto inverse_cdf = [] {
    std::vector<float> row(5000);
    rng::gaussian_row(rng::stream_key(7, 8), 3 * rng::golden_gamma, 5000, 0.5f, row.data());
    return fnv1a(std::span<const float>(row));
  };
  return {{"terrain_1025", terrain(1, 0.8, true, {10, 0, Rect{0, 0, 1025, 1025}})},
          {"terrain_513_h03_no_additions", terrain(2, 0.3, false, {9, 0, Rect{0, 0, 513, 513}})},
          {"tile_of_65537_world", terrain(3, 0.7, true, {16, 0, Rect{30001, 17003, 30001 + 300, 17003 + 257}})},
          {"preview_lod3", terrain(4, 0.8, true, {12, 3, Rect{0, 0, 513, 513}})},
          {"gaussian_pairs", pairs},
          {"gaussian_inverse_cdf", inverse_cdf}};
}

}  // namespace sansui::test
