// The parameter tables of the recipe's own sections, the table of the whole recipe, and which
// source and outputs read each section.
#include <algorithm>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/crs.hpp"
#include "io/extension.hpp"
#include "io/file_formats.hpp"
#include "scene/engines.hpp"
#include "scene/look.hpp"
#include "scene/output_kinds.hpp"
#include "scene/recipe.hpp"
#include "scene/solid_slice.hpp"
#include "scene/sources.hpp"
#include "solid/pictures.hpp"
#include "solid/texture.hpp"

namespace sansui::scene {
namespace {

/// "" when `value` is 2^k + 1 between `low` and `high`, else the rule in words.
std::string power_of_two_plus_one(const params::Value& value, long long low, long long high) {
  const auto n = std::get<std::int64_t>(value);
  const bool ok = n >= low && n <= high && terrain::levels_for_size(n) >= 1;
  return ok ? "" : fmt::format("2^k+1 between {} and {}", low, high);
}

/// 2^k+1, or an Unreal landscape size (a window of the 2^k+1 world just above it).
std::string world_side(const params::Value& value, long long low, long long high) {
  const auto n = std::get<std::int64_t>(value);
  if (n >= low && n <= high && (terrain::levels_for_size(n) >= 1 || is_unreal_landscape_size(n))) return "";
  return fmt::format("2^k+1 or an Unreal landscape size (505, 1009, 2017, 4033, 8129...) between {} and {}", low, high);
}

/// "" for an empty CRS (the input's) or one the outputs can carry, else the rule with PROJ's reason.
std::string crs_rule(const std::string& text) {
  if (text.empty()) return "";
  const std::string problem = io::output_crs_problem(text);
  return problem.empty() ? "" : fmt::format("EPSG:CODE or WKT of a projected CRS in metres that PROJ knows ({})", problem);
}

std::string min_below_max(const params::Value& value) {
  const auto& n = std::get<std::vector<double>>(value);
  return n.size() == 2 && n[0] < n[1] ? "" : "MIN,MAX with MIN below MAX";
}

template <class E>
std::vector<std::pair<std::string, E>> named(std::initializer_list<E> values, std::string_view (*name)(E)) {
  std::vector<std::pair<std::string, E>> names;
  for (E value : values) names.emplace_back(std::string(name(value)), value);
  return names;
}

const std::vector<std::pair<std::string, SourceKind>>& source_choices() {
  static const auto names = [] {
    std::vector<std::pair<std::string, SourceKind>> list;
    for (const detail::SourceEntry& entry : detail::source_entries()) list.emplace_back(std::string(entry.name), entry.kind);
    return list;
  }();
  return names;
}

const std::vector<std::pair<std::string, OutputKind>>& output_choices() {
  static const auto names = [] {
    std::vector<std::pair<std::string, OutputKind>> list;
    for (const OutputKindInfo& info : output_kinds()) list.emplace_back(std::string(info.name), info.kind);
    return list;
  }();
  return names;
}

}  // namespace

std::string_view source_name(SourceKind source) {
  return detail::source_entry(source).name;
}

std::optional<SourceKind> source_from_name(std::string_view name) {
  for (const auto& [text, kind] : source_choices())
    if (text == name) return kind;
  return std::nullopt;
}

std::vector<std::string> source_names() {
  std::vector<std::string> names;
  for (const auto& [text, kind] : source_choices()) names.push_back(text);
  return names;
}

std::string_view output_kind_name(OutputKind kind) {
  return output_kind_info(kind).name;
}

// ---- the recipe's own sections ---------------------------------------------------------------

const params::Table<WorldParams>& parameter_table(const WorldParams*) {
  using P = WorldParams;
  static const auto table =
      params::Table<P>("world", "The world a midpoint source generates, and which window of it (tiles, previews)")
          .add(params::field("size", &P::size)
                   .rule([](const params::Value& v) { return world_side(v, 3, 16385); }, "2^k+1 or an Unreal size, 3 to 16385")
                   .doc("Samples per side of the whole terrain: 2^k+1, or an Unreal landscape size (505, 1009, 2017...), a window "
                        "of the 2^k+1 world just above it"))
          .add(params::field("world_size", &P::world_size)
                   .rule([](const params::Value& v) { return world_side(v, 3, (1 << terrain::max_world_levels) + 1); },
                         "2^k+1 or an Unreal size, 3 to 1048577")
                   .unset("size")
                   .doc("Samples per side of the whole world, for tile and lod"))
          .add(params::field("tile", &P::tile)
                   .at_least(0)
                   .no_unit()
                   .unset("the whole world")
                   .doc("Only tile X,Y of the world (tiles share their border samples)"))
          .add(params::field("tile_size", &P::tile_size)
                   .rule([](const params::Value& v) { return world_side(v, 3, (1 << terrain::max_world_levels) + 1); },
                         "2^m+1 or an Unreal size")
                   .doc("Samples per side of a tile"))
          .add(params::field("tiled", &P::tiled)
                   .doc("Build the whole world tile by tile, tile_size samples each, with erosion and drainage exact across tiles: the "
                        "same bytes as one untiled run, in one process or spread over MPI ranks (mpirun -np N sansui run); grids are "
                        "written as GeoTIFF tiles with a GDAL VRT"))
          .add(params::field("lod", &P::lod)
                   .at_most(20)
                   .at_least(0)
                   .doc("Level of detail: every 2^lod-th sample, exactly the full world's values there"))
          .add(params::field("cell", &P::cell_m)
                   .at_most(1e7)
                   .above(0)
                   .units("m")
                   .doc("Distance between samples of the full-resolution world"))
          .add(params::field("erosion_size", &P::erosion_size)
                   .rule([](const params::Value& v) { return power_of_two_plus_one(v, 3, 16385); }, "2^k+1 between 3 and 16385")
                   .doc("An eroded world in tiles or at a level of detail is eroded whole at most this many samples per side, then "
                        "each tile is refined from it"))
          .add(params::field("erosion_detail", &P::erosion_detail)
                   .at_least(0)
                   .at_most(1)
                   .no_unit()
                   .doc("Size of the fractal detail refined onto an eroded world's tiles, relative to the uneroded terrain's: "
                        "full-size detail is rougher than eroded valleys and sends their rivers astray"))
          .add(params::field("sea_level", &P::sea_level_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .doc("The world's sea level: the stage filter's and the erosion's base level, the sea the picture draws and where "
                        "rivers end; every node and output takes it"))
          .add(params::field("crs", &P::crs)
                   .rule([](const params::Value& v) { return crs_rule(std::get<std::string>(v)); },
                         "EPSG:CODE or WKT of a projected CRS in metres that PROJ knows")
                   .unset("the input's CRS (GeoTIFF keys, GeoJSON crs member, sidecar), else none")
                   .doc("Coordinate reference system of the world and its outputs, EPSG:CODE (e.g. EPSG:2193) or WKT, projected in "
                        "metres, checked with PROJ; assigned to the coordinates, not transformed to"))
          .add(params::field("origin", &P::origin_m)
                   .in(-1e9, 1e9)
                   .units("m")
                   .unset("sample (0, 0) at 0,0")
                   .introduced(4)
                   .doc("Where the world lies: EAST,NORTH of its north-west corner (the GeoTIFF's upper-left corner, what gdalinfo "
                        "prints as Origin) in the CRS's metres; tiles, rivers, lakes, plants and engine notes follow"));
  return table;
}

const params::Table<FileSourceParams>& parameter_table(const FileSourceParams*) {
  using P = FileSourceParams;
  static const auto table = params::Table<P>("file", "A heightmap file as the source")
                                .add(params::path("path", &P::path)
                                         .doc("Heightmap to read, metres: " + io::format_help(io::FormatData::heights, io::Access::read)))
                                .add(params::field("cell", &P::cell_m)
                                         .at_most(1e7)
                                         .above(0)
                                         .units("m")
                                         .unset("the file's or its sidecar's")
                                         .doc("Distance between samples, for files that do not say"))
                                .add(params::field("range", &P::range_m)
                                         .rule(min_below_max, "MIN below MAX")
                                         .units("m")
                                         .unset("the sidecar's")
                                         .doc("Metres that 16-bit values 0 and 65535 stand for, MIN,MAX"));
  return table;
}

const params::Table<ContourSeedParams>& parameter_table(const ContourSeedParams*) {
  using P = ContourSeedParams;
  static const auto table =
      params::Table<P>("contour_seed", "Where the seed contour of a contour mountain comes from, and how its levels are reshaped")
          .add(params::path("file", &P::file)
                   .doc("Seed contour: .geojson (Polygon or closed LineString, metres), .csv (x,y per line) or .svg"))
          .add(params::path("from_dem", &P::from_dem)
                   .doc("Take the seed contour from a DEM (a heightmap Sansui writes, or any DEM GDAL reads: .tif .asc .hgt .vrt ...) at "
                        "`level`, instead of a file"))
          .add(params::field("level", &P::level_m).in(-1e5, 1e5).units("m").unset("none").doc("Elevation of the seed contour in the DEM"))
          .add(params::field("pick", &P::pick_m)
                   .in(-1e8, 1e8)
                   .units("m")
                   .unset("the largest contour")
                   .doc("X,Y: the contour around this point of the DEM plane"))
          .add(params::field("scale", &P::svg_scale).at_most(1e6).above(0).units("m").doc("Metres per SVG unit, for .svg seeds"))
          .add(params::path("hypsometry", &P::hypsometry)
                   .doc("CSV of area,height fractions that reassigns elevations (an altitude-area curve)"))
          .add(params::field("relief", &P::relief_m)
                   .at_most(1e5)
                   .above(0)
                   .units("m")
                   .unset("levels x dz")
                   .doc("Height of the hypsometric curve's top above z0"));
  return table;
}

const params::Table<DemGridParams>& parameter_table(const DemGridParams*) {
  using P = DemGridParams;
  static const auto table = params::Table<P>("dem", "The grid a contour mountain or a subdivided mesh is rasterised onto")
                                .add(params::field("size", &P::size)
                                         .in(2, 65537)
                                         .unset("1025; a seed from a DEM: that DEM's grid")
                                         .doc("Samples along the longer side: up to 65537 for a mesh, 32768 for a contour "
                                              "mountain or a contour map"))
                                .add(params::field("cell", &P::cell_m)
                                         .at_most(1e7)
                                         .above(0)
                                         .units("m")
                                         .alias("--cell")
                                         .unset("from size")
                                         .doc("Distance between samples instead of size (same extent)"))
                                .add(params::field("fill", &P::fill_m)
                                         .in(-1e5, 1e5)
                                         .units("m")
                                         .unset("the lowest contour; the lowest vertex")
                                         .doc("Height outside the shape: outside the outermost contour, where no triangle is"));
  return table;
}

const params::Table<ContourMapSourceParams>& parameter_table(const ContourMapSourceParams*) {
  using P = ContourMapSourceParams;
  static const auto table =
      params::Table<P>("contour_map", "A given contour map (sansui contour-dem): contour lines with elevations to interpolate into a DEM")
          .add(params::path("file", &P::file)
                   .doc("Contour lines: .geojson (LineString, MultiLineString, Polygon, MultiPolygon features, metres), as "
                        "gdal_contour writes them"))
          .add(params::field("elevation_attribute", &P::elevation_attribute)
                   .unset("the first of elev, ELEV, elevation, elevation_m, ELEVATION")
                   .doc("The features' property that holds the elevation in metres"))
          .add(params::field("spot_heights", &P::spot_heights).doc("Also read Point features as spot heights (shape summits and pits)"))
          .add(params::path("grid_from", &P::grid_from)
                   .doc("Take the DEM's grid (size, cell, origin) from this heightmap (.tif .r32 .png with sidecar), to compare "
                        "cell by cell; instead of [dem] size and cell"));
  return table;
}

const params::Table<MeshSourceParams>& parameter_table(const MeshSourceParams*) {
  using P = MeshSourceParams;
  static const auto table =
      params::Table<P>("mesh", "A coarse triangle mesh to subdivide: a file, the pyramid of Fig. 3, or a sketch")
          .add(params::path("file", &P::file).doc("Coarse mesh: .obj (red vertex colours lock vertices) or .glb/.gltf (attribute _LOCK)"))
          .add(params::field("pyramid", &P::pyramid_m)
                   .at_most(1e7)
                   .above(0)
                   .units("m")
                   .unset("none")
                   .doc("The quadrangular pyramid of Fig. 3: base width and apex height, WIDTH,HEIGHT"))
          .add(params::path("sketch", &P::sketch).doc("GeoJSON sketch: ridge/valley LineStrings and spot-height Points with heights"))
          .add(params::field("measure", &P::measure).doc("Measure the fractal dimension of the result (a height variogram)"));
  return table;
}

const params::Table<HeightmapOutputParams>& parameter_table(const HeightmapOutputParams*) {
  using P = HeightmapOutputParams;
  static const auto table =
      params::Table<P>("heightmap_output", "How heightmaps are written")
          .add(params::field("range", &P::range_m)
                   .rule(min_below_max, "MIN below MAX")
                   .units("m")
                   .unset("the data's range; tiles and previews: sea level -/+ 6 sigma")
                   .doc("Metres mapped to 0 and 65535 in 16-bit outputs, MIN,MAX"))
          .add(params::field("raw_flip_y", &P::raw_flip_y).doc("Write .raw rows south first, as Unity's terrain importer reads them"))
          .add(params::choice("compression", &P::compression,
                              {{"none", io::Compression::none}, {"fast", io::Compression::fast}, {"small", io::Compression::small}})
                   .doc("Compression of .png and .tif: fast (Deflate level 1), small (GeoTIFF 6 % and PNG up to 1 % smaller, GeoTIFF 10x "
                        "slower) or none (at disk speed, files 1.6-1.7x larger)"))
          .add(params::choice("engine", &P::engine,
                              {{"none", Engine::none}, {"unreal", Engine::unreal}, {"unity", Engine::unity}, {"godot", Engine::godot}})
                   .doc("Game engine the heightmaps are for: unreal (.r16/.png, landscape sizes 505, 1009...), unity (.raw south row "
                        "first, 2^k+1), godot (.r16/.png, 2^k+1); a note and the sidecar give the importer's scales and location "
                        "(docs/engines.md)"));
  return table;
}

const params::Table<GeoreferenceParams>& parameter_table(const GeoreferenceParams*) {
  using P = GeoreferenceParams;
  static const auto table =
      params::Table<P>("georeference", "The coordinate reference system of the outputs (GeoTIFF keys, GeoJSON crs member, sidecars)")
          .add(params::field("crs", &P::crs)
                   .rule([](const params::Value& v) { return crs_rule(std::get<std::string>(v)); },
                         "EPSG:CODE or WKT of a projected CRS in metres that PROJ knows")
                   .unset("the input's CRS (GeoTIFF keys, GeoJSON crs member, sidecar), else none")
                   .doc("Coordinate reference system of the outputs, EPSG:CODE (e.g. EPSG:2193) or WKT, projected in metres, checked "
                        "with PROJ; assigned to the coordinates, not transformed to"))
          .add(params::field("force_metres", &P::force_metres)
                   .doc("Read a GeoJSON or CSV input in degrees (a geographic crs member, or none and longitude/latitude-sized "
                        "coordinates) as metres anyway, without its CRS; otherwise it is refused"));
  return table;
}

const params::Table<SolidParams>& parameter_table(const SolidParams*) {
  using P = SolidParams;
  static const auto table =
      params::Table<P>("solid", "Solid-texture outputs: the evaluator, the texture, the pictures")
          .add(params::choice("type", &P::type,
                              {{"I", solid::EvaluatorType::type1},
                               {"II", solid::EvaluatorType::type2},
                               {"III", solid::EvaluatorType::type3},
                               {"IV", solid::EvaluatorType::type4}})
                   .doc("Evaluator: I (whole array), II (memo map), III (ancestors only), IV (array to r2, then III); all give the same "
                        "values"))
          .add(params::field("r2", &P::r2)
                   .at_most(30)
                   .in(0, solid::max_levels)
                   .unset("min(6, R)")
                   .doc("Type IV: levels held in the Type I array (at most R)"))
          .add(params::choice("texture", &P::texture, solid::texture_names())
                   .doc("white-marble, green-marble, oak, pine, strata, marble (= white-marble), wood (= oak), or field (D in grey)"))
          .add(params::field("strength", &P::strength)
                   .in(-1e6, 1e6)
                   .unset("the preset's")
                   .units("block per unit of D")
                   .doc("k: how far the field displaces the texture (eq. 7)"))
          .add(params::field("slice_at", &P::slice_at)
                   .rule([](const params::Value& v) { return slice_problem(std::get<std::string>(v)); }, "AXIS=V")
                   .doc("Where the slice picture cuts: AXIS=V, V in lattice units (0..2^R) or a percentage, e.g. z=50%"))
          .add(params::field("picture_size", &P::picture_size)
                   .in(8, solid::max_picture_px)
                   .units("px")
                   .doc("Width and height of the pictures"))
          .add(params::field("reuse", &P::reuse)
                   .doc("Types III/IV keep the previous query's ancestors (false: a fresh memo per query, as the paper)"))
          .add(params::field("memory", &P::memory_mb)
                   .at_most(1e9)
                   .at_least(0)
                   .units("MB")
                   .doc("Memory the field may use; 0: what the machine has available"));
  return table;
}

const params::Table<CompareSetup>& parameter_table(const CompareSetup*) {
  using P = CompareSetup;
  static const auto table =
      params::Table<P>("compare", "A real DEM to compare the heightfield with: hypsometry, slopes, summits, contours, spectra")
          .add(params::path("real", &P::real)
                   .doc("The real DEM (a heightmap Sansui writes, or any DEM GDAL reads: .tif .asc .hgt .vrt ...)"))
          .add(params::path("inside", &P::inside).doc("Only cells inside the seed contour of this GeoJSON (written by a contour source)"))
          .nest("", "", &P::measures, contour::parameter_table(static_cast<const contour::CompareParams*>(nullptr)));
  return table;
}

/// Recipes of version 3 on have one sea level, [world] sea_level; older ones gave it in their
/// [[shape]] steps, [render] and [flow], and are still read so.
template <class S>
void supersede_sea_level(std::vector<params::Param<S>>& rows, std::string_view key) {
  for (auto& row : rows)
    if (row.key == key) row.superseded(3, "[world] sea_level");
}

const params::Table<ShapeStep>& parameter_table(const ShapeStep*) {
  using P = ShapeStep;
  static const auto table =
      params::Table<P>("shape", "A shaping step on the heightfield, in order")
          .add(params::choice("step", &P::step, {{"stage", StepKind::stage}, {"erode", StepKind::erode}})
                   .doc("What the step does: stage (the paper's geomorphic stage filter) or erode (stream power, diffusion, thermal "
                        "and droplet erosion; `stage` is then the erosion time)"))
          .nest("", "", &P::stage, terrain::parameter_table(static_cast<const terrain::StageFilterParams*>(nullptr)))
          .add(params::field("time_from_stage", &P::time_from_stage)
                   .doc("erode: the erosion time from `stage` (young 0.05, mature 0.7, old 1.2, peneplain 2.5 response times); "
                        "false: steps x time_step"))
          .add(params::field("force", &P::force).doc("erode: run even when the erosion is estimated to take longer than ten minutes"));
  static const auto with_erosion = [] {
    params::Table<P> t = table;
    params::Table<water::ErosionChainParams> chain("erosion", "");
    chain.nest("", "", &water::ErosionChainParams::fluvial, params::table_of<water::StreamPowerParams>());
    chain.nest("", "", &water::ErosionChainParams::thermal, params::table_of<water::ThermalParams>());
    chain.nest("", "", &water::ErosionChainParams::droplets, params::table_of<water::DropletParams>());
    chain.add(params::field("keep_detail", &water::ErosionChainParams::keep_detail)
                  .in(0, 2)
                  .no_unit()
                  .doc("How much of the land's fine roughness (wavelengths under 8 cells) its hillslopes keep after erosion: 0 "
                       "smooth, 1 as rough as before")
                  .grouped("erosion"));
    t.nest("", "", &P::erosion, chain);
    // The stage filter's sea level is the erosion's base level too: one key, set once.
    std::vector<params::Param<P>> unique;
    for (auto& row : t.rows)
      if (std::none_of(unique.begin(), unique.end(), [&](const auto& kept) { return kept.key == row.key; })) unique.push_back(row);
    t.rows = std::move(unique);
    supersede_sea_level(t.rows, "sea_level");
    return t;
  }();
  return with_erosion;
}

const params::Table<Output>& parameter_table(const Output*) {
  using P = Output;
  static const auto table =
      params::Table<P>("output", "One output file")
          .add(params::path("file", &P::file).doc("The file to write (its JSON sidecar FILE.json is written beside it)"))
          .add(params::choice("kind", &P::kind, output_choices()).unset(inferred_kinds_text()).doc("What the file holds"))
          .add(params::field("camera", &P::camera).unset("the first camera").doc("Render outputs: the [[camera]] of this name"))
          .add(params::field("node", &P::node).unset("the graph's final node").doc("Recipe graphs: the [[node]] whose heights it writes"));
  return table;
}

const params::Table<ClimateParams>& parameter_table(const ClimateParams*) {
  using P = ClimateParams;
  static const auto table =
      params::Table<P>("climate", "The Köppen climate (Oka et al. 1997, Tables 1 and 4): it derives the palette, tree and snow lines")
          .add(params::choice("koppen", &P::koppen, climate_choices())
                   .alias("--climate")
                   .doc("Köppen class: Af Am Aw (tropical), BW BS (dry), Cs Cw Cfa Cfb Cfc (temperate), Df Dw (boreal), ET EF (polar)"));
  return table;
}

const params::Table<SeasonParams>& parameter_table(const SeasonParams*) {
  using P = SeasonParams;
  static const auto table =
      params::Table<P>("season", "The season: autumn colours, winter snow lines, spring greens")
          .add(params::choice("season", &P::season, season_choices())
                   .unset("from time.date and time.latitude")
                   .doc("spring, summer, autumn or winter; unset: the meteorological season of the date at the latitude (December "
                        "to February is winter in the north, summer in the south)"));
  return table;
}

const params::Table<WeatherParams>& parameter_table(const WeatherParams*) {
  using P = WeatherParams;
  static const auto table =
      params::Table<P>("weather", "The weather: clouds, fog, haze and the sun's strength")
          .add(params::choice("weather", &P::weather, weather_choices()).doc("clear, cloudy, overcast, rain, snow or fog"));
  return table;
}

const params::Table<TimeParams>& parameter_table(const TimeParams*) {
  using P = TimeParams;
  static const auto table =
      params::Table<P>("time", "When and where: the sun's position from date, time and place (NOAA's formula), or given")
          .add(params::field("date", &P::date)
                   .rule([](const params::Value& v) { return date_problem(std::get<std::string>(v)); }, "YYYY-MM-DD")
                   .doc("Date, YYYY-MM-DD"))
          .add(params::field("time", &P::time)
                   .rule([](const params::Value& v) { return time_problem(std::get<std::string>(v)); }, "HH:MM or HH:MM:SS")
                   .doc("Local clock time, HH:MM or HH:MM:SS"))
          .add(
              params::field("utc_offset", &P::utc_offset_h).in(-14, 14).units("h").doc("The local clock's offset from UTC (east positive)"))
          .add(params::field("latitude", &P::latitude_deg).in(-90, 90).units("deg").doc("Latitude, north positive"))
          .add(params::field("longitude", &P::longitude_deg).in(-180, 180).units("deg").doc("Longitude, east positive"))
          .add(params::field("sun", &P::sun_deg)
                   .rule(
                       [](const params::Value& v) {
                         const double elevation = std::get<std::vector<double>>(v)[1];
                         return elevation >= -90.0 && elevation <= 90.0 ? "" : "AZIMUTH,ELEVATION with the elevation -90..90";
                       },
                       "AZIMUTH,ELEVATION with the elevation -90..90")
                   .units("deg")
                   .unset("from the date, time and place")
                   .doc("The sun's compass bearing (clockwise from north) and height above the horizon, given directly"));
  return table;
}

const params::Table<TreeParams>& parameter_table(const TreeParams*) {
  using P = TreeParams;
  static const auto table = params::Table<P>("tree", "One plant on its own: a picture or a mesh (sansui tree)")
                                .add(params::field("species", &P::species).doc("The species (docs/species.md lists them)"))
                                .add(params::path("species_file", &P::species_file)
                                         .doc("Your own species: a TOML file of [[species]] tables, as in data/species.toml"))
                                .add(params::field("seed", &P::seed).doc("Seed of the plant's shape"))
                                .add(params::field("winter_snow", &P::snow).doc("In winter, evergreens carry snow"));
  return table;
}

// ---- the whole recipe ------------------------------------------------------------------------

const std::vector<Section>& recipe_sections() {
  using S = SourceKind;
  using O = OutputKind;
  auto title = [](const auto& table) { return table.title; };
  static const std::vector<Section> sections{
      {"midpoint", title(params::table_of<terrain::MidpointParams>()), {S::midpoint}, {}},
      {"world", title(params::table_of<WorldParams>()), {S::midpoint}, {}},
      {"file", title(params::table_of<FileSourceParams>()), {S::file}, {}},
      {"contour_seed", title(params::table_of<ContourSeedParams>()), {S::contour}, {}},
      {"contour", title(params::table_of<contour::GenerationParams>()), {S::contour}, {}},
      {"contour_dem", title(params::table_of<contour::DemParams>()), {S::contour}, {}},
      {"dem", title(params::table_of<DemGridParams>()), {S::contour, S::mesh, S::contour_map}, {}},
      {"contour_map", title(params::table_of<ContourMapSourceParams>()), {S::contour_map}, {}},
      {"mesh", title(params::table_of<MeshSourceParams>()), {S::mesh}, {}},
      {"sketch", title(params::table_of<mesh::SketchParams>()), {S::mesh}, {}},
      {"subdivide", title(params::table_of<mesh::SubdivideParams>()), {S::mesh}, {}},
      {"heightmap_output", title(params::table_of<HeightmapOutputParams>()), {}, {O::heightmap}},
      {"georeference",
       title(params::table_of<GeoreferenceParams>()),
       {S::contour, S::contour_map, S::mesh},
       {O::heightmap, O::contours, O::rivers, O::lakes, O::flow_map, O::erosion_map, O::deposition_map, O::wetness_map,
        O::water_depth_map}},
      {"render", title(params::table_of<look::RenderParams>()), {}, {O::render, O::tree, O::mesh, O::splat_map}},
      {"rock", title(params::table_of<solid::RockParams>()), {}, {O::render}},
      {"map", title(params::table_of<contour::MapStyle>()), {}, {O::map, O::map_real, O::map_generated}},
      {"solid_field", title(params::table_of<solid::FieldParams>()), {}, {O::volume, O::sphere, O::cube, O::slice}},
      {"solid", title(params::table_of<SolidParams>()), {}, {O::volume, O::sphere, O::cube, O::slice}},
      {"compare", title(params::table_of<CompareSetup>()), {}, {O::comparison, O::map_real, O::map_generated}},
      {"climate", title(params::table_of<ClimateParams>()), {}, {O::render, O::plants, O::mesh, O::splat_map}},
      {"season", title(params::table_of<SeasonParams>()), {}, {O::render, O::plants, O::tree, O::mesh, O::splat_map}},
      {"weather", title(params::table_of<WeatherParams>()), {}, {O::render, O::plants, O::mesh, O::splat_map}},
      {"time", title(params::table_of<TimeParams>()), {}, {O::render}},
      {"camera", title(params::table_of<look::Camera>()), {}, {O::render}},
      {"land", title(params::table_of<look::Land>()), {}, {O::render, O::plants, O::mesh, O::splat_map}},
      {"sea", title(params::table_of<look::Sea>()), {}, {O::render}},
      {"sky", title(params::table_of<look::Sky>()), {}, {O::render}},
      {"atmosphere", title(params::table_of<look::Atmosphere>()), {}, {O::render}},
      {"vegetation", title(params::table_of<vegetation::VegetationParams>()), {}, {O::render, O::plants}},
      {"tree", title(params::table_of<TreeParams>()), {}, {O::tree}},
      {"flow",
       title(params::table_of<water::FlowParams>()),
       {},
       {O::render, O::rivers, O::lakes, O::flow_map, O::wetness_map, O::water_depth_map}},
  };
  return sections;
}

const params::Table<Recipe>& recipe_table() {
  using R = Recipe;
  static const auto table = [] {
    auto t = params::Table<R>("recipe", "A recipe: a source, shaping steps, outputs")
                 .add(params::choice("source", &R::source, source_choices())
                          .doc("Where the heightfield comes from; none: only solid-texture outputs"));
    auto section = [&](std::string name, auto R::*member) {
      using Struct = std::remove_reference_t<decltype(std::declval<R&>().*member)>;
      t.nest(name + ".", "", member, params::table_of<Struct>());
    };
    section("midpoint", &R::midpoint);
    section("world", &R::world);
    section("file", &R::file);
    section("contour_seed", &R::contour_seed);
    section("contour", &R::contour);
    section("contour_dem", &R::contour_dem);
    section("dem", &R::dem);
    section("contour_map", &R::contour_map);
    section("mesh", &R::mesh);
    section("sketch", &R::sketch);
    section("subdivide", &R::subdivide);
    section("heightmap_output", &R::heightmap_output);
    section("georeference", &R::georeference);
    section("render", &R::render);
    section("rock", &R::rock);
    section("map", &R::map);
    section("solid_field", &R::solid_field);
    section("solid", &R::solid);
    section("compare", &R::compare);
    section("climate", &R::climate);
    section("season", &R::season);
    section("weather", &R::weather);
    section("time", &R::time);
    section("vegetation", &R::vegetation);
    section("tree", &R::tree);
    section("flow", &R::flow);
    // The renderer's own parts are sections of their own: [camera], [land], [sea], [sky], [atmosphere].
    auto render_part = [&](std::string name, auto look::RenderParams::*member) {
      using Struct = std::remove_reference_t<decltype(std::declval<look::RenderParams&>().*member)>;
      params::Table<look::RenderParams> part(name, params::table_of<Struct>().title);
      part.nest("", "", member, params::table_of<Struct>());
      t.nest(name + ".", "", &R::render, part);
    };
    render_part("camera", &look::RenderParams::camera);
    render_part("land", &look::RenderParams::land);
    render_part("sea", &look::RenderParams::water);
    render_part("sky", &look::RenderParams::sky);
    render_part("atmosphere", &look::RenderParams::atmosphere);
    for (auto& row : t.rows)
      if (row.key == "land.lines" || row.key == "land.tree_line_m" || row.key == "land.snow_line_m") row.introduced(4);
    supersede_sea_level(t.rows, "render.sea_level");
    supersede_sea_level(t.rows, "flow.sea_level");
    for (auto& row : t.rows)
      if (row.key == "georeference.crs") row.superseded(3, "[world] crs");
    return t;
  }();
  return table;
}

std::string_view section_of(std::string_view key) {
  const auto dot = key.find('.');
  return dot == std::string_view::npos ? std::string_view() : key.substr(0, dot);
}

bool section_used(const Recipe& recipe, const Section& section) {
  // The world's sea level is every recipe's with heights from version 3 on (a graph's always).
  const bool has_heights = !recipe.nodes.empty() || (recipe.source != SourceKind::none && recipe.version >= 3);
  if (has_heights && section.name == "world") return true;
  if (std::find(section.sources.begin(), section.sources.end(), recipe.source) != section.sources.end()) return true;
  for (const Output& output : recipe.outputs) {
    const auto kind = resolved_kind(output);
    if (kind && std::find(section.outputs.begin(), section.outputs.end(), *kind) != section.outputs.end()) return true;
  }
  return false;
}

const std::vector<SourceDefault>& source_defaults() {
  static const std::vector<SourceDefault> defaults{
      {SourceKind::contour, "render.exaggeration", "1", "a mountain drawn at its true height, as the paper's Fig. 17"},
      {SourceKind::contour, "render.sea", "false", "the foot of the mountain is land, not sea"},
      {SourceKind::contour, "rock.texture", "strata", "cliffs in rock strata"},
  };
  return defaults;
}

ShapeStep default_shape_step(int version) {
  ShapeStep step;
  if (version == 1) {
    // The defaults before version 2 (model 1 erosion, a fixed count of droplets).
    water::ErosionChainParams& chain = step.erosion;
    chain.fluvial.uplift_m_per_yr = 1e-4;
    chain.fluvial.diffusivity_m2_per_yr = 0.01;
    chain.fluvial.steps = 10;
    chain.thermal.iterations = 20;
    chain.droplets.droplets = 200000;
    chain.keep_detail = 0.0;
  }
  return step;
}

std::array<double, 2> world_sample_origin(const WorldParams& world) {
  if (!world.origin_m) return {0.0, 0.0};
  return {(*world.origin_m)[0] + 0.5 * world.cell_m, -(*world.origin_m)[1] + 0.5 * world.cell_m};
}

bool reads_key(const Recipe& recipe, const params::ParamInfo& row) {
  if (row.key == "world.sea_level") return recipe.version >= 3 || !recipe.nodes.empty();
  if (row.key == "world.crs") return recipe.version >= 3;
  return row.current_in(recipe.version);
}

void settle_world(Recipe& recipe) {
  if (recipe.version < 3) return;
  recipe.georeference.crs = recipe.world.crs;
  const double sea = recipe.world.sea_level_m;
  for (ShapeStep& step : recipe.shape) step.stage.sea_level_m = sea;
  recipe.render.sea_level_m = sea;
  // Rivers end in the sea where the world has one; without a sea, low ground holds lakes.
  recipe.flow.sea_level_m = recipe.render.sea ? std::optional<double>(sea) : std::nullopt;
}

ShapeStep default_erode_step() {
  ShapeStep step = default_shape_step();
  step.step = StepKind::erode;
  return step;
}

Recipe default_recipe(SourceKind source, int version) {
  Recipe recipe;
  recipe.source = source;
  recipe.version = version;
  if (version < 4) {
    // Before version 4 the season did not follow the date, and the tree and snow lines were
    // Table 4's fractions of the highest point.
    recipe.season.season = Season::summer;
    recipe.render.land.lines = look::LandLines::paper;
    recipe.midpoint.sigma_m = terrain::default_sigma_m;  // the same whatever the world's extent
  }
  if (version == 1) {
    recipe.midpoint.paper_sea_level = true;
    recipe.midpoint.hurst = 0.8;
    recipe.midpoint.sigma_m = 400.0;
  }
  const auto& table = recipe_table();
  for (const auto& d : source_defaults()) {
    if (d.source != source) continue;
    const auto* row = table.find(d.key);
    row->set(recipe, params::parse_text(*row, d.value, d.key));
  }
  return recipe;
}

const look::Camera* camera_for(const Recipe& recipe, const Output& output) {
  if (output.camera.empty() || output.camera == recipe.render.camera.name) return &recipe.render.camera;
  for (const look::Camera& camera : recipe.more_cameras)
    if (camera.name == output.camera) return &camera;
  return nullptr;
}

std::optional<OutputKind> resolved_kind(const Output& output) {
  if (output.kind) return output.kind;
  const std::string extension = io::lower_extension(output.file);
  for (const OutputKindInfo& info : output_kinds())
    if (std::find(info.inferred_from.begin(), info.inferred_from.end(), extension) != info.inferred_from.end()) return info.kind;
  return std::nullopt;
}

std::vector<std::string> extensions_for(OutputKind kind) {
  return output_kind_info(kind).extensions;
}

}  // namespace sansui::scene
