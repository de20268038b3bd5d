// The terrain and the random rows of this build compiled for plain x86-64 with no vectorisation
// (tests/terrain/CMakeLists.txt): prints the hashes of their bytes, which the test suite, built
// for this machine's widest vectors, compares with its own (issue 16: same bytes on every
// instruction set).
#include <cstdio>
#include <vector>

#include "core/gaussian_row.hpp"
#include "core/random.hpp"
#include "terrain/midpoint.hpp"
#include "tests/terrain/scalar_build_cases.hpp"

int main() {
  for (const auto& c : sansui::test::scalar_build_cases())
    std::printf("%s %llu\n", c.name.c_str(), static_cast<unsigned long long>(c.hash()));
  return 0;
}
