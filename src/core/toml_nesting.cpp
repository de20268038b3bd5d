#include "core/toml_nesting.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace sansui {
namespace {

/// One pass over TOML text that keeps just enough state to know how deep each value sits: a
/// table header's parts, a key's parts, and the open arrays and inline tables. Iterative, with a
/// stack that cannot grow past the limit, so the scan itself is safe on any input.
class NestingScan {
 public:
  NestingScan(std::string_view text, int limit) : text_(text), limit_(limit) {}

  /// The deepest nesting met, stopping once it is past the limit or at a character toml++
  /// mishandles (problem()).
  int run() {
    while (at_ < text_.size() && deepest_ <= limit_ && problem_.empty()) step();
    return deepest_;
  }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }

 private:
  enum class Mode { line_start, value, after_value, inline_key };
  struct Open {
    char kind;  // '[' or '{'
    int depth;  // the depth of the array or inline table itself
  };

  void step() {
    const char c = text_[at_];
    if (!ascii(c)) {
      outside_quotes();
    } else if (c == ' ' || c == '\t' || c == '\r') {
      ++at_;
    } else if (c == '\n') {
      ++line_, ++at_;
      if (open_.empty()) mode_ = Mode::line_start;
    } else if (c == '#') {
      while (at_ < text_.size() && text_[at_] != '\n') ++at_;
    } else if (mode_ == Mode::line_start) {
      line_start(c);
    } else if (mode_ == Mode::inline_key) {
      inline_key(c);
    } else if (mode_ == Mode::value) {
      value(c);
    } else {
      after_value(c);
    }
  }

  void line_start(char c) {
    if (c == '[') {  // [a.b] or [[a.b]]: an element of an array of tables is one level deeper
      const bool array = at_ + 1 < text_.size() && text_[at_ + 1] == '[';
      at_ += array ? 2 : 1;
      table_depth_ = key_parts(']') + (array ? 1 : 0);
      while (at_ < text_.size() && text_[at_] == ']') ++at_;
      reach(table_depth_);
      mode_ = Mode::after_value;
      return;
    }
    key_then_value(table_depth_);
  }

  void inline_key(char c) {
    if (c == '}') {  // {} or a trailing comma
      close();
      return;
    }
    key_then_value(open_.back().depth);
  }

  /// `a.b.c = ` inside a table at `depth`: the value is `parts` deeper.
  void key_then_value(int depth) {
    value_depth_ = depth + key_parts('=');
    if (at_ < text_.size() && text_[at_] == '=') ++at_;
    reach(value_depth_);
    mode_ = Mode::value;
  }

  void value(char c) {
    if (c == '[') {
      open_.push_back({'[', value_depth_});
      ++at_;
      reach(++value_depth_);  // the elements
    } else if (c == '{') {
      open_.push_back({'{', value_depth_});
      ++at_;
      mode_ = Mode::inline_key;
    } else if (c == ']' && !open_.empty() && open_.back().kind == '[') {
      close();  // [] or a trailing comma
    } else if (c == '"' || c == '\'') {
      skip_string();
      mode_ = Mode::after_value;
    } else {
      const std::size_t start = at_;
      while (at_ < text_.size() && std::string_view(" \t\r\n#,]}").find(text_[at_]) == std::string_view::npos) {
        if (!ascii(text_[at_])) return outside_quotes();
        ++at_;
      }
      if (at_ == start) ++at_;  // not valid TOML; toml++ says so
      mode_ = Mode::after_value;
    }
  }

  void after_value(char c) {
    if (c == ',' && !open_.empty()) {
      ++at_;
      if (open_.back().kind == '[') {
        mode_ = Mode::value;
        value_depth_ = open_.back().depth + 1;
      } else {
        mode_ = Mode::inline_key;
      }
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      close();
    } else {
      ++at_;  // not valid TOML; toml++ says so
    }
  }

  void close() {
    open_.pop_back();
    ++at_;
    mode_ = Mode::after_value;
  }

