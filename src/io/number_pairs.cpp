#include "io/number_pairs.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>

#include "core/error.hpp"

namespace sansui::io::detail {
namespace {

std::optional<double> number_of(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return value;
}

}  // namespace

std::vector<NumberPair> read_number_pairs(std::string_view text, std::string_view source, std::string_view what) {
  std::vector<NumberPair> pairs;
  int line_number = 0;
  bool header_seen = false;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    const auto comma = line.find_first_of(",;\t");
    const auto first = comma == std::string_view::npos ? std::nullopt : number_of(line.substr(0, comma));
    std::string_view rest = comma == std::string_view::npos ? std::string_view{} : line.substr(comma + 1);
    if (const auto more = rest.find_first_of(",;\t"); more != std::string_view::npos) rest = rest.substr(0, more);
    const auto second = number_of(rest);
    if (!first || !second) {
      if (pairs.empty() && !header_seen) {  // a header such as "x,y"
        header_seen = true;
        continue;
      }
      fail("{}:{}: '{}' is not {}", source, line_number, line, what);
    }
    pairs.push_back({*first, *second, line_number});
  }
  return pairs;
}

}  // namespace sansui::io::detail
