// Through the binary: a negative value (or one past 64 bits) for any option of an unsigned field
// (seeds, counts) is refused with a message naming the value and the allowed range, exit 2, no
// file; it never wraps around to 2^64 - 1.
#include <gtest/gtest.h>

#include "scene/commands.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

struct UnsignedOption {
  std::string command;
  std::string option;   // "--seed"
  std::string allowed;  // what the message must say is allowed: the field's range, or its type's
};

/// Every option of every recipe command whose field is an unsigned whole number.
std::vector<UnsignedOption> unsigned_options() {
  std::vector<UnsignedOption> found;
  for (const auto& spec : scene::command_specs())
    for (const auto& use : spec.sections)
      for (const auto& row : scene::recipe_table().rows) {
        bool positional = false;
        for (const auto& p : spec.positionals) positional = positional || p.key == row.key;
        if (!row.exposed || positional || row.kind != params::Kind::integer || scene::section_of(row.key) != use.section) continue;
        if (!row.limits.type_min || *row.limits.type_min != 0.0) continue;
        const double type_max = row.limits.type_max.value_or(0.0);
        const std::string type_bound = type_max >= 9.2e18 ? "2^63 - 1" : std::to_string(static_cast<long long>(type_max));
        const bool own_range = row.limits.min || row.limits.max;
        found.push_back({spec.name, "--" + use.prefix + row.flag, own_range ? params::allowed_text(row) : "and " + type_bound});
      }
  return found;
}

TEST(UnsignedOptionsCli, NegativeValuesAreRefusedForEveryUnsignedOption) {
  const auto options = unsigned_options();
  ASSERT_GE(options.size(), 5u);  // the seeds of terrain, solid, subdivide, tree and render at least
  TempDir dir("unsigned-options");
  for (const auto& [command, option, allowed] : options) {
    SCOPED_TRACE(command + " " + option);
    const CliResult r = run_cli_line(command + " " + option + " -1 -o out.png", dir.path());
    expect_rejected(r, option + " -1 is not allowed: it must be ", dir.path());
    EXPECT_NE(r.err.find(allowed), std::string::npos) << r.err;
  }
}

TEST(UnsignedOptionsCli, SeedsPastSixtyFourBitsAndBenchSeedsAreRefused) {
  TempDir dir("unsigned-seeds");
  expect_rejected(run_cli_line("terrain --size 33 --seed 18446744073709551615 -o out.png", dir.path()),
                  "--seed '18446744073709551615' is not allowed: it must be a whole number between 0 and 2^63 - 1", dir.path());
  expect_rejected(run_cli_line("terrain --size 33 --seed=-1 -o out.png", dir.path()),
                  "--seed -1 is not allowed: it must be a whole number between 0 and 2^63 - 1", dir.path());
  expect_rejected(run_cli_line("bench solid --seed -1", dir.path()),
                  "--seed -1 is not allowed: it must be a whole number between 0 and 2^63 - 1", dir.path());
}

}  // namespace
}  // namespace sansui::test
