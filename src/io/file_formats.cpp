#include "io/file_formats.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/extension.hpp"

namespace sansui::io {

const std::vector<FileFormat>& file_formats() {
  using D = FormatData;
  static const std::vector<FileFormat> formats = {
      {"png16", {".png"}, D::heights, true, true, "16-bit"},
      {"raw16", {".raw"}, D::heights, true, true, "16-bit LE"},
      {"r16", {".r16"}, D::heights, true, true, "16-bit LE"},
      {"r32", {".r32"}, D::heights, true, true, "float32 LE"},
      {"geotiff", {".tif", ".tiff"}, D::heights, true, true, "GeoTIFF float32"},
      {"obj", {".obj"}, D::mesh, true, true, "Wavefront"},
      {"glb", {".glb"}, D::mesh, true, true, "binary glTF"},
      {"gltf", {".gltf"}, D::mesh, true, false, "glTF"},
  };
  return formats;
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
