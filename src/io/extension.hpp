// File-name extensions, the way every Sansui format is chosen.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace sansui::io {

/// The extension of `path` in lower case, with its dot (".png"); empty if none.
inline std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::ranges::transform(extension, extension.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace sansui::io
