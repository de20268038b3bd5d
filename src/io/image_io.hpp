// 8-bit RGBA pictures as PNG (libpng).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/color.hpp"

namespace sansui::io {

/// Writes an RGBA PNG atomically (see atomic_file.hpp). With `provenance`, the sidecar
/// NAME.png.json (kind "picture", width, height, provenance) is written beside it, both or
/// neither. `extra`: more members for that sidecar (a splat map's grid and layers). Throws InputError.
void write_png(const std::filesystem::path& path, const Image& image, const std::optional<nlohmann::json>& provenance = std::nullopt,
               const nlohmann::json& extra = nullptr);

/// The bytes of an RGBA PNG of `image`, in memory (for textures embedded in a .glb).
std::vector<unsigned char> encode_png(const Image& image);

/// Reads any PNG as 8-bit RGBA. Throws InputError naming the file if unreadable or corrupt.
Image read_png(const std::filesystem::path& path);

}  // namespace sansui::io
