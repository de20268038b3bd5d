// The libFuzzer targets whose inputs are mutated as structures, not bytes (structured_mutator.hpp):
// `recipe` (a scene file or a sidecar, loaded and checked, not run) and `species_tree` (a species
// file, each species built into its tree mesh). The body is the reader of fuzz_readers.cpp of the
// same name, so FuzzReplay replays their corpus and regressions on every build as it does the
// others'. Built by `scripts/build --sanitize` with clang; `scripts/fuzz NAME MINUTES` runs one.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

#include <unistd.h>

#include "core/memory.hpp"
#include "tests/fuzz/fuzz_readers.hpp"
#include "tests/fuzz/structured_mutator.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

constexpr std::string_view target_name = SANSUI_FUZZ_READER;
constexpr sansui::test::Grammar grammar = target_name == "species_tree" ? sansui::test::Grammar::species : sansui::test::Grammar::recipe;

const std::filesystem::path& scratch() {
  static const std::filesystem::path folder = [] {
    auto path = std::filesystem::temp_directory_path() / ("sansui-fuzz-" SANSUI_FUZZ_READER "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    // Gone when the run ends well (scripts/fuzz --keep-going starts a process per job); kept,
    // with the mutator's last input, when it ends in a crash.
    static const auto* const doomed = new std::filesystem::path(path);  // outlives the statics
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(*doomed, ignored);
    });
    return path;
  }();
  return folder;
}

void write_mutator_input(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path path = scratch() / "mutator-input";
  if (std::FILE* file = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, file);
    std::fclose(file);
  }
}

std::size_t copy_out(const std::string& text, std::uint8_t* data, std::size_t max_size) {
  const std::size_t size = std::min(text.size(), max_size);
  std::memcpy(data, text.data(), size);
  return size;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Below the 512 MB of the reader targets: a recipe is only checked and one tree is small, so
  // anything near the limit is runaway growth that the checks must refuse first.
  sansui::set_memory_limit_bytes(std::size_t{256} << 20);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const sansui::test::FuzzReader& reader = sansui::test::fuzz_reader(target_name);
  (void)sansui::test::read_fuzz_input(reader, std::string_view(reinterpret_cast<const char*>(data), size), scratch());
  return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
  // One time in five, and whenever the input does not parse, libFuzzer's byte mutations: they
  // reach the parsers' own error paths, which structured mutations never do.
  if (seed % 5 != 0) {
    // The mutator parses inputs that libFuzzer's byte mutations made and the target never ran:
    // a crash in the parser here (LLVMFuzzerCustomMutator in its stack) is a finding whose input
    // libFuzzer does not write, so it is kept at /tmp/sansui-fuzz-NAME-PID/mutator-input.
    write_mutator_input(data, size);
    const auto text = sansui::test::mutate_structured(grammar, std::string_view(reinterpret_cast<const char*>(data), size), seed);
    if (text && text->size() <= max_size) return copy_out(*text, data, max_size);
  }
  return LLVMFuzzerMutate(data, size, max_size);
}

extern "C" std::size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* first, std::size_t first_size, const std::uint8_t* second,
                                                 std::size_t second_size, std::uint8_t* out, std::size_t max_out_size, unsigned int seed) {
  const auto text = sansui::test::cross_over_structured(grammar, std::string_view(reinterpret_cast<const char*>(first), first_size),
                                                        std::string_view(reinterpret_cast<const char*>(second), second_size), seed);
  if (text && text->size() <= max_out_size) return copy_out(*text, out, max_out_size);
  // Different formats or unparsable: the first input, cut where it would overflow.
  return copy_out(std::string(reinterpret_cast<const char*>(first), std::min(first_size, max_out_size)), out, max_out_size);
}
