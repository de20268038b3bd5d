// GDAL as a reader of local raster files (see gdal_local.hpp).
#include "io/gdal_local.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/binary_file.hpp"
#include "io/gdal_api.hpp"

namespace sansui::io::detail {
namespace {

namespace fs = std::filesystem;

/// The drivers kept: the DEM formats file_formats.cpp routes to GDAL, GeoTIFF (the usual
/// source of a VRT) and MEM (GDAL's own scratch datasets; no file name reaches it, since names
/// of driver syntax are refused). None of them reads a file named inside another file, but VRT,
/// which check_vrt checks, and HFA, whose spill files are refused.
constexpr std::array<const char*, 17> kept_drivers = {"GTiff", "VRT",     "AAIGrid",  "SRTMHGT", "HFA",      "EHdr", "ENVI", "GSAG", "GSBG",
                                                      "GS7BG", "USGSDEM", "PCRaster", "XYZ",     "Terragen", "MEM",  "AIG",  nullptr};

bool is_kept(const char* name) {
  return name != nullptr &&
         std::any_of(kept_drivers.begin(), kept_drivers.end() - 1, [&](const char* n) { return std::strcmp(n, name) == 0; });
}

/// Deepest chain of VRTs referring to VRTs, and most files one raster may refer to in all.
constexpr int deepest_reference = 8;
constexpr std::size_t most_references = std::size_t{1} << 20;
/// Largest VRT read: a mosaic of 100,000 tiles is about 60 MB. [Units: bytes]
constexpr std::uintmax_t largest_vrt = std::uintmax_t{256} << 20;

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool starts_ignoring_case(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && equal_ignoring_case(text.substr(0, prefix.size()), prefix);
}

std::string lower(std::string_view text) {
  std::string out(text);
  std::ranges::transform(out, out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

/// Why GDAL would not take `name` as a plain local file, or nullptr. GDAL reads names as much
/// more than paths: a virtual file system (/vsicurl/, /vsis3/, /vsizip/, /vsistdin/ ...), a URL
/// (its HTTP, WMS and WCS drivers), a driver's syntax (NETCDF:file:var, GTIFF_DIR:1:file,
/// MEM:::DATAPOINTER=..., vrt://...), or a whole dataset written inline (<VRTDataset>).
const char* name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.find('\0') != std::string_view::npos) return "holds a NUL byte";
  const std::size_t first = name.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && name[first] == '<') return "is a dataset written inline, not a file name";
  if (starts_ignoring_case(name, "/vsi")) return "names one of GDAL's virtual file systems (/vsi...): only local files are read";
  if (name.find("://") != std::string_view::npos) return "is a URL: only local files are read";
  // NAME: at the start, NAME a driver-like word: GDAL would hand it to that driver.
  const std::size_t colon = name.find(':');
  if (colon != std::string_view::npos && colon > 0 &&
      std::all_of(name.begin(), name.begin() + static_cast<std::ptrdiff_t>(colon),
                  [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-'; }))
    return "uses a GDAL driver's syntax (NAME:...): only file names are read";
  return nullptr;
}

bool lies_within(const fs::path& file, const fs::path& folder) {
  const fs::path relative = file.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

/// The first bytes of a regular file (opened as open_regular_file opens it: never a FIFO).
std::string head_of(const fs::path& path, std::size_t bytes) {
  InputFile file(path);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(bytes, file.size())), '\0');
  file.read(head.data(), head.size());
  return head;
}

std::string whole_file(const fs::path& path, std::uintmax_t largest, const std::string& what) {
  InputFile file(path);
  if (file.size() > largest) fail("cannot read {}: {} of {} bytes is more than the {} allowed", path.string(), what, file.size(), largest);
  std::string bytes(static_cast<std::size_t>(file.size()), '\0');
  file.read(bytes.data(), bytes.size());
  return bytes;
}

struct XmlFree {
  void operator()(CPLXMLNode* node) const { gdal_api().CPLDestroyXMLNode(node); }
};

/// One check of a raster and everything it refers to: the files met (for cycles and the count)
/// and the folders listed.
class RasterCheck {
 public:
  CheckedRaster run(const fs::path& path) {
    CheckedRaster result;
    result.file = check_raster(path.string(), path, 0, &result.siblings);
    result.sources = std::move(sources_);
    return result;
  }

 private:
  /// Checks one raster file (`given` is how the user or the referring file named it), its
  /// companions and its references; returns its real path.
  fs::path check_raster(const std::string& given, const fs::path& path, int depth, std::vector<std::string>* siblings) {
    if (const char* problem = name_problem(given)) fail("cannot read {}: the name {}", given, problem);
    std::error_code error;
    fs::path real = fs::canonical(path, error);
    if (error) fail("cannot read {}: {}", given, error.message());
    for (const char* system : {"/proc", "/sys", "/dev"})
      if (lies_within(real, system) || real == system)
        fail("cannot read {}: it lies in {} ({}), which holds no rasters", given, system, real.string());
    if (on_path_.contains(real)) fail("cannot read {}: it refers to itself through its sources (a cycle)", given);
    if (++references_ > most_references) fail("cannot read {}: it refers to more than {} files", given, most_references);
    {
      InputFile file(real);  // a regular file, or a one-line refusal naming it
      if (file.size() == 0) fail("cannot read {}: the file is empty", given);
    }
    check_driver(given, real);
    check_companions(given, real, siblings);
    const std::string head = head_of(real, 1024);
    if (head.find("<VRTDataset") != std::string::npos || lower(head).find("<vrtdataset") != std::string::npos) {
      on_path_.insert(real);
      check_vrt(given, real, depth);
      on_path_.erase(real);
    } else if (head.starts_with("EHFA_HEADER_TAG")) {
      check_imagine(given, real);
    }
    return real;
  }

  /// The driver that would open a file must be one Sansui keeps: a local file may still be a
  /// WMS or WCS service description, a STAC catalogue or an MRF index that names data elsewhere.
  /// (A program that owns its process removes the other drivers too: restrict_gdal_to_local_rasters.)
  void check_driver(const std::string& given, const fs::path& real) {
    const GdalApi& gdal = gdal_api();
    GDALDriverH driver = gdal.GDALIdentifyDriverEx(real.c_str(), GDAL_OF_RASTER, nullptr, nullptr);
    if (driver == nullptr) return;  // nothing reads it: the open says so
    const char* name = gdal.GDALGetDriverShortName(driver);
    if (!is_kept(name))
      fail(
          "cannot read {}: it is a {} dataset, which Sansui does not read (it reads DEM files: GeoTIFF, ESRI ASCII, SRTM HGT, "
          "ERDAS IMAGINE, BIL/FLT, ENVI, Surfer, USGS DEM, PCRaster, XYZ, Terragen, and VRTs of them)",
          given, name != nullptr ? name : "unknown");
  }

  /// The files GDAL reads beside `real` (the same name with more after a dot: x.prj, x.hdr,
  /// x.asc.aux.xml, x.ovr, ...) must be regular files (a FIFO would hang the read) inside the
  /// folder; an external overview that is itself a VRT is checked as one.
  void check_companions(const std::string& given, const fs::path& real, std::vector<std::string>* siblings) {
    const fs::path folder = real.parent_path();
    const std::string stem = lower(real.stem().string()) + ".";
    const Listing& names = listing(folder);
    for (auto at = std::ranges::lower_bound(names, stem, {}, &Listing::value_type::first); at != names.end() && at->first.starts_with(stem);
         ++at) {
      const std::string& name = at->second;
      if (name == real.filename().string()) continue;
      const fs::path companion = folder / name;
      struct stat info {};
      if (::lstat(companion.c_str(), &info) != 0) continue;
      if (S_ISLNK(info.st_mode)) {
        std::error_code error;
        const fs::path target = fs::canonical(companion, error);
        if (error || !lies_within(target, folder))
          fail("cannot read {}: the file beside it that GDAL would read with it, {}, is a link out of its folder", given, name);
        if (::stat(companion.c_str(), &info) != 0) continue;
      }
      if (S_ISDIR(info.st_mode)) continue;
      if (!S_ISREG(info.st_mode))
        fail("cannot read {}: the file beside it that GDAL would read with it, {}, is not a regular file (a device, FIFO or socket)", given,
             name);
      if (siblings != nullptr) siblings->push_back(name);
      // External overviews (x.ovr, x.asc.ovr) are opened as any raster: one that is a VRT is checked as one.
      if (lower(name).ends_with(".ovr") && info.st_size > 0 && lower(head_of(companion, 1024)).find("<vrtdataset") != std::string::npos)
        check_raster(name, companion, deepest_reference, nullptr);  // no deeper references allowed
    }
    if (siblings != nullptr) siblings->push_back(real.filename().string());
  }

  /// A folder's entries as (lower-case name, name), sorted: a file's companions are one range.
  using Listing = std::vector<std::pair<std::string, std::string>>;

  const Listing& listing(const fs::path& folder) {
    const auto found = listings_.find(folder);
    if (found != listings_.end()) return found->second;
    Listing& names = listings_[folder];
    std::error_code error;
    for (fs::directory_iterator entry(folder, error), end; !error && entry != end; entry.increment(error)) {
      std::string name = entry->path().filename().string();
      names.emplace_back(lower(name), std::move(name));
    }
    std::ranges::sort(names);
    return names;
  }

  /// A VRT may only gather rasters from inside its own folder: no raw bands (a file's bytes as
  /// samples), no warped or pansharpened datasets, no pixel-function code.
  void check_vrt(const std::string& given, const fs::path& real, int depth) {
    const std::string text = whole_file(real, largest_vrt, "a VRT");
    const std::unique_ptr<CPLXMLNode, XmlFree> tree(gdal_api().CPLParseXMLString(text.c_str()));
    if (!tree) fail("cannot read {}: it is not a valid VRT (its XML does not parse)", given);
    const CPLXMLNode* root = gdal_api().CPLGetXMLNode(tree.get(), "=VRTDataset");
    if (root == nullptr) fail("cannot read {}: it is not a valid VRT (no VRTDataset element)", given);
    walk(given, real, root, depth);
  }

  void walk(const std::string& given, const fs::path& vrt, const CPLXMLNode* node, int depth) {
    for (; node != nullptr; node = node->psNext) {
      if (node->eType != CXT_Element) continue;
      check_element(given, vrt, node, depth);
      walk(given, vrt, node->psChild, depth);
    }
  }

  void check_element(const std::string& given, const fs::path& vrt, const CPLXMLNode* node, int depth) {
    const std::string_view name = node->pszValue;
    const std::string sub_class = gdal_api().CPLGetXMLValue(node, "subClass", "");
    if (equal_ignoring_case(name, "VRTDataset") && !sub_class.empty() && !equal_ignoring_case(sub_class, "VRTDataset"))
      fail("cannot read {}: it is a {} (a VRT that warps or pansharpens): run gdalwarp or gdal_translate on it first", given, sub_class);
    if (equal_ignoring_case(name, "VRTRasterBand") && !sub_class.empty() && !equal_ignoring_case(sub_class, "VRTSourcedRasterBand") &&
        !equal_ignoring_case(sub_class, "VRTDerivedRasterBand")) {
      if (equal_ignoring_case(sub_class, "VRTRawRasterBand"))
        fail(
            "cannot read {}: it has a raw band (VRTRawRasterBand), which reads any file's bytes as samples: convert the data with "
            "gdal_translate first",
            given);
      fail("cannot read {}: its band is a {}, which Sansui does not read", given, sub_class);
    }
    if (equal_ignoring_case(name, "PixelFunctionCode") ||
        (equal_ignoring_case(name, "PixelFunctionLanguage") && !equal_ignoring_case(gdal_api().CPLGetXMLValue(node, nullptr, ""), "C")))
      fail("cannot read {}: it holds pixel-function code, which would run as a program", given);
    const std::string lowered = lower(name);
    if (lowered.ends_with("filename") || lowered == "sourcedataset") check_reference(given, vrt, node, depth);
  }

  /// A file named inside a VRT: relative to the VRT's folder (relativeToVRT="1"), else as GDAL
  /// takes it (absolute, or relative to the working folder); it must be a raster inside the VRT's
  /// folder, checked in turn.
  void check_reference(const std::string& given, const fs::path& vrt, const CPLXMLNode* node, int depth) {
    const std::string name = gdal_api().CPLGetXMLValue(node, nullptr, "");
    if (const char* problem = name_problem(name)) fail("cannot read {}: its source \"{}\" {}", given, name.substr(0, 200), problem);
    const bool relative = std::atoi(gdal_api().CPLGetXMLValue(node, "relativeToVRT", "0")) != 0;
    const fs::path path = relative && fs::path(name).is_relative() ? vrt.parent_path() / name : fs::absolute(fs::path(name));
    std::error_code error;
    const fs::path real = fs::weakly_canonical(path, error);
    if (error || !lies_within(real, vrt.parent_path()))
      fail("cannot read {}: its source \"{}\" lies outside the VRT's folder ({}): a VRT may only gather files beside it", given,
           name.substr(0, 200), vrt.parent_path().string());
    if (depth + 1 > deepest_reference)
      fail("cannot read {}: its sources refer to further VRTs more than {} deep", given, deepest_reference);
    sources_.push_back(check_raster(name, path, depth + 1, nullptr));
  }

  /// An ERDAS IMAGINE file keeps large rasters in a spill file it names (x.ige): refused, since
  /// that name may lead anywhere.
  void check_imagine(const std::string& given, const fs::path& real) {
    InputFile file(real);
    std::array<char, 1 << 16> buffer{};
    constexpr std::string_view marker = "ExternalRasterDMS";
    std::string carry;
    for (std::uintmax_t left = file.size(); left > 0;) {
      const auto take = static_cast<std::size_t>(std::min<std::uintmax_t>(left, buffer.size()));
      file.read(buffer.data(), take);
      left -= take;
      const std::string window = carry + std::string(buffer.data(), take);
      if (window.find(marker) != std::string::npos)
        fail("cannot read {}: its samples lie in a separate spill file (.ige): convert it with gdal_translate -of GTiff first", given);
      carry = window.substr(window.size() - std::min(window.size(), marker.size()));
    }
  }

  std::set<fs::path> on_path_;
  std::map<fs::path, Listing> listings_;
  std::vector<fs::path> sources_;
  std::size_t references_ = 0;
};

/// What Sansui reads with, in its own thread, while it reads (LocalGdal): no .aux.xml read or
/// written, no Python pixel functions, no MEM:::DATAPOINTER sources, and every /vsicurl-based
/// file system (/vsicurl/, /vsis3/, /vsigs/, /vsiaz/, ...) taking only a name no file has, with no
/// request signed (so no credentials are looked for at the cloud metadata service).
constexpr std::array<std::pair<const char*, const char*>, 9> local_options = {{
    {"GDAL_PAM_ENABLED", "NO"},
    {"GDAL_VRT_ENABLE_PYTHON", "NO"},
    {"VRT_ALLOW_MEM_DRIVER", "NO"},
    {"CPL_VSIL_CURL_ALLOWED_FILENAME", "/sansui-reads-local-files-only"},
    {"AWS_NO_SIGN_REQUEST", "YES"},
    {"GS_NO_SIGN_REQUEST", "YES"},
    {"AZURE_NO_SIGN_REQUEST", "YES"},
    {"GDAL_HTTP_TIMEOUT", "1"},
    {"GDAL_HTTP_MAX_RETRY", "0"},
}};

}  // namespace

std::atomic<bool>& owned_by_process() {
  static std::atomic<bool> owned{false};
  return owned;
}

LocalGdal::LocalGdal() {
  const GdalApi& gdal = gdal_api();
  if (owned_by_process().load()) restrict_gdal_to_local_rasters();
  for (const auto& [key, value] : local_options) {
    const char* before = gdal.CPLGetThreadLocalConfigOption(key, nullptr);
    saved_.emplace_back(key, before != nullptr ? std::optional<std::string>(before) : std::nullopt);
    gdal.CPLSetThreadLocalConfigOption(key, value);
  }
  static std::once_flag registered;
  std::call_once(registered, [&] {
    gdal.CPLSetThreadLocalConfigOption("GDAL_DRIVER_PATH", "disable");  // no plugin library loaded by our registration
    gdal.GDALAllRegister();
    gdal.CPLSetThreadLocalConfigOption("GDAL_DRIVER_PATH", nullptr);
  });
}

LocalGdal::~LocalGdal() {
  const GdalApi& gdal = gdal_api();
  for (const auto& [key, before] : saved_) gdal.CPLSetThreadLocalConfigOption(key.c_str(), before ? before->c_str() : nullptr);
}

void restrict_gdal_to_local_rasters() {
  static std::once_flag once;
  std::call_once(once, [] {
    const GdalApi& gdal = gdal_api();
    gdal.CPLSetConfigOption("GDAL_DRIVER_PATH", "disable");
    for (const auto& [key, value] : local_options) gdal.CPLSetConfigOption(key, value);
    gdal.OSRSetPROJEnableNetwork(FALSE);
    gdal.GDALAllRegister();
    // Every driver not kept goes: the network ones (HTTP, WMS, WCS, WFS, DAAS, EEDA, PLMosaic,
    // OGCAPI, STACTA, ...) and the many that read files named inside files (MRF, PDS, ISIS,
    // Sentinel-2, ...). A VRT's sources are opened through this same registry.
    for (int k = gdal.GDALGetDriverCount() - 1; k >= 0; --k) {
      GDALDriverH driver = gdal.GDALGetDriver(k);
      if (is_kept(gdal.GDALGetDriverShortName(driver))) continue;
      gdal.GDALDeregisterDriver(driver);
      gdal.GDALDestroyDriver(driver);
    }
  });
}

const char* const* local_gdal_drivers() {
  return kept_drivers.data();
}

}  // namespace sansui::io::detail

namespace sansui::io {

void let_gdal_own_the_process() {
  detail::owned_by_process().store(true);
}

}  // namespace sansui::io

namespace sansui::io::detail {

CheckedRaster check_gdal_input(const std::filesystem::path& path) {
  return RasterCheck().run(path);
}

}  // namespace sansui::io::detail
