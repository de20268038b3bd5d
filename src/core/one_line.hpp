// Messages shown as one line, whatever they quote.
#pragma once

#include <string>
#include <string_view>

#include <fmt/format.h>

namespace sansui {

/// `message` as one line, whatever it quotes (a file name with a newline, a value with control
/// characters): trailing newlines dropped, a newline inside as " / ", other control characters
/// as \xNN. The CLI prints errors so; the Python module raises them so.
inline std::string one_line(std::string_view message) {
  while (!message.empty() && message.back() == '\n') message.remove_suffix(1);
  std::string out;
  out.reserve(message.size());
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n')
      out += " / ";
    else if (byte < 0x20 || byte == 0x7f)
      out += fmt::format("\\x{:02x}", byte);
    else
      out += c;
  }
  return out;
}

}  // namespace sansui
