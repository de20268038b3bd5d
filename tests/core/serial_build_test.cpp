// The parallel seam's back ends give the same bytes: copies of core, terrain and water whose loops
// run on one thread, in order (sansui_serial_build), or on the browser build's std::thread pool
// (sansui_threads_build), give the same hashes as this binary, whose loops run on oneTBB's
// threads, chunked as its scheduler likes.
#include <array>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/core/serial_build_cases.hpp"
#include "tests/test_paths.hpp"

namespace sansui::test {
namespace {

void expect_the_bytes_of_this_build(const char* other_build) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(other_build, "r"), ::pclose);
  ASSERT_NE(pipe, nullptr);
  std::map<std::string, unsigned long long> other;
  std::array<char, 256> name{};
  unsigned long long hash = 0;
  while (std::fscanf(pipe.get(), "%255s %llu", name.data(), &hash) == 2) other[name.data()] = hash;
  const auto cases = serial_build_cases();
  ASSERT_EQ(other.size(), cases.size());
  for (const auto& c : cases) EXPECT_EQ(other[c.name], c.hash()) << c.name;
}

TEST(SerialBuild, GivesTheSameBytesAsTheTbbBuild) {
  expect_the_bytes_of_this_build(sansui::test::serial_build_path);
}

TEST(ThreadsBuild, GivesTheSameBytesAsTheTbbBuild) {
  expect_the_bytes_of_this_build(sansui::test::threads_build_path);
}

}  // namespace
}  // namespace sansui::test
