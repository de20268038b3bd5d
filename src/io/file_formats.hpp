// Every file format Sansui reads or writes by extension, listed once, as GDAL lists its drivers:
// a name, the extensions, what the file holds, whether it is read, written or both, and its
// driver (the reader and writer, in the format's own file). Kind inference of outputs, the
// extension checks and their messages, the help texts that name extensions and the choice of
// reader and writer all come from this list (formats a reader picks by content are not in it).
// Heights and mesh formats carry their drivers here; pictures, vector files, records and volumes
// are written by their own functions (image_io, geojson_features, map_svg, plant_instances,
// volume_file), and the list names their extensions for output kinds and readers.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace sansui::io {

namespace detail {
struct HeightsDriver;  // io/heightmap_formats.hpp
struct MeshDriver;     // io/mesh_formats.hpp
}  // namespace detail

/// What a file holds: a heightfield, a mesh, a picture, vector geometry (lines, polygons),
/// records (plant instances, x,y points, measures) or a 3-D field.
enum class FormatData { heights, mesh, image, vector, table, volume };

struct FileFormat {
  std::string_view name;                     ///< as sidecars name it: "r32"
  std::vector<std::string_view> extensions;  ///< lower case, with the dot: {".tif", ".tiff"}
  FormatData data = FormatData::heights;
  bool reads = true;
  bool writes = true;
  std::string_view label;                                 ///< a few words for help texts: "16-bit LE"
  const detail::HeightsDriver* heights_driver = nullptr;  ///< for heights formats
  const detail::MeshDriver* mesh_driver = nullptr;        ///< for mesh formats
};

enum class Access { read, write };

/// The list, in the order help texts show it.
const std::vector<FileFormat>& file_formats();
/// The format of that name. Names are the list's own, so an unknown one is a programming error.
const FileFormat& file_format_named(std::string_view name);
/// The extensions of the named formats, in the order given: {".svg", ".png"} for {"svg", "png8"}.
std::vector<std::string> extensions_of(std::initializer_list<std::string_view> names);
/// The format holding `data` whose extension `path` has (any case), or nullptr.
const FileFormat* file_format_for(const std::filesystem::path& path, FormatData data, Access access);
/// The extensions of the formats holding `data` that can be read (or written).
std::vector<std::string> format_extensions(FormatData data, Access access);
/// Those extensions for a message: ".png .raw .r16 .r32 .tif .tiff".
std::string format_extension_list(FormatData data, Access access);
/// Those extensions with their labels for help: ".png (16-bit) .raw (16-bit LE) ...".
std::string format_help(FormatData data, Access access);

}  // namespace sansui::io
