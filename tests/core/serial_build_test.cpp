// The parallel seam's back ends give the same bytes: a copy of core, terrain and water whose loops
// run on one thread, in order (sansui_serial_build) gives the same hashes as this binary, whose
// loops run on oneTBB's threads, chunked as its scheduler likes.
#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/serial_build_cases.hpp"

namespace sansui::test {
namespace {

TEST(SerialBuild, GivesTheSameBytesAsTheTbbBuild) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(SANSUI_SERIAL_BUILD_PATH, "r"), ::pclose);
  ASSERT_NE(pipe, nullptr);
  std::map<std::string, unsigned long long> serial;
  std::array<char, 256> name{};
  unsigned long long hash = 0;
  while (std::fscanf(pipe.get(), "%255s %llu", name.data(), &hash) == 2) serial[name.data()] = hash;
  const auto cases = serial_build_cases();
  ASSERT_EQ(serial.size(), cases.size());
  for (const auto& c : cases) EXPECT_EQ(serial[c.name], c.hash()) << c.name;
}

}  // namespace
}  // namespace sansui::test
