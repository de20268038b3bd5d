// Terrain, flow and erosion of a build whose parallel loops run on another back end
// (SANSUI_PARALLEL_SERIAL or SANSUI_PARALLEL_THREADS, tests/core/CMakeLists.txt): prints the hashes
// of their bytes, which the test suite, built with oneTBB, compares with its own.
#include <cstdio>

#include "tests/core/serial_build_cases.hpp"

int main() {
  for (const auto& c : sansui::test::serial_build_cases())
    std::printf("%s %llu\n", c.name.c_str(), static_cast<unsigned long long>(c.hash()));
  return 0;
}
