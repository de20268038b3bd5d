// 8-bit RGBA pictures as PNG (libpng).
#pragma once

#include <filesystem>

#include "core/color.hpp"

namespace sansui::io {

/// Writes an RGBA PNG atomically (see atomic_file.hpp). Throws InputError.
void write_png(const std::filesystem::path& path, const Image& image);

/// Reads any PNG as 8-bit RGBA. Throws InputError naming the file if unreadable or corrupt.
Image read_png(const std::filesystem::path& path);

}  // namespace sansui::io
