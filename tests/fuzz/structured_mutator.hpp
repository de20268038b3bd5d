// Structure-aware mutations of recipes (scene TOML, sidecar JSON) and species files, for the
// libFuzzer targets `recipe` and `species_tree` (fuzz_structured.cpp) and for the mutation test
// that CI runs with GCC. An input is parsed, changed at the level of keys, values, tables and
// [[array]] entries, guided by the parameter tables (each row's kind, range and choices), and
// written again, so that most results still look like recipes and reach the checks behind the
// parser: a value at or just past its documented bound, a hostile number, another choice, a
// key added, removed or moved, an [[output]], [[shape]], [[camera]] or [[node]] entry repeated
// or dropped, output files that collide, climb out with "..", hold a NUL or name another
// output's sidecar, deeper nesting. Inputs that do not parse are left to byte mutations.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sansui::test {

/// What an input is: a recipe (TOML scene file, or JSON sidecar when it starts with '{') or a
/// species file (TOML [[species]] tables).
enum class Grammar { recipe, species };

/// One structured mutation of `input`, the same for the same `seed`; nullopt when `input` does
/// not parse (the caller mutates its bytes instead). The result may be longer than the input.
std::optional<std::string> mutate_structured(Grammar grammar, std::string_view input, std::uint64_t seed);

/// `first` with a table, key or [[array]] entry of `second` put into it; nullopt when either
/// does not parse or both are of different formats.
std::optional<std::string> cross_over_structured(Grammar grammar, std::string_view first, std::string_view second, std::uint64_t seed);

/// Whether recipe text is a sidecar (JSON) rather than a scene file (TOML): its first non-blank
/// character is '{'.
bool looks_like_json(std::string_view text);

}  // namespace sansui::test
