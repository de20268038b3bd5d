// Whole text files: reading one for a parser, and writing one atomically with its sidecar.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sansui::io {

/// The contents of a file. Throws InputError naming it if it is missing or unreadable, or
/// larger than `max_bytes`. The string has at least `spare_bytes` of capacity past its end (for
/// parsers that read past it: parse_contour_map).
std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes = std::size_t(1) << 30, std::size_t spare_bytes = 0);

/// Writes `text` atomically; with `provenance`, the sidecar NAME.EXT.json (kind `kind`) beside
/// it, both or neither. Throws InputError.
void write_text_file(const std::filesystem::path& path, std::string_view text, std::string_view kind,
                     const std::optional<nlohmann::json>& provenance = std::nullopt);

}  // namespace sansui::io
