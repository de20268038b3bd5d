// The JSON sidecar NAME.EXT.json written beside every heightmap and mesh: what the file holds
// (size, cell size, origin, sample layout, metres range) and how it was made (provenance).
// Internal to io/; the keys are documented in docs/formats.md.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sansui::io {

/// The version of the sidecar layout, written as "sansui_sidecar". 2: the provenance holds the
/// recipe that rebuilds the file. Sidecars of a newer version are refused.
inline constexpr int sidecar_version = 2;

}  // namespace sansui::io

namespace sansui::io::detail {

/// The start of every sidecar: {"sansui_sidecar": version, "kind": kind, "file": the file name}.
nlohmann::json sidecar_head(std::string_view kind, const std::filesystem::path& path);

/// Writes the file through `write_file` and, if `sidecar` is given, the sidecar beside it, so that
/// both appear or neither: the sidecar's temporary is written first and renamed last (both are
/// atomic, see atomic_file.hpp). Throws InputError.
void write_with_sidecar(const std::filesystem::path& path, const std::optional<nlohmann::json>& sidecar,
                        const std::function<void(const std::filesystem::path& temporary)>& write_file);

/// The sidecar of `path` if there is one. Throws InputError naming it if it is not a JSON object.
std::optional<nlohmann::json> read_sidecar(const std::filesystem::path& path);

/// The number at `pointer` (e.g. "/range_m/min") in a sidecar, nullopt if absent. Throws
/// InputError naming the sidecar if it is there but not a finite number.
std::optional<double> sidecar_number(const nlohmann::json& sidecar, const std::filesystem::path& sidecar_file, std::string_view pointer);

/// The string at `pointer`, nullopt if absent; InputError if it is not a string.
std::optional<std::string> sidecar_string(const nlohmann::json& sidecar, const std::filesystem::path& sidecar_file,
                                          std::string_view pointer);

}  // namespace sansui::io::detail
