// Every vector level the CPU has gives the same bytes (core/simd.hpp): the kernels forced to each
// level in turn make the same random rows and the same terrain.
#include "core/simd.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/gaussian_row.hpp"
#include "terrain/midpoint.hpp"

namespace sansui {
namespace {

std::uint64_t fnv1a(const void* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  return hash;
}

/// The hashes of what the kernels make at the level now in force.
std::vector<std::uint64_t> kernel_hashes() {
  std::vector<std::uint64_t> hashes;
  std::vector<float> row(rng::gaussian_pair_room(1000));
  rng::gaussian_pair_row(0x1234, 0x9E3779B97F4A7C15ull, 1000, 2.5f, row.data());
  hashes.push_back(fnv1a(row.data(), row.size() * sizeof(float)));
  std::vector<float> singles(4099);
  rng::gaussian_row(77, 3, static_cast<int>(singles.size()), 0.5f, singles.data());
  hashes.push_back(fnv1a(singles.data(), singles.size() * sizeof(float)));
  const Heightfield heights = terrain::generate_midpoint(terrain::MidpointParams{}, terrain::WorldWindow{9, 0, Rect{0, 0, 513, 513}});
  hashes.push_back(fnv1a(heights.data(), heights.size() * sizeof(float)));
  return hashes;
}

struct ForcedLevel {
  explicit ForcedLevel(simd::Level level) { simd::force_level(level); }
  ~ForcedLevel() { simd::force_level(std::nullopt); }
};

TEST(Simd, EveryLevelTheCpuHasGivesTheSameBytes) {
  std::vector<std::uint64_t> baseline;
  {
    const ForcedLevel forced(simd::Level::sse2);
    ASSERT_EQ(simd::level(), simd::Level::sse2);
    baseline = kernel_hashes();
  }
  for (const simd::Level level : {simd::Level::avx2, simd::Level::avx512}) {
    if (level > simd::best_level()) continue;
    const ForcedLevel forced(level);
    ASSERT_EQ(simd::level(), level);
    EXPECT_EQ(kernel_hashes(), baseline) << simd::name(level);
  }
  std::printf("best level on this CPU: %s\n", std::string(simd::name(simd::best_level())).c_str());
}

TEST(Simd, ALevelAboveTheCpusIsNeverForced) {
  const ForcedLevel forced(simd::Level::avx512);
  EXPECT_LE(simd::level(), simd::best_level());
}

}  // namespace
}  // namespace sansui
