// write_heightmap / read_heightmap: validation, the sidecar, and dispatch to one file per format
// (png16.cpp, raw16.cpp, r32.cpp, geotiff.cpp).
#include "io/heightmap_io.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <new>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_file.hpp"
#include "io/envi_header.hpp"
#include "io/file_formats.hpp"
#include "io/heightmap_formats.hpp"
#include "io/png_georeference.hpp"
#include "io/sidecar.hpp"
#include "io/square_cells.hpp"

namespace sansui::io {
namespace {

struct DataRange {
  double min_m = 0.0, max_m = 0.0;
};

/// The data's range; throws InputError naming the first NaN or infinite sample.
DataRange finite_range_of(const std::filesystem::path& path, const Heightfield& heights) {
  detail::SampleScan scan;
  for (int y = 0; y < heights.height(); ++y) {
    if (detail::scan_samples(heights.row(y), scan).finite) continue;
    for (int x = 0; x < heights.width(); ++x)
      if (!std::isfinite(heights(x, y)))
        fail("cannot write {}: sample ({}, {}) is {}: heights must be finite numbers", path.string(), x, y, heights(x, y));
  }
  return {scan.min, scan.max};
}

void require_valid_range(const HeightRange& range, std::string_view what) {
  if (!std::isfinite(range.min_m) || !std::isfinite(range.max_m) || !(range.min_m < range.max_m))
    fail("{} {},{} m is not allowed: MIN must be below MAX, both finite", what, range.min_m, range.max_m);
}

/// The 16-bit range to write: the caller's, or the data's. A flat grid gets [h, h + 1 m] so that
/// every sample encodes as level 0 and reads back exactly.
HeightRange range_to_write(const HeightmapWriteOptions& options, const DataRange& data) {
  if (options.range) {
    require_valid_range(*options.range, "height range");
    return *options.range;
  }
  if (data.max_m > data.min_m) return {data.min_m, data.max_m};
  return {data.min_m, data.min_m + std::max(1.0, std::abs(data.min_m) * 1e-6)};
}

nlohmann::json heightmap_sidecar(const std::filesystem::path& path, const Heightfield& heights, const detail::HeightsDriver& driver,
                                 const HeightRange* range, const DataRange& data, const HeightmapWriteOptions& options,
                                 bool south_row_first) {
  nlohmann::json sidecar = {
      {"sansui_sidecar", sidecar_version},
      {"kind", "heightmap"},
      {"file", path.filename().string()},
      {"width", heights.width()},
      {"height", heights.height()},
      {"cell_size_m", heights.cell_size_m},
      {"origin", {{"east_m", heights.origin_x_m}, {"south_m", heights.origin_y_m}}},
      {"axes",
       "sample (i, j) of row j stands at east_m + i * cell_size_m, south_m + j * cell_size_m; "
       "rows run north to south"},
      {"format", driver.describe(south_row_first, options.compression)},
      {"data_range_m", {{"min", data.min_m}, {"max", data.max_m}}},
  };
  if (range)
    sidecar["range_m"] = {{"min", range->min_m},
                          {"max", range->max_m},
                          {"encoding", "metres = min + level * (max - min) / 65535, levels outside were clamped"}};
  if (options.crs && !is_local_metres(*options.crs)) sidecar["crs"] = crs_to_sidecar(*options.crs);  // local metres: no CRS
  if (!options.engine.is_null()) sidecar["engine"] = options.engine;
  sidecar["provenance"] = options.provenance;
  return sidecar;
}

/// What a sidecar says about a heightmap, checked.
struct SidecarFacts {
  std::optional<int> width, height;
  std::optional<double> cell_size_m, origin_x_m, origin_y_m;
  std::optional<HeightRange> range;
  std::optional<bool> south_row_first;
};

std::optional<int> sidecar_size(const nlohmann::json& sidecar, const std::filesystem::path& file, std::string_view key) {
  const auto value = detail::sidecar_number(sidecar, file, key);
  if (!value) return std::nullopt;
  if (*value < 1 || *value > std::numeric_limits<int>::max() || *value != std::floor(*value))
    fail("cannot read sidecar {}: {} is {}, not a positive whole number", file.string(), key, *value);
  return static_cast<int>(*value);
}

SidecarFacts facts_of(const nlohmann::json& sidecar, const std::filesystem::path& file) {
  SidecarFacts facts;
  facts.width = sidecar_size(sidecar, file, "/width");
  facts.height = sidecar_size(sidecar, file, "/height");
  facts.cell_size_m = detail::sidecar_number(sidecar, file, "/cell_size_m");
  if (facts.cell_size_m && !(*facts.cell_size_m > 0.0))
    fail("cannot read sidecar {}: cell_size_m is {}, it must be > 0", file.string(), *facts.cell_size_m);
  facts.origin_x_m = detail::sidecar_number(sidecar, file, "/origin/east_m");
  facts.origin_y_m = detail::sidecar_number(sidecar, file, "/origin/south_m");
  const auto low = detail::sidecar_number(sidecar, file, "/range_m/min");
  const auto high = detail::sidecar_number(sidecar, file, "/range_m/max");
  if (low && high) {
    facts.range = HeightRange{*low, *high};
    require_valid_range(*facts.range, fmt::format("cannot read sidecar {}: range_m", file.string()));
  }
  if (const auto rows = detail::sidecar_string(sidecar, file, "/format/row_order")) facts.south_row_first = rows->starts_with("south");
  return facts;
}

void check_read_options(const HeightmapReadOptions& options) {
  if (options.range) require_valid_range(*options.range, "height range");
  if (options.cell_size_m && !(*options.cell_size_m > 0.0 && std::isfinite(*options.cell_size_m)))
    fail("cell size {} m is not allowed: it must be > 0", *options.cell_size_m);
  if (options.width && *options.width < 1) fail("width {} is not allowed: it must be > 0", *options.width);
  if (options.height && *options.height < 1) fail("height {} is not allowed: it must be > 0", *options.height);
}

/// The sidecar's size, else the option's; both given and different is an error.
int agreed_size(std::optional<int> from_sidecar, std::optional<int> from_options, const std::filesystem::path& path,
                std::string_view what) {
  if (from_sidecar && from_options && *from_sidecar != *from_options)
    fail("cannot read {}: {} {} disagrees with its sidecar {} ({} {})", path.string(), what, *from_options, sidecar_path(path).string(),
         what, *from_sidecar);
  return from_sidecar ? *from_sidecar : from_options.value_or(0);
}

}  // namespace

const FileFormat* heightmap_format_for(const std::filesystem::path& path) {
  return file_format_for(path, FormatData::heights, Access::write);
}

void write_heightmap(const std::filesystem::path& path, const Heightfield& heights, const HeightmapWriteOptions& options) {
  const auto format = heightmap_format_for(path);
  if (!format)
    fail("cannot write {}: unknown extension '{}': heightmaps are {}", path.string(), path.extension().string(),
         format_extension_list(FormatData::heights, Access::write));
  check_writable(path);
  if (heights.empty()) fail("cannot write {}: the heightfield is empty", path.string());
  if (!(heights.cell_size_m > 0.0) || !std::isfinite(heights.cell_size_m))
    fail("cannot write {}: cell size {} m is not allowed: it must be > 0", path.string(), heights.cell_size_m);
  if (!std::isfinite(heights.origin_x_m) || !std::isfinite(heights.origin_y_m))
    fail("cannot write {}: origin {},{} m is not finite", path.string(), heights.origin_x_m, heights.origin_y_m);
  if (options.crs && !options.crs->metric)
    fail("cannot write {}: CRS {} is in {}, not metres; Sansui grids are metres: give a projected CRS in metres", path.string(),
         options.crs->label(), options.crs->unit);
  const DataRange data = finite_range_of(path, heights);
  const detail::HeightsDriver& driver = *format->heights_driver;
  // 16-bit formats store levels of a range (the caller's or the data's); the others metres.
  const HeightRange range = driver.sixteen_bit ? range_to_write(options, data) : HeightRange{};
  const bool south_row_first = driver.unity_rows && options.raw_flip_y;

  std::optional<nlohmann::json> sidecar;
  if (options.sidecar)
    sidecar = heightmap_sidecar(path, heights, driver, driver.sixteen_bit ? &range : nullptr, data, options, south_row_first);
  const detail::HeightsWrite request{range, options.compression, south_row_first, &options.crs};
  const auto write_file_and_sidecar = [&] {
    detail::write_with_sidecar(path, sidecar,
                               [&](const std::filesystem::path& temporary) { driver.write(temporary, path, heights, request); });
  };
  // Raw files get an ENVI header so that GDAL and QGIS open them in place (not for south-first
  // rows, which the header cannot say); it is renamed after the file and its sidecar.
  const bool raw = format->name == "raw16" || format->name == "r16" || format->name == "r32";
  if (format->name == "png16" && options.sidecar) {
    // A world file and GDAL's .aux.xml beside it, so that QGIS places and scales the PNG; each
    // renamed after the next, the PNG and its sidecar first (io/atomic_file.hpp).
    const auto write_then = [](const std::filesystem::path& file, const std::string& text, const std::function<void()>& inner) {
      write_atomically(file, [&](const std::filesystem::path& temporary) {
        detail::OutputFile out(temporary, file);
        out.write(text);
        out.close();
        inner();
      });
    };
    const std::string aux = png_aux_xml_text((range.max_m - range.min_m) / 65535.0, range.min_m, options.crs);
    write_then(png_world_file_path(path), png_world_file_text(heights),
               [&] { write_then(png_aux_xml_path(path), aux, write_file_and_sidecar); });
    return;
  }
  if (!raw || !options.sidecar || south_row_first) {
    write_file_and_sidecar();
    return;
  }
  const EnviLayout layout{driver.sixteen_bit, (range.max_m - range.min_m) / 65535.0, range.min_m};
  const std::string header = envi_header_text(heights, layout, options.crs);
  write_atomically(envi_header_path(path), [&](const std::filesystem::path& temporary) {
    detail::OutputFile file(temporary, envi_header_path(path));
    file.write(header);
    file.close();
    write_file_and_sidecar();
  });
}

Heightfield read_heightmap(const std::filesystem::path& path, const HeightmapReadOptions& options, HeightmapAssumptions* assumed) {
  const auto format = file_format_for(path, FormatData::heights, Access::read);
  if (!format)
    fail("cannot read {}: unknown extension '{}': heightmaps are {}", path.string(), path.extension().string(),
         format_extension_list(FormatData::heights, Access::read));
  check_read_options(options);
  const auto sidecar = detail::read_sidecar(path);
  const SidecarFacts facts = sidecar ? facts_of(*sidecar, sidecar_path(path)) : SidecarFacts{};
  const HeightRange range = options.range ? *options.range : facts.range.value_or(default_16bit_read_range);
  const detail::RawLayout layout{agreed_size(facts.width, options.width, path, "width"),
                                 agreed_size(facts.height, options.height, path, "height"),
                                 facts.south_row_first.value_or(options.raw_flip_y)};

  detail::GeoReference georeference;
  Heightfield heights;
  const detail::HeightsDriver& driver = *format->heights_driver;
  try {
    heights = driver.read(path, {range, layout, options.cell_size_m ? options.cell_size_m : facts.cell_size_m, &georeference});
  } catch (const std::bad_alloc&) {  // a header may promise more samples than memory holds
    fail("cannot read {}: its samples do not fit in memory", path.string());
  }
  // A sidecar left over from an earlier file of the same name must not silently rescale this one.
  if ((facts.width && *facts.width != heights.width()) || (facts.height && *facts.height != heights.height()))
    fail("cannot read {}: its sidecar {} describes {} x {} samples but the file has {} x {}: fix or remove the sidecar", path.string(),
         sidecar_path(path).string(), facts.width.value_or(heights.width()), facts.height.value_or(heights.height()), heights.width(),
         heights.height());

  if (assumed) {
    for (std::string& note : georeference.notes) assumed->notes.push_back(std::move(note));
    const bool sixteen_bit = driver.sixteen_bit;
    assumed->range = sixteen_bit && !options.range && !facts.range;
    assumed->cell_size = !georeference.cell_size_m && !facts.cell_size_m && !options.cell_size_m;
  }
  heights.cell_size_m =
      georeference.cell_size_m.value_or(facts.cell_size_m.value_or(options.cell_size_m.value_or(default_read_cell_size_m)));
  heights.origin_x_m = georeference.origin_x_m.value_or(facts.origin_x_m.value_or(0.0));
  heights.origin_y_m = georeference.origin_y_m.value_or(facts.origin_y_m.value_or(0.0));
  if (georeference.cell_height_m) {
    const double cell_x = heights.cell_size_m, cell_y = *georeference.cell_height_m;
    const int width = heights.width(), height = heights.height();
    heights = detail::resample_to_square_cells(heights, cell_x, cell_y);
    if (assumed)
      assumed->notes.push_back(
          fmt::format("{}: cells of {:g} x {:g} m are not square; resampled bilinearly from {} x {} to {} x {} samples of {:g} m",
                      path.filename().string(), cell_x, cell_y, width, height, heights.width(), heights.height(), heights.cell_size_m));
  }
  return heights;
}

std::optional<Crs> read_heightmap_crs(const std::filesystem::path& path, std::string* note) {
  std::optional<Crs> crs;
  if (const FileFormat* format = file_format_for(path, FormatData::heights, Access::read); format != nullptr && format->name == "gdal") {
    const std::string wkt = detail::read_gdal_raster_crs(path);
    try {
      if (!wkt.empty()) crs = parse_crs(wkt, fmt::format("{}: its CRS", path.filename().string()));
    } catch (const InputError& error) {
      if (note) *note = fmt::format("{}; the outputs carry no CRS (pass --crs to give one)", error.what());
      return std::nullopt;
    }
  } else if (const FileFormat* heights_format = heightmap_format_for(path);
             heights_format != nullptr && heights_format->heights_driver->georeferenced) {
    const detail::GeoReference georeference = detail::read_geotiff_georeference(path);
    if (georeference.geographic) return std::nullopt;
    try {
      if (georeference.epsg != 0)
        crs = crs_from_epsg(georeference.epsg, fmt::format("{}: its GeoKeys' CRS", path.filename().string()));
      else if (!georeference.esri_wkt.empty())
        crs = parse_crs(georeference.esri_wkt, fmt::format("{}: the WKT of its citation", path.filename().string()));
    } catch (const InputError& error) {
      // A CRS PROJ does not know must not stop the heights being used: they are still metres.
      if (note) *note = fmt::format("{}; the outputs carry no CRS (pass --crs to give one)", error.what());
      return std::nullopt;
    }
  }
  if (!crs) {
    if (const auto sidecar = detail::read_sidecar(path); sidecar && sidecar->contains("crs") && !(*sidecar)["crs"].is_null())
      crs = crs_from_sidecar((*sidecar)["crs"], fmt::format("sidecar {}: crs", sidecar_path(path).string()));
  }
  if (crs && is_local_metres(*crs)) return std::nullopt;  // written by Sansui without a CRS
  if (crs && !crs->metric) {
    if (note)
      *note = fmt::format(
          "{}: its CRS {} is in {}; the heights were read in metres, so the outputs carry no CRS (reproject it to a "
          "metric CRS with gdalwarp -t_srs to keep one, or pass --crs)",
          path.filename().string(), crs->label(), crs->unit);
    return std::nullopt;
  }
  return crs;
}

std::string assumptions_note(const std::filesystem::path& path, const HeightmapAssumptions& assumed) {
  if (!assumed.any()) return {};
  std::string what, how;
  if (assumed.range) {
    what = fmt::format("heights {:g} to {:g} m for values 0 to 65535", default_16bit_read_range.min_m, default_16bit_read_range.max_m);
    how = "[file] range = [MIN, MAX] (--range MIN,MAX)";
  }
  if (assumed.cell_size) {
    what += fmt::format("{}cells of {:g} m", what.empty() ? "" : " and ", default_read_cell_size_m);
    how += fmt::format("{}[file] cell = M (--cell M)", how.empty() ? "" : " and ");
  }
  std::error_code ignored;
  const std::string sidecar = sidecar_path(path).filename().string();
  return fmt::format("{} {}: read as {}; set {}", path.filename().string(),
                     std::filesystem::exists(sidecar_path(path), ignored) ? fmt::format("and its sidecar {} do not say its scale", sidecar)
                                                                          : fmt::format("has no sidecar {} saying its scale", sidecar),
                     what, how);
}

namespace detail {

detail::RawLayout resolve_raw_layout(const std::filesystem::path& path, std::uintmax_t file_bytes, int sample_bytes, RawLayout layout) {
  const int bits = 8 * sample_bytes;
  if (file_bytes == 0) fail("cannot read {}: the file is empty", path.string());
  if (file_bytes % static_cast<unsigned>(sample_bytes) != 0)
    fail("cannot read {}: its {} bytes are not a whole number of {}-bit samples (truncated?)", path.string(), file_bytes, bits);
  const std::uintmax_t samples = file_bytes / static_cast<unsigned>(sample_bytes);
  if (layout.width > 0 && layout.height > 0) {
    const std::uintmax_t expected = std::uintmax_t(layout.width) * std::uintmax_t(layout.height);
    if (samples != expected)
      fail("cannot read {}: it has {} bytes but {} x {} {}-bit samples need {} bytes (truncated, or the wrong size)", path.string(),
           file_bytes, layout.width, layout.height, bits, expected * static_cast<unsigned>(sample_bytes));
  } else if (layout.width > 0 || layout.height > 0) {
    const auto known = static_cast<std::uintmax_t>(std::max(layout.width, layout.height));
    if (samples % known != 0) fail("cannot read {}: its {} samples are not a whole number of rows of {}", path.string(), samples, known);
    (layout.width > 0 ? layout.height : layout.width) = static_cast<int>(std::min<std::uintmax_t>(samples / known, 1u << 30));
  } else {
    auto side = static_cast<std::uintmax_t>(std::llround(std::sqrt(static_cast<double>(samples))));
    if (side * side != samples)
      fail("cannot read {}: its {} samples do not make a square; give the width and height (or keep its sidecar {})", path.string(),
           samples, sidecar_path(path).filename().string());
    side = std::min<std::uintmax_t>(side, 1u << 30);
    layout.width = layout.height = static_cast<int>(side);
  }
  require_plausible_size(path, static_cast<std::uint64_t>(layout.width), static_cast<std::uint64_t>(layout.height));
  return layout;
}

void require_plausible_size(const std::filesystem::path& path, std::uint64_t width, std::uint64_t height) {
  constexpr std::uint64_t max_side = std::uint64_t{1} << 21, max_samples = std::uint64_t{1} << 32;
  if (width == 0 || height == 0 || width > max_side || height > max_side || width * height > max_samples)
    fail("cannot read {}: {} x {} samples is not a heightmap Sansui reads (at most {} per side and {} in all)", path.string(), width,
         height, max_side, max_samples);
  // Before the grid is allocated (4 bytes a sample): a header's size is a number from the file.
  check_memory(4.0 * static_cast<double>(width) * static_cast<double>(height),
               fmt::format("cannot read {}: its {} x {} samples", path.string(), width, height));
}

SampleScan& scan_samples(std::span<const float> samples, SampleScan& scan) {
  constexpr std::size_t lanes = 16;
  float low[lanes], high[lanes];
  std::uint32_t non_finite[lanes] = {};
  std::fill_n(low, lanes, scan.min);
  std::fill_n(high, lanes, scan.max);
  std::size_t i = 0;
  for (; i + lanes <= samples.size(); i += lanes)
    for (std::size_t k = 0; k < lanes; ++k) {
      const float value = samples[i + k];
      non_finite[k] |= static_cast<std::uint32_t>((std::bit_cast<std::uint32_t>(value) & 0x7F800000u) == 0x7F800000u);
      low[k] = value < low[k] ? value : low[k];
      high[k] = value > high[k] ? value : high[k];
    }
  for (; i < samples.size(); ++i) {
    non_finite[0] |= static_cast<std::uint32_t>(!std::isfinite(samples[i]));
    low[0] = std::min(low[0], samples[i]);
    high[0] = std::max(high[0], samples[i]);
  }
  for (std::size_t k = 0; k < lanes; ++k) {
    scan.min = std::min(scan.min, low[k]);
    scan.max = std::max(scan.max, high[k]);
    scan.finite &= non_finite[k] == 0;
  }
  return scan;
}

void require_finite(const std::filesystem::path& path, const Heightfield& heights) {
  for (int y = 0; y < heights.height(); ++y) {
    SampleScan scan;
    if (scan_samples(heights.row(y), scan).finite) continue;
    for (int x = 0; x < heights.width(); ++x)
      if (!std::isfinite(heights(x, y)))
        fail("cannot read {}: sample ({}, {}) is {}: heights must be finite numbers", path.string(), x, y, heights(x, y));
  }
}

}  // namespace detail
}  // namespace sansui::io
