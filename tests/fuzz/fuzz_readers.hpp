// Every reader of outside data, by name, on arbitrary bytes: the body of the libFuzzer targets
// (fuzz_target.cpp, one per reader, built with -DSANSUI_FUZZ=ON and clang) and of the CTest
// replay of tests/fuzz/corpus/ and tests/fuzz/regressions/ on every build. Any input must end
// either in a result or in an InputError: no crash, no hang, no other exception (which the CLI
// would report as an internal error).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sansui::test {

/// One reader: `name` is the fuzz target's (fuzz_NAME) and its corpus folder's name.
struct FuzzReader {
  std::string_view name;
  /// The file name the input is written to (readers that take a path), or empty (text parsers).
  std::string_view file_name;
  /// Reads `bytes`; scratch is a private folder for the files a path-taking reader needs.
  void (*read)(std::string_view bytes, const std::filesystem::path& scratch);
  /// The `sansui` arguments that read the same input from INPUT (the replay through the binary);
  /// empty if no command reads it alone.
  std::vector<std::string_view> command;
};

/// Inputs of readers that take a file and its sidecar hold both: the sidecar's JSON, this line,
/// then the file's bytes. Without the line there is no sidecar.
inline constexpr std::string_view sidecar_separator = "\n--sansui-fuzz-file--\n";

const std::vector<FuzzReader>& fuzz_readers();
const FuzzReader& fuzz_reader(std::string_view name);

/// Runs `reader` on `bytes`: true if read, false if refused with an InputError (its message in
/// `refusal` if given); anything else propagates (a bug).
bool read_fuzz_input(const FuzzReader& reader, std::string_view bytes, const std::filesystem::path& scratch,
                     std::string* refusal = nullptr);

/// Writes `bytes` where the reader's command reads it (scratch/file_name, and the sidecar):
/// returns the path to pass as INPUT.
std::filesystem::path write_fuzz_input(const FuzzReader& reader, std::string_view bytes, const std::filesystem::path& scratch);

/// The argv reader's input: NUL-separated arguments after `sansui`.
std::vector<std::string> split_arguments(std::string_view bytes);

}  // namespace sansui::test
