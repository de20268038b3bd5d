// The heights formats' drivers: each format's reader, writer and sidecar description, as
// io/file_formats.cpp registers them (the readers and writers are in png16.cpp, raw16.cpp,
// r32.cpp and geotiff.cpp).
#include <bit>

#include "io/heightmap_formats.hpp"

namespace sansui::io::detail {
namespace {

namespace fs = std::filesystem;

const char* rows(bool south_row_first) {
  return south_row_first ? "south row first (Unity)" : "north row first";
}

nlohmann::json format(const char* name, const char* description, const char* sample_type, const char* byte_order, bool south_row_first) {
  return {{"name", name},
          {"description", description},
          {"sample_type", sample_type},
          {"byte_order", byte_order},
          {"row_order", rows(south_row_first)}};
}

}  // namespace

const HeightsDriver png16_driver{
    true,
    false,
    false,
    [](const fs::path& path, const HeightsRead& r) { return read_png16(path, r.range); },
    [](const fs::path& temporary, const fs::path& target, const Heightfield& h, const HeightsWrite& w) {
      write_png16(temporary, target, h, w.range, w.compression);
    },
    [](bool south, Compression) { return format("png16", "greyscale PNG, 16 bits per sample, no gamma", "uint16", "big-endian", south); }};

const HeightsDriver raw16_driver{true,
                                 true,
                                 false,
                                 [](const fs::path& path, const HeightsRead& r) { return read_raw16(path, r.layout, r.range); },
                                 [](const fs::path& temporary, const fs::path& target, const Heightfield& h, const HeightsWrite& w) {
                                   write_raw16(temporary, target, h, w.range, w.south_row_first);
                                 },
                                 [](bool south, Compression) {
                                   return format("raw16", "headerless 16-bit samples (Unity/Unreal RAW)", "uint16", "little-endian", south);
                                 }};

// The same bytes as raw16, always north row first, whatever a sidecar or the options say.
const HeightsDriver r16_driver{true,
                               false,
                               false,
                               [](const fs::path& path, const HeightsRead& r) {
                                 return read_raw16(path, {r.layout.width, r.layout.height, false}, r.range);
                               },
                               [](const fs::path& temporary, const fs::path& target, const Heightfield& h, const HeightsWrite& w) {
                                 write_raw16(temporary, target, h, w.range, false);
                               },
                               [](bool south, Compression) {
                                 return format("r16", "headerless 16-bit samples (RAW16, Unreal/Terrain3D .r16)", "uint16", "little-endian",
                                               south);
                               }};

const HeightsDriver r32_driver{
    false,
    false,
    false,
    [](const fs::path& path, const HeightsRead& r) { return read_r32(path, r.layout); },
    [](const fs::path& temporary, const fs::path& target, const Heightfield& h, const HeightsWrite&) { write_r32(temporary, target, h); },
    [](bool south, Compression) { return format("r32", "headerless float32 samples in metres", "float32", "little-endian", south); }};

const HeightsDriver geotiff_driver{
    false,
    false,
    true,
    [](const fs::path& path, const HeightsRead& r) { return read_geotiff(path, *r.georeference, r.cell_size_for_degrees_m); },
    [](const fs::path& temporary, const fs::path& target, const Heightfield& h, const HeightsWrite& w) {
      write_geotiff(temporary, target, h, w.compression, *w.crs);
    },
    [](bool south, Compression compression) {
      const char* native_order = std::endian::native == std::endian::little ? "little-endian" : "big-endian";
      return format("geotiff",
                    compression == Compression::none ? "GeoTIFF, one float32 band in metres, uncompressed"
                                                     : "GeoTIFF, one float32 band in metres, Deflate + floating-point predictor",
                    "float32", native_order, south);
    }};

const HeightsDriver gdal_driver{
    false,   false,
    true,    [](const fs::path& path, const HeightsRead& r) { return read_gdal_raster(path, *r.georeference, r.cell_size_for_degrees_m); },
    nullptr, [](bool, Compression) { return nlohmann::json{{"name", "gdal"}, {"description", "a raster GDAL reads"}}; }};

}  // namespace sansui::io::detail
