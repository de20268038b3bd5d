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

  /// The deepest nesting met, stopping once it is past the limit.
  int run() {
    while (at_ < text_.size() && deepest_ <= limit_) step();
    return deepest_;
  }
  int line() const { return line_; }

 private:
  enum class Mode { line_start, value, after_value, inline_key };
  struct Open {
    char kind;  // '[' or '{'
    int depth;  // the depth of the array or inline table itself
  };

  void step() {
    const char c = text_[at_];
    if (c == ' ' || c == '\t' || c == '\r') {
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
      while (at_ < text_.size() && std::string_view(" \t\r\n#,]}").find(text_[at_]) == std::string_view::npos) ++at_;
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
        if (at_ + 1 < text_.size() && text_[at_ + 1] == '\n') ++line_;
        at_ += 2;
        continue;
      } else if (c == quote && (!multi_line || text_.substr(at_, 3) == std::string(3, quote))) {
        at_ += multi_line ? 3 : 1;
        while (multi_line && at_ < text_.size() && text_[at_] == quote) ++at_;  // """a"""" ends in a quote
        return;
      }
      ++at_;
    }
  }

  void reach(int depth) { deepest_ = std::max(deepest_, depth); }

  std::string_view text_;
  int limit_;
  std::size_t at_ = 0;
  int line_ = 1, deepest_ = 0;
  Mode mode_ = Mode::line_start;
  int table_depth_ = 0, value_depth_ = 0;
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
  int line = 0;
  if (toml_nesting_depth(text, max_toml_depth, &line) > max_toml_depth)
    fail("{}:{}: tables, arrays and dotted keys nest more than {} deep: Sansui's files need a few levels", source, line, max_toml_depth);
}

}  // namespace sansui
