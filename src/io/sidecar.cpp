#include "io/sidecar.hpp"

#include <cmath>
#include <fstream>
#include <system_error>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/json_text.hpp"
#include "io/text_file.hpp"

namespace sansui::io {

std::filesystem::path sidecar_path(const std::filesystem::path& path) {
  std::filesystem::path sidecar = path;
  sidecar += ".json";
  return sidecar;
}

namespace detail {

void write_with_sidecar(const std::filesystem::path& path, const std::optional<nlohmann::json>& sidecar,
                        const std::function<void(const std::filesystem::path& temporary)>& write_file) {
  if (!sidecar) {
    write_atomically(path, write_file);
    return;
  }
  const std::filesystem::path sidecar_file = sidecar_path(path);
  write_atomically(sidecar_file, [&](const std::filesystem::path& temporary) {
    OutputFile file(temporary, sidecar_file);
    // replace: a provenance string with invalid UTF-8 (a file name) must not stop the write
    file.write(dump_json(*sidecar, 2) + "\n");
    file.close();
    write_atomically(path, write_file);  // the heightmap or mesh, renamed before the sidecar is
  });
}

nlohmann::json sidecar_head(std::string_view kind, const std::filesystem::path& path) {
  return {{"sansui_sidecar", sidecar_version}, {"kind", kind}, {"file", path.filename().string()}};
}

std::optional<nlohmann::json> read_sidecar(const std::filesystem::path& path) {
  const std::filesystem::path sidecar_file = sidecar_path(path);
  std::error_code error;
  if (!std::filesystem::is_regular_file(sidecar_file, error)) return std::nullopt;
  nlohmann::json sidecar = parse_json(read_text_file(sidecar_file, std::size_t(64) << 20), "cannot read sidecar " + sidecar_file.string());
  if (!sidecar.is_object()) fail("cannot read sidecar {}: it is not a JSON object (fix or remove it)", sidecar_file.string());
  const auto version = sidecar.find("sansui_sidecar");
  if (version != sidecar.end() && version->is_number() && version->get<double>() > sidecar_version)
    fail("cannot read sidecar {}: it was written by a newer sansui (sidecar version {}; this one reads up to {})", sidecar_file.string(),
         version->dump(), sidecar_version);
  return sidecar;
}

std::optional<double> sidecar_number(const nlohmann::json& sidecar, const std::filesystem::path& sidecar_file, std::string_view pointer) {
  const nlohmann::json::json_pointer where{std::string(pointer)};
  if (!sidecar.contains(where)) return std::nullopt;
  const nlohmann::json& value = sidecar.at(where);
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    fail("cannot read sidecar {}: {} is {}, not a finite number", sidecar_file.string(), pointer, value.dump());
  return value.get<double>();
}

std::optional<std::string> sidecar_string(const nlohmann::json& sidecar, const std::filesystem::path& sidecar_file,
                                          std::string_view pointer) {
  const nlohmann::json::json_pointer where{std::string(pointer)};
  if (!sidecar.contains(where)) return std::nullopt;
  const nlohmann::json& value = sidecar.at(where);
  if (!value.is_string()) fail("cannot read sidecar {}: {} is {}, not a string", sidecar_file.string(), pointer, value.dump());
  return value.get<std::string>();
}

}  // namespace detail
}  // namespace sansui::io