  /// The parts of a key up to `end` ('=' or ']'): a.b."c.d" has 3. Stops at the end of the line.
  int key_parts(char end) {
    int parts = 1;
    while (at_ < text_.size() && text_[at_] != end && text_[at_] != '\n') {
      if (text_[at_] == '"' || text_[at_] == '\'') {
        skip_string();
        continue;
      }
      if (text_[at_] == '.') ++parts;
      if (!ascii(text_[at_])) {
        outside_quotes();
        return parts;
      }
      ++at_;
    }
    return parts;
  }

  /// Past a basic ("), literal ('), or multi-line (""" ''') string. A one-line string ends at the
  /// end of its line at the latest.
  void skip_string() {
    const char quote = text_[at_];
    const bool multi_line = text_.substr(at_, 3) == std::string(3, quote);
    at_ += multi_line ? 3 : 1;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        if (!multi_line) return;
        ++line_;
      } else if (c == '\\' && quote == '"') {
        escape(multi_line);
        if (!problem_.empty()) return;
        continue;
      } else if (c == quote && (!multi_line || text_.substr(at_, 3) == std::string(3, quote))) {
        at_ += multi_line ? 3 : 1;
        while (multi_line && at_ < text_.size() && text_[at_] == quote) ++at_;  // """a"""" ends in a quote
        return;
      }
      ++at_;
    }
  }

  /// Past a backslash and what it escapes. toml++ 3.3 asks its Unicode whitespace test about the
  /// character after a backslash, and after a line-ending backslash about every character up to
  /// the next one that is not whitespace; for U+00A1..U+0499 that test reaches
  /// __builtin_unreachable (undefined behaviour: marzer/tomlplusplus#295, fixed upstream after
  /// 3.3). Such a character is refused here: after a backslash it is no escape TOML knows, and
  /// after a line-ending backslash it can be written on the line before.
  void escape(bool multi_line) {
    ++at_;
    if (at_ < text_.size() && !ascii(text_[at_])) {
      problem_ = "a backslash before a character that is not ASCII is not an escape TOML knows";
      return;
    }
    const bool line_ending = multi_line && at_ < text_.size() && std::string_view(" \t\r\n").find(text_[at_]) != std::string_view::npos;
    if (!line_ending) {
      ++at_;
      return;
    }
    while (at_ < text_.size() && std::string_view(" \t\r\n").find(text_[at_]) != std::string_view::npos) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    if (at_ < text_.size() && !ascii(text_[at_]))
      problem_ = "a line-ending backslash followed by a character that is not ASCII: end the line after that character instead";
  }

  /// TOML allows characters that are not ASCII only in strings and comments, and toml++ 3.3 asks
  /// its Unicode whitespace test about them (see escape()): refused here, with the line.
  void outside_quotes() { problem_ = "a character that is not ASCII outside quotes: TOML allows it only in strings and comments"; }

  static bool ascii(char c) { return static_cast<unsigned char>(c) < 0x80; }

  void reach(int depth) { deepest_ = std::max(deepest_, depth); }

  std::string_view text_;
  int limit_;
  std::size_t at_ = 0;
  int line_ = 1, deepest_ = 0;
  Mode mode_ = Mode::line_start;
  int table_depth_ = 0, value_depth_ = 0;
  std::string problem_;
  std::vector<Open> open_;  // each is deeper than the one before, so never more than limit_ + 1
};

}  // namespace

int toml_nesting_depth(std::string_view text, int limit, int* line) {
  NestingScan scan(text, limit);
  const int depth = scan.run();
  if (line != nullptr) *line = scan.line();
  return depth;
}

void check_toml_nesting(std::string_view text, std::string_view source) {
  NestingScan scan(text, max_toml_depth);
  if (scan.run() > max_toml_depth)
    fail("{}:{}: tables, arrays and dotted keys nest more than {} deep: Sansui's files need a few levels", source, scan.line(),
         max_toml_depth);
  if (!scan.problem().empty()) fail("{}:{}: not valid TOML: {}", source, scan.line(), scan.problem());
}

}  // namespace sansui
