// Whole text files: reading one for a parser, and writing one atomically with its sidecar.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sansui::io {

/// The contents of a file. Throws InputError naming it if it is missing or unreadable, or
/// larger than `max_bytes`. The string has at least `spare_bytes` of capacity past its end (for
/// parsers that read past it: parse_contour_map).
std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes = std::size_t(1) << 30, std::size_t spare_bytes = 0);

/// Calls `block(data, size)` on a file's bytes in order, a block at a time, after the same
/// checks as read_text_file (a regular file: never a device or FIFO, which would never end or
/// block forever). For hashing an input of any size without holding it.
void read_file_blocks(const std::filesystem::path& path, const std::function<void(const char* data, std::size_t size)>& block);

/// Writes `text` atomically; with `provenance`, the sidecar NAME.EXT.json (kind `kind`) beside
/// it, both or neither. Throws InputError.
void write_text_file(const std::filesystem::path& path, std::string_view text, std::string_view kind,
                     const std::optional<nlohmann::json>& provenance = std::nullopt);

}  // namespace sansui::io
