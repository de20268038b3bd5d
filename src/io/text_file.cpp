#include "io/text_file.hpp"

#include <algorithm>
#include <system_error>
#include <vector>

#include "core/error.hpp"
#include "io/binary_file.hpp"
#include "io/sidecar.hpp"

namespace sansui::io {

std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes, std::size_t spare_bytes) {
  detail::InputFile file(path);
  if (file.size() > max_bytes) fail("cannot read {}: it has {} bytes, more than the {} allowed", path.string(), file.size(), max_bytes);
  std::string text;
  text.reserve(static_cast<std::size_t>(file.size()) + spare_bytes);
  text.resize(static_cast<std::size_t>(file.size()));
  file.read(text.data(), text.size());
  return text;
}

void read_file_blocks(const std::filesystem::path& path, const std::function<void(const char* data, std::size_t size)>& block) {
  detail::InputFile file(path);
  std::vector<char> buffer(std::size_t{1} << 16);
  for (std::uintmax_t left = file.size(); left > 0;) {
    const auto take = static_cast<std::size_t>(std::min<std::uintmax_t>(left, buffer.size()));
    file.read(buffer.data(), take);
    block(buffer.data(), take);
    left -= take;
  }
}

void write_text_file(const std::filesystem::path& path, std::string_view text, std::string_view kind,
                     const std::optional<nlohmann::json>& provenance) {
  std::optional<nlohmann::json> sidecar;
  if (provenance) {
    sidecar = detail::sidecar_head(kind, path);
    (*sidecar)["provenance"] = *provenance;
  }
  detail::write_with_sidecar(path, sidecar, [&](const std::filesystem::path& temporary) {
    detail::OutputFile file(temporary, path);
    file.write(text);
    file.close();
  });
}

}  // namespace sansui::io
