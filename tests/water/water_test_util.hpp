// Small terrains for the water tests.
#pragma once

#include <cstdint>

#include <gtest/gtest.h>

#include "core/grid.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"
#include "terrain/midpoint.hpp"
#include "test_util.hpp"

namespace sansui::water::test {

/// Random heights on a coarse set of levels (so that flats and ties are common).
inline Heightfield random_heights(int width, int height, std::uint64_t seed, int levels = 8) {
  Heightfield h(width, height, 0.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) h(x, y) = static_cast<float>(static_cast<int>(rng::uniform(seed, 7, x, y) * levels));
  return h;
}

/// A fractal terrain of 2^k + 1 samples with the given cell size.
inline Heightfield midpoint_terrain(int size, double cell_size_m, std::uint64_t seed = 3, double sigma_m = 300.0) {
  terrain::MidpointParams params;
  params.seed = seed;
  params.sigma_m = sigma_m;
  Heightfield h = terrain::generate_midpoint(params, size);
  h.cell_size_m = cell_size_m;
  return h;
}

/// FNV-1a of a grid's samples.
template <class T>
std::uint64_t hash_of(const Grid<T>& grid) {
  return sansui::test::fnv1a(grid.values());
}

/// The hash `run` returns is the same with one thread and with two.
template <class F>
void expect_same_bytes_with_one_and_two_threads(F run) {
  std::uint64_t one = 0, two = 0;
  {
    ThreadLimit limit(1);
    one = run();
  }
  {
    ThreadLimit limit(2);
    two = run();
  }
  EXPECT_EQ(one, two);
}

}  // namespace sansui::water::test
