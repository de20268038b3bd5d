// Text files of number pairs, one per line (seed contours as x,y; hypsometric curves as
// area,height): the two numbers separated by a comma, semicolon or tab (more fields are
// ignored), '#' starts a comment, blank lines are skipped, and one header line ("x,y") may come
// before the first pair. Internal to io/.
#pragma once

#include <string_view>
#include <vector>

namespace sansui::io::detail {

struct NumberPair {
  double first = 0.0, second = 0.0;
  int line = 0;  ///< 1-based, for messages
};

/// Throws InputError "SOURCE:LINE: 'TEXT' is not WHAT" for a line that is not a pair.
std::vector<NumberPair> read_number_pairs(std::string_view text, std::string_view source, std::string_view what);

}  // namespace sansui::io::detail
