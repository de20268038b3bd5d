#include "io/volume_file.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/json_text.hpp"
#include "io/sidecar.hpp"

namespace sansui::io {

static_assert(std::endian::native == std::endian::little, "r32 volumes are little-endian: add byte swapping here");

void write_volume_r32(const std::filesystem::path& path, const Volume& volume, const nlohmann::json& provenance, const Context& context) {
  const int side = volume.side;
  const std::filesystem::path sidecar = sidecar_path(path);
  io::check_writable(sidecar);
  std::vector<float> plane(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
  float low = std::numeric_limits<float>::infinity(), high = -std::numeric_limits<float>::infinity();
  io::write_atomically(path, [&](const std::filesystem::path& temporary) {
    detail::OutputFile file(temporary, path);
    for (int z = 0; z < side; ++z) {
      context.check_cancelled();
      volume.plane(z, plane.data());
      const auto [lo, hi] = std::minmax_element(plane.begin(), plane.end());
      low = std::min(low, *lo);
      high = std::max(high, *hi);
      file.write(plane.data(), plane.size() * sizeof(float));
      context.report("volume", static_cast<double>(z + 1) / side);
    }
    file.close();

    // The keys follow docs/formats.md (sansui_sidecar, kind, file, format, provenance).
    nlohmann::json json = detail::sidecar_head("volume", path);
    json.update(nlohmann::json{
        {"size", {side, side, side}},
        {"axes", "value (x, y, z) is the field at lattice point (x, y, z) of the block [0, 2^R]^3"},
        {"format",
         {{"name", "r32"},
          {"sample_type", "float32"},
          {"byte_order", "little-endian"},
          {"order", "x fastest, then y, then z"},
          {"description", volume.description}}},
        {"data_range", {{"min", low}, {"max", high}}},
        {"provenance", provenance},
    });
    json.update(volume.about);
    // The sidecar goes first, atomically; if it fails, the volume's temporary file is removed.
    io::write_atomically(sidecar, [&](const std::filesystem::path& temporary_sidecar) {
      detail::OutputFile out(temporary_sidecar, sidecar);
      out.write(dump_json(json, 2) + "\n");
      out.close();
    });
  });
}

}  // namespace sansui::io
