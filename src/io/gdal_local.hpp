// GDAL as a reader of local raster files, nothing more. A DEM comes from strangers: opening one
// must never reach the network, read a file it does not hold in its own folder, hang on a FIFO
// or run code. GDAL would do all of these for a crafted file (a VRT whose source is
// /vsicurl/..., a raw band over /proc/self/environ, a Python pixel function, a sibling .prj that
// is a FIFO), so every file is checked here before GDAL sees its name, and GDAL itself runs with
// its network drivers gone and its network file systems closed. Internal to io/.
#pragma once

#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sansui::io::detail {

/// While one lives, GDAL reads as Sansui wants in this thread: no .aux.xml, no Python pixel
/// functions, no MEM sources, every /vsicurl-based file system (/vsis3/, /vsigs/, ...) closed
/// (thread-local options, restored after: a Python program's own use of GDAL is not changed).
/// The first one registers GDAL's drivers.
class LocalGdal {
 public:
  LocalGdal();
  ~LocalGdal();
  LocalGdal(const LocalGdal&) = delete;
  LocalGdal& operator=(const LocalGdal&) = delete;

 private:
  std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

/// Whether let_gdal_own_the_process() was called.
std::atomic<bool>& owned_by_process();

/// For a program that owns its process (the CLI, once let_gdal_own_the_process() said so): the options above for every thread, PROJ's
/// network off, and every GDAL driver but the local raster ones Sansui reads removed, so that
/// nothing GDAL opens, a VRT's sources included, can reach the network. Once per process.
void restrict_gdal_to_local_rasters();

/// The names of the drivers Sansui reads with, as GDALOpenEx's allowed list (null-ended).
const char* const* local_gdal_drivers();

/// What check_gdal_input found: the files GDAL may read beside the raster (its companions, as
/// GDALOpenEx's sibling list: names in its folder) and every file it refers to.
struct CheckedRaster {
  std::filesystem::path file;                  ///< its real path (links resolved): the name GDAL is given
  std::vector<std::string> siblings;           ///< file names in the raster's folder that belong to it
  std::vector<std::filesystem::path> sources;  ///< files a VRT refers to, each checked the same way
};

/// Checks a raster before GDAL opens it. Throws InputError with one line naming the file or the
/// reference at fault when:
/// - its name is one GDAL would take to the network or to a driver's syntax (/vsi..., URL://,
///   NETCDF:..., an inline <VRTDataset>);
/// - it is not a regular non-empty file, or lies in /proc, /sys or /dev;
/// - a file beside it that GDAL reads with it (the same name with another extension: .prj,
///   .hdr, .aux.xml, .ovr ...) is not a regular file in the same folder;
/// - it is a VRT with a raw band, a warped or pansharpened dataset, pixel-function code, or a
///   source that is not a raster file inside the VRT's own folder (sources are checked in turn,
///   to a depth of 8, cycles refused);
/// - it is an ERDAS IMAGINE file whose samples lie in an external spill file.
CheckedRaster check_gdal_input(const std::filesystem::path& path);

}  // namespace sansui::io::detail
