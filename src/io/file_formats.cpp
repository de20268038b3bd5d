#include "io/file_formats.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/extension.hpp"
#include "io/heightmap_formats.hpp"
#include "io/mesh_formats.hpp"

namespace sansui::io {

const std::vector<FileFormat>& file_formats() {
  using D = FormatData;
  static const std::vector<FileFormat> formats = {
      {"png16", {".png"}, D::heights, true, true, "16-bit", &detail::png16_driver},
      {"raw16", {".raw"}, D::heights, true, true, "16-bit LE", &detail::raw16_driver},
      {"r16", {".r16"}, D::heights, true, true, "16-bit LE", &detail::r16_driver},
      {"r32", {".r32"}, D::heights, true, true, "float32 LE", &detail::r32_driver},
      {"geotiff", {".tif", ".tiff"}, D::heights, true, true, "GeoTIFF float32", &detail::geotiff_driver},
      // Read through GDAL: the DEM formats GIS tools write (ESRI ASCII grid, SRTM HGT, ERDAS
      // IMAGINE, VRT mosaics, BIL/FLT, Surfer grids, PCRaster, USGS DEM).
      {"gdal",
       {".asc", ".hgt", ".img", ".vrt", ".bil", ".flt", ".grd", ".dem", ".map", ".xyz", ".ter"},
       D::heights,
       true,
       false,
       "GDAL raster",
       &detail::gdal_driver},
      {"obj", {".obj"}, D::mesh, true, true, "Wavefront", nullptr, &detail::obj_driver},
      {"glb", {".glb"}, D::mesh, true, true, "binary glTF", nullptr, &detail::glb_driver},
      {"gltf", {".gltf"}, D::mesh, true, false, "glTF", nullptr, &detail::gltf_driver},
      {"png8", {".png"}, D::image, false, true, "8-bit RGBA"},
      {"geojson", {".geojson", ".json"}, D::vector, true, true, "GeoJSON"},
      {"svg", {".svg"}, D::vector, true, true, "SVG"},
      {"csv", {".csv"}, D::table, true, true, "comma-separated"},
      {"text", {".txt"}, D::table, true, false, "number pairs"},
      {"json", {".json"}, D::table, true, true, "JSON"},
      {"volume_r32", {".r32"}, D::volume, false, true, "float32 LE planes"},
  };
  return formats;
}

const FileFormat& file_format_named(std::string_view name) {
  for (const FileFormat& format : file_formats())
    if (format.name == name) return format;
  throw std::logic_error(fmt::format("no file format is named {}", name));
}

std::vector<std::string> extensions_of(std::initializer_list<std::string_view> names) {
  std::vector<std::string> extensions;
  for (std::string_view name : names)
    for (std::string_view extension : file_format_named(name).extensions) extensions.emplace_back(extension);
  return extensions;
}

namespace {

bool serves(const FileFormat& format, FormatData data, Access access) {
  return format.data == data && (access == Access::read ? format.reads : format.writes);
}

}  // namespace

const FileFormat* file_format_for(const std::filesystem::path& path, FormatData data, Access access) {
  const std::string extension = lower_extension(path);
  for (const FileFormat& format : file_formats())
    if (serves(format, data, access))
      for (std::string_view candidate : format.extensions)
        if (candidate == extension) return &format;
  return nullptr;
}

std::vector<std::string> format_extensions(FormatData data, Access access) {
  std::vector<std::string> extensions;
  for (const FileFormat& format : file_formats())
    if (serves(format, data, access))
      for (std::string_view extension : format.extensions) extensions.emplace_back(extension);
  return extensions;
}

std::string format_extension_list(FormatData data, Access access) {
  return fmt::format("{}", fmt::join(format_extensions(data, access), " "));
}

std::string format_help(FormatData data, Access access) {
  std::vector<std::string> parts;
  for (const FileFormat& format : file_formats())
    if (serves(format, data, access)) parts.push_back(fmt::format("{} ({})", fmt::join(format.extensions, " "), format.label));
  return fmt::format("{}", fmt::join(parts, " "));
}

}  // namespace sansui::io
