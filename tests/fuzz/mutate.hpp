// Deterministic mutations of a valid input (bit flips, cuts, repeated and swapped pieces, hostile
// numbers and nesting), for the readers' mutation tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/random.hpp"

namespace sansui::test {

/// The n-th mutation of `text`: the same n gives the same bytes.
inline std::string mutate(const std::string& text, std::uint64_t n) {
  auto pick = [&](int k, std::size_t size) { return static_cast<std::size_t>(rng::uniform(77, n, k, 0) * static_cast<double>(size)); };
  std::string out = text;
  const std::size_t at = out.empty() ? 0 : pick(0, out.size());
  switch (n % 8) {
    case 0:
      if (!out.empty()) out[at] = static_cast<char>(out[at] ^ (1 << pick(1, 8)));
      break;
    case 1:
      out.resize(at);
      break;
    case 2:
      out.insert(at, out.substr(pick(2, out.size()), pick(3, 40)));
      break;
    case 3:
      out.erase(at, pick(4, 30));
      break;
    case 4:
      out.insert(at, std::vector<std::string>{"1e999", "-1", "nan", "9223372036854775808", "\"\"", "[[", "{", "\n[x]\n", "= =", "\xff\xfe",
                                              "[[output]]\n", "-0"}[pick(5, 12)]);
      break;
    case 5:
      out.insert(at, std::string(pick(6, 3000), "[{\"a"[pick(7, 4)]));
      break;
    case 6:
      out.replace(at, 1, 1, "\n=.,[]{}\"'#"[pick(8, 11)]);
      break;
    default:
      for (int k = 0; k < 4; ++k)
        if (!out.empty()) out[pick(10 + k, out.size())] = static_cast<char>(pick(20 + k, 256));
      break;
  }
  return out;
}

}  // namespace sansui::test
