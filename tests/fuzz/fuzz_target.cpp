// The libFuzzer target of one reader, chosen at build time (SANSUI_FUZZ_READER, see
// fuzz_targets.cmake): any input must end in a result or an InputError. Built by
// `scripts/build --sanitize` with clang; `scripts/fuzz NAME MINUTES` runs one for long.
#include <cstdint>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "core/memory.hpp"
#include "tests/fuzz/fuzz_readers.hpp"

namespace {

const std::filesystem::path& scratch() {
  static const std::filesystem::path folder = [] {
    auto path = std::filesystem::temp_directory_path() / ("sansui-fuzz-" SANSUI_FUZZ_READER "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Inputs may declare huge sizes: the readers must refuse those above the limit before they
  // allocate, and libFuzzer's own limit (-rss_limit_mb) must never be what stops them.
  sansui::set_memory_limit_bytes(std::size_t{512} << 20);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sansui::test::FuzzReader& reader = sansui::test::fuzz_reader(SANSUI_FUZZ_READER);
  (void)sansui::test::read_fuzz_input(reader, std::string_view(reinterpret_cast<const char*>(data), size), scratch());
  return 0;
}
