// A limit on how deeply a TOML file from outside nests, checked on its text before toml++ parses
// it. toml++ limits arrays and inline tables (256 deep) but not dotted keys or table headers:
// `a.a.a...a = 1` or `[a.a...a]` 100,000 deep builds a chain of tables whose parse, walk and
// destruction recurse once per level and overflow the stack (a crash, exit 139).
#pragma once

#include <string_view>

namespace sansui {

/// The deepest nesting a TOML file may have: table header parts, dotted key parts, arrays and
/// inline tables added along one path. Sansui's own files need 5 ([[camera]] name, render.fog.x).
inline constexpr int max_toml_depth = 64;

/// The deepest nesting of `text` read as TOML, stopping early once past `limit`; `line` gets the
/// 1-based line where it went past. Text that is not valid TOML gives some depth (toml++ then
/// reports the error): the scan only needs to be right for files toml++ would accept.
int toml_nesting_depth(std::string_view text, int limit, int* line = nullptr);

/// Throws InputError "SOURCE:LINE: tables, arrays and dotted keys nest more than 64 deep: ..."
/// if `text` nests deeper than max_toml_depth, and "SOURCE:LINE: not valid TOML: ..." for a
/// character that is not ASCII where TOML forbids it or toml++ 3.3 mishandles it (see the .cpp).
/// Call it before toml::parse of any outside file.
void check_toml_nesting(std::string_view text, std::string_view source);

}  // namespace sansui
