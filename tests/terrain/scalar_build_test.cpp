// The terrain's bytes do not depend on the instruction set: a copy of core and terrain compiled
// for plain x86-64 with vectorisation off (sansui_scalar_build) gives the same hashes as this
// binary, built with -march=native (AVX-512 here) and 512-bit vectors in the row kernels.
#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/terrain/scalar_build_cases.hpp"
#include "tests/test_paths.hpp"

namespace sansui::test {
namespace {

TEST(ScalarBuild, GivesTheSameTerrainAndRandomBytesAsThisBuild) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(sansui::test::scalar_build_path, "r"), ::pclose);
  ASSERT_NE(pipe, nullptr);
  std::map<std::string, unsigned long long> scalar;
  std::array<char, 256> name{};
  unsigned long long hash = 0;
  while (std::fscanf(pipe.get(), "%255s %llu", name.data(), &hash) == 2) scalar[name.data()] = hash;
  const auto cases = scalar_build_cases();
  ASSERT_EQ(scalar.size(), cases.size());
  for (const auto& c : cases) EXPECT_EQ(scalar[c.name], c.hash()) << c.name;
}

}  // namespace
}  // namespace sansui::test
