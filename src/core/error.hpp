// The library's user-facing error: bad input (a parameter out of range, an unreadable or corrupt
// file). It carries a one-line message naming the value and what is allowed. The library never
// exits or prints; apps/ turn this into "sansui: <message>" and exit code 2.
// Programmer mistakes are asserts, not InputError.
#pragma once

#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace sansui {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(without_nul(message)) {}

  /// `message` with each NUL byte written as \x00. what() is a C string, and a NUL quoted from the
  /// input (a file name "a\0b") would end it there, cutting off the rest of the message (a fuzz
  /// finding: Python raised "cannot read a").
  static std::string without_nul(const std::string& message) {
    if (message.find('\0') == std::string::npos) return message;
    std::string out;
    for (const char c : message) out += c == '\0' ? std::string("\\x00") : std::string(1, c);
    return out;
  }
};

/// Thrown when a Context's cancel flag is raised during long work.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

/// Throws InputError with a formatted message.
template <class... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw InputError(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace sansui
