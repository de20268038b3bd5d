// Every input kept in tests/fuzz/corpus/NAME, grown/NAME and regressions/NAME (each regression
// once crashed, hung or escaped as an internal error), replayed on every build, GCC Release and
// the sanitizer build alike: through its reader in this process, and through the `sansui`
// binary, where it must end with exit 0, or exit 2 and one line on stderr.
#include <algorithm>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "core/memory.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/fuzz/fuzz_readers.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

const std::filesystem::path fuzz_dir = std::filesystem::path(sansui::test::source_dir) / "tests/fuzz";

std::vector<std::filesystem::path> inputs_of(std::string_view reader, std::string_view kind) {
  std::vector<std::filesystem::path> files;
  const auto folder = fuzz_dir / kind / reader;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// Restores the memory limit a test lowered.
struct MemoryLimit {
  std::size_t saved = memory_limit_bytes();
  explicit MemoryLimit(std::size_t bytes) { set_memory_limit_bytes(bytes); }
  ~MemoryLimit() { set_memory_limit_bytes(saved); }
};

TEST(FuzzReplay, EveryReaderHasAFuzzTargetAndASeedCorpus) {
  const std::string cmake = read_text(fuzz_dir / "fuzz_targets.cmake");
  for (const auto& reader : fuzz_readers()) {
    EXPECT_TRUE(std::regex_search(cmake, std::regex("[\\s(]" + std::string(reader.name) + "[\\s)]"))) << reader.name;
    EXPECT_FALSE(inputs_of(reader.name, "corpus").empty()) << "no seed inputs in tests/fuzz/corpus/" << reader.name;
  }
}

TEST(FuzzReplay, CorpusAndRegressionInputsEndInAResultOrAClearError) {
  const MemoryLimit limit(std::size_t{512} << 20);  // as the fuzz targets run
  TempDir scratch("fuzz-replay");
  for (const auto& reader : fuzz_readers()) {
    int accepted = 0, seeds = 0;
    std::string refusals;
    // corpus: seeds written by hand, mostly valid; grown: what long fuzz runs added (mostly
    // refused, kept for their coverage); regressions: past findings.
    for (const char* kind : {"corpus", "grown", "regressions"})
      for (const auto& file : inputs_of(reader.name, kind)) {
        const std::string bytes = read_text(file);
        bool read = false;
        std::string refusal;
        ASSERT_NO_THROW(read = read_fuzz_input(reader, bytes, scratch.path(), &refusal)) << file;
        if (std::string_view(kind) == "corpus") accepted += read ? 1 : 0, ++seeds;
        if (!read) refusals += "\n" + file.filename().string() + ": " + refusal;
      }
    // The seed corpus is mostly valid files, so that fuzzing starts deep in each reader.
    EXPECT_GE(2 * accepted, seeds) << reader.name << refusals;
  }
}

TEST(FuzzReplay, RegressionInputsThroughTheBinaryEndWithExitZeroOrTwoAndOneLine) {
  TempDir scratch("fuzz-replay-cli");
  int runs = 0;
  for (const auto& reader : fuzz_readers()) {
    if (reader.command.empty()) continue;
    auto files = inputs_of(reader.name, "regressions");
    const auto seeds = inputs_of(reader.name, "corpus");
    files.insert(files.end(), seeds.begin(), seeds.begin() + std::min<std::ptrdiff_t>(2, std::ssize(seeds)));
    for (const auto& file : files) {
      const auto input = write_fuzz_input(reader, read_text(file), scratch.path());
      std::vector<std::string> arguments{"--max-memory", "0.5"};
      for (const auto& argument : reader.command)
        arguments.push_back(argument == "INPUT"        ? input.string()
                            : argument == "OUTPUT.r32" ? (scratch / "out.r32").string()
                            : argument == "OUTPUT.glb" ? (scratch / "out.glb").string()
                            : argument == "OUTPUT.png" ? (scratch / "out.png").string()
                                                       : std::string(argument));
      const CliResult result = run_cli(arguments);
      ++runs;
      EXPECT_TRUE(result.exit_code == 0 || result.exit_code == 2) << file << ": exit " << result.exit_code << "\n" << result.err;
      if (result.exit_code == 2) {
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << file << "\n" << result.err;
      }
      EXPECT_EQ(result.err.find("internal error"), std::string::npos) << file << "\n" << result.err;
    }
  }
  EXPECT_GT(runs, 10);
}

}  // namespace
}  // namespace sansui::test
