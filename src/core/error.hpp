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
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
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
