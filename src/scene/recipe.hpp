// A recipe (SPEC 3.7): a source, a chain of shaping steps, and outputs. Every command of the CLI
// fills one, a scene file (TOML) is one written out, and the JSON sidecar of every output holds
// the recipe that rebuilds that output byte for byte. Its sections are the library's params
// structs, each with its parameter table (core/params.hpp); the structs below are the sections
// that belong to no one algorithm: where a source reads its input, the world window, outputs.
//
//   source ──► Heightfield ──► shape steps ──► outputs
//   midpoint   (terrain)        stage filter     heightmaps, meshes, render, contour maps,
//   file       (a heightmap)    (erosion later)  previews, solid-texture volumes and pictures,
//   contour    (seed 000)                        comparisons with a real DEM
//   mesh       (seed 004)
//   contour_map (a given contour map: contours_to_dem.hpp)
//   none       (only solid-texture outputs)
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contour/compare.hpp"
#include "contour/generate.hpp"
#include "contour/map_drawing.hpp"
#include "contour/to_dem.hpp"
#include "core/params.hpp"
#include "io/heightmap_io.hpp"
#include "look/render_params.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"
#include "scene/climate.hpp"
#include "scene/graph.hpp"
#include "solid/field.hpp"
#include "solid/rock_albedo.hpp"
#include "terrain/midpoint.hpp"
#include "terrain/stage_filter.hpp"
#include "vegetation/placement.hpp"
#include "water/erode.hpp"
#include "water/flow.hpp"

namespace sansui::scene {

/// Where the heightfield comes from.
enum class SourceKind { none, midpoint, file, contour, mesh, contour_map };

/// The world a midpoint source generates, and which window of it. [world]
struct WorldParams {
  /// Samples per side of the whole terrain, 2^k+1, or an Unreal landscape size (505, 1009...:
  /// a window of the 2^k+1 world just above it). [Range: 3..16385] [Default: 1025]
  long long size = 1025;
  /// Samples per side of the whole world, 2^k+1 up to 1048577, for tiles and previews.
  /// [Default: unset: size]
  std::optional<long long> world_size;
  /// Only tile X,Y of the world (tiles share their border samples). [Default: the whole world]
  std::optional<std::array<int, 2>> tile;
  /// Samples per side of a tile, 2^m+1. [Default: 1025]
  long long tile_size = 1025;
  /// Build the whole world tile by tile (scene/tiled_world.hpp): erosion and drainage exact
  /// across tiles, over MPI ranks when run by mpirun. [Default: false]
  bool tiled = false;
  /// Level of detail: every 2^lod-th sample, exactly the full world's values there. [Default: 0]
  int lod = 0;
  /// Distance between samples of the full-resolution world. [Units: m] [Range: > 0] [Default: 10]
  double cell_m = 10.0;
  /// An eroded world in tiles or at a level of detail is eroded whole at most this many samples
  /// per side (2^k+1), then every tile is refined from it. [Range: 3..16385] [Default: 1025]
  long long erosion_size = 1025;
  /// Size of the fractal detail refined onto an eroded world's tiles, relative to the uneroded
  /// terrain's. [Range: 0..1] [Default: 0.1]
  double erosion_detail = 0.1;
  /// The world's sea level, which every step, node and output takes (recipes of version 3 on,
  /// and graphs). [Units: m] [Default: 0]
  double sea_level_m = 0.0;
  /// The world's coordinate reference system (recipes of version 3 on; before, [georeference]
  /// crs): EPSG:CODE or WKT, projected in metres. [Default: "" = the input's, else none]
  std::string crs;
  /// Where the world lies: EAST,NORTH of its north-west corner (the GeoTIFF's upper-left corner)
  /// in the CRS's metres (recipes of version 4 on). [Units: m] [Default: unset: sample (0, 0) at
  /// 0, 0, as before version 4]
  std::optional<std::array<double, 2>> origin_m;
};

/// The position, in the world's coordinates (east, south), of sample (0, 0) of the full-resolution
/// world: (0, 0) without an origin, else half a cell inside the origin corner.
std::array<double, 2> world_sample_origin(const WorldParams& world);

/// A heightmap file as the source. [file]
struct FileSourceParams {
  std::string path;  ///< .png (16-bit) .raw .r32 .tif
  /// Cell size for files with none of their own. [Units: m] [Default: the file's or its sidecar's]
  std::optional<double> cell_m;
  /// Metres that 16-bit values 0 and 65535 stand for, MIN,MAX. [Units: m] [Default: the sidecar's]
  std::optional<std::array<double, 2>> range_m;
};

/// Where the seed contour of a contour mountain comes from, and how its levels are reshaped.
/// [contour_seed]
struct ContourSeedParams {
  std::string file;                             ///< .geojson .json .csv .txt .svg
  std::string from_dem;                         ///< or a DEM, at `level`
  std::optional<double> level_m;                ///< [Units: m]
  std::optional<std::array<double, 2>> pick_m;  ///< the contour around this point of the DEM plane
  double svg_scale = 1.0;                       ///< metres per SVG unit. [Units: m] [Range: > 0]
  std::string hypsometry;                       ///< CSV of area,height fractions
  std::optional<double> relief_m;               ///< top of the hypsometric curve above z0. [Units: m]
};

/// A given contour map to interpolate into a DEM (sansui contour-dem). [contour_map]
struct ContourMapSourceParams {
  std::string file;  ///< .geojson .json: LineString, MultiLineString, Polygon, MultiPolygon features
  /// The elevation's attribute. [Default: "" = the first of elev, ELEV, elevation, elevation_m, ELEVATION]
  std::string elevation_attribute;
  /// Also read Point and MultiPoint features as spot heights. [Default: false]
  bool spot_heights = false;
  /// A heightmap whose grid (size, cell, origin) the DEM takes, to compare cell by cell. [Default: none]
  std::string grid_from;
};

/// The grid a contour or mesh source is rasterised onto. [dem]
struct DemGridParams {
  /// Samples along the longer side. [Range: 2..65537; 2..32768 for a contour mountain or a contour map] [Default: 1025; a seed from a DEM:
  /// that DEM's grid]
  std::optional<int> size;
  /// Cell size instead of size (same extent). [Units: m]
  std::optional<double> cell_m;
  /// Height outside the shape (outside the outermost contour; where no triangle is). [Units: m]
  /// [Default: the lowest contour's elevation; the lowest vertex]
  std::optional<double> fill_m;
};

/// A coarse mesh to subdivide: a file, the pyramid of Fig. 3, or a sketch. [mesh]
struct MeshSourceParams {
  std::string file;                                ///< .obj .glb .gltf
  std::optional<std::array<double, 2>> pyramid_m;  ///< WIDTH,HEIGHT. [Units: m]
  std::string sketch;                              ///< GeoJSON ridge and valley lines
  bool measure = true;                             ///< measure the fractal dimension of the result
};

/// The game engine whose terrain importer the heightmaps are for (scene/engines.hpp).
enum class Engine { none, unreal, unity, godot };

/// How heightmaps are written. [heightmap_output]
struct HeightmapOutputParams {
  /// Metres mapped to 0 and 65535 in 16-bit outputs, MIN,MAX. [Units: m]
  /// [Default: the data's range; tiles and previews: sea level -/+ 6 sigma]
  std::optional<std::array<double, 2>> range_m;
  /// .raw rows south first, as Unity's terrain importer reads them. [Default: false]
  bool raw_flip_y = false;
  /// .png and .tif: none, fast or small (io::Compression). [Default: fast]
  io::Compression compression = io::Compression::fast;
  /// unreal, unity or godot: sizes and formats that engine imports; the sidecar and a note give
  /// its importer's scales and location. [Default: none]
  Engine engine = Engine::none;
};

/// The coordinate reference system of the outputs (issue 14 item 3). [georeference]
struct GeoreferenceParams {
  /// The outputs' CRS: EPSG:CODE or WKT of a projected CRS in metres, checked by PROJ; it is
  /// assigned, not transformed to. [Default: "" = the input's (a GeoTIFF's keys, a GeoJSON's crs
  /// member, a sidecar's crs), else none: a local plane in metres]
  std::string crs;
  /// Read a GeoJSON input whose crs member is geographic, or a GeoJSON or CSV input without one
  /// that looks like longitude/latitude, as metres anyway (its CRS is dropped). [Default: false:
  /// refuse it]
  bool force_metres = false;
};

/// How the solid texture's outputs are made. [solid]
struct SolidParams {
  solid::EvaluatorType type = solid::EvaluatorType::type4;
  std::optional<int> r2;           ///< Type IV's array levels. [Default: min(6, R)]
  std::string texture = "marble";  ///< preset
  std::optional<double> strength;  ///< k of eq. 7. [Default: the preset's]
  std::string slice_at = "z=50%";  ///< AXIS=V of the slice picture
  int picture_size = 512;          ///< [Units: px]
  bool reuse = true;               ///< Types III/IV keep the previous query's ancestors
  double memory_mb = 0.0;          ///< memory the field may use; 0: what is available. [Units: MB]
};

/// A real DEM to compare the heightfield with (SPEC 1.4). [compare]
struct CompareSetup {
  std::string real;    ///< the real DEM
  std::string inside;  ///< GeoJSON whose seed contour bounds the compared cells
  contour::CompareParams measures;
};

/// The scene's high-level parameters (seed 003's "information compression", SPEC 3.2): they
/// derive the look's low-level values (scene/climate.hpp, scene/look.hpp) that the scene file
/// leaves unset. [climate] [season] [weather]
struct ClimateParams {
  Climate koppen = Climate::Cfb;
};
struct SeasonParams {
  /// Unset: from time.date and time.latitude (southern latitudes flip it); recipes before version
  /// 4 default to summer.
  std::optional<Season> season;
};
struct WeatherParams {
  Weather weather = Weather::clear;
};

/// When and where the scene is: the sun's position (NOAA's formula) and the ripples' phase. [time]
struct TimeParams {
  std::string date = "2026-07-15";  ///< YYYY-MM-DD
  std::string time = "16:00";       ///< local clock time, HH:MM or HH:MM:SS
  double utc_offset_h = 0.0;        ///< the local clock's offset from UTC. [Units: h] [Range: -14..14]
  double latitude_deg = 45.0;       ///< [Units: deg] [Range: -90..90]
  double longitude_deg = 0.0;       ///< east positive. [Units: deg] [Range: -180..180]
  /// The sun's AZIMUTH,ELEVATION given directly, instead of from the date and time. [Units: deg]
  std::optional<std::array<double, 2>> sun_deg;
};

/// One plant on its own: `sansui tree`, and tree outputs. [tree]
struct TreeParams {
  std::string species = "oak";  ///< a species of data/species.toml or of species_file
  /// A TOML file of the user's own [[species]] tables (data/species.toml's form), added to the
  /// library (a name already there replaces it). [Default: none]
  std::string species_file;
  std::uint64_t seed = 1;  ///< the plant's shape
  /// In winter, evergreens carry snow. [Default: true]
  bool snow = true;
};

/// A shaping step on the heightfield. [[shape]]
///   stage: the paper's geomorphic stage filter (seeds/003), a bend of the heights;
///   erode: landscape evolution (water/): stream power with deposition and hillslope diffusion,
///          then thermal and droplet erosion; `stage` is then the erosion time (young 0.1,
///          mature 0.5, old 2, peneplain 8 response times) unless time_from_stage is false.
enum class StepKind { stage, erode };
struct ShapeStep {
  StepKind step = StepKind::stage;
  terrain::StageFilterParams stage;
  /// erode: the erosion time comes from `stage`; false: steps x time_step. [Default: true]
  bool time_from_stage = true;
  /// erode: run even when the erosion is estimated to take longer than ten minutes. [Default: false]
  bool force = false;
  water::ErosionChainParams erosion;
};

/// What an output file holds.
/// The kinds of output; what each holds, its extensions and needs are in scene/output_kinds.hpp.
enum class OutputKind {
  heightmap,
  mesh,
  render,
  contours,
  map,
  preview,
  volume,
  sphere,
  cube,
  slice,
  comparison,
  map_real,
  map_generated,
  plants,
  tree,
  rivers,
  lakes,
  flow_map,
  erosion_map,
  deposition_map,
  wetness_map,
  water_depth_map,
  splat_map,
};

struct Output {
  std::string file;
  /// [Default: from the extension: .png .raw .r16 .r32 .tif heightmap, .obj .glb mesh, .geojson contours, .svg map]
  std::optional<OutputKind> kind;
  /// Render outputs: the camera of this name. [Default: "" (the first camera)]
  std::string camera;
  /// A recipe graph's node whose heights this output writes. [Default: "" (the graph's final node)]
  std::string node;
};

/// The version of the recipe layout, written as `sansui_recipe`. Newer files are refused.
/// Version 2 changed defaults (see CHANGELOG.md): a midpoint world has land by default
/// (midpoint.land_fraction), and an erode step is model 2 (water/erode.hpp) with defaults that
/// scale with the grid. A recipe keeps the version it was written with, so every version 1
/// file, and the sidecar it rebuilds, keeps its bytes. Version 3 has one sea level, [world]
/// sea_level, for the shaping steps, the picture, the plants and the rivers; older recipes gave
/// it in [[shape]], [render] and [flow], each its own, and are read so.
/// Version 4 places the world on the map and in its climate: the tree and snow lines are metres
/// from the climate and latitude (land.lines = "climate"; older recipes read "paper", Table 4's
/// fractions of the highest point), and the season follows the date and latitude unless set
/// (older recipes: summer).
/// Version 5 names one CRS, "Sansui local metres", in every georeferenced file of a world given
/// no CRS: GeoTIFF, ENVI and .aux.xml headers and GeoJSON alike (older recipes: none in rasters,
/// and GeoJSON's with its datum named).
/// Version 6 erodes with model 3 (water/erode.hpp): the fine roughness put back after an erosion
/// is what the erosion took of it, so land that little erosion touched (the stages original and
/// young) is no rougher than before (older recipes: model 2, which put all of it back again).
/// Version 7 erodes with model 4: with a margin of land past the map's edges, so that no edge
/// stands as a rim (older recipes: model 3, each edge a divide).
inline constexpr int recipe_version = 7;

/// The most entries each list of a recipe may hold: far above any scene (the gallery's largest
/// has a few outputs and cameras), and low enough that every check over them stays instant and a
/// sidecar stays small. A file with more is refused as it is read, naming the limit.
inline constexpr std::size_t max_outputs = 4096, max_cameras = 4096, max_shape_steps = 256, max_nodes = 1024;

/// Limits on the files a run of a recipe writes (scene/output_plan.hpp). Not parameters: they say
/// where the recipe came from and what the user allowed, and are never saved.
struct OutputRules {
  /// The scene file or sidecar the recipe was read from (empty: made on the command line or in
  /// code): no output may overwrite it, except as the sidecar of the output it rebuilds.
  std::filesystem::path recipe_file;
  /// Every output must lie inside this directory: for a recipe read from a file, the file's
  /// folder (`sansui run --out-dir`: that directory), so that a recipe someone sent cannot
  /// replace files elsewhere. Empty: anywhere (names typed on the command line,
  /// `--allow-outside-paths`).
  std::filesystem::path confined_to;
  /// An output name that is a symbolic link is written through it (its target gets the bytes),
  /// and a link on the way out of confined_to is allowed. [Default: false: refused]
  bool follow_symlinks = false;
};

struct Recipe {
  SourceKind source = SourceKind::none;
  terrain::MidpointParams midpoint;
  WorldParams world;
  FileSourceParams file;
  ContourSeedParams contour_seed;
  contour::GenerationParams contour;
  contour::DemParams contour_dem;
  DemGridParams dem;
  ContourMapSourceParams contour_map;
  MeshSourceParams mesh;
  mesh::SketchParams sketch;
  mesh::SubdivideParams subdivide;
  std::vector<ShapeStep> shape;
  HeightmapOutputParams heightmap_output;
  GeoreferenceParams georeference;
  look::RenderParams render;
  solid::RockParams rock;
  contour::MapStyle map;
  solid::FieldParams solid_field;
  SolidParams solid;
  CompareSetup compare;
  ClimateParams climate;
  SeasonParams season;
  WeatherParams weather;
  TimeParams time;
  vegetation::VegetationParams vegetation;
  TreeParams tree;
  /// Rivers and lakes: where water flows and stands. [flow]
  water::FlowParams flow;
  std::vector<Output> outputs;
  /// A scene's second and later cameras ([[camera]] tables after the first, which is
  /// render.camera); render outputs pick one by name.
  std::vector<look::Camera> more_cameras;
  /// The recipe's graph ([[node]] tables, scene/graph.hpp): when it has nodes, they make the
  /// heights instead of `source` (which is none) and `shape`.
  std::vector<GraphNode> nodes;
  /// Relative file names in the recipe are relative to this directory (a scene file's
  /// directory; the working directory on the command line). Not a parameter.
  std::filesystem::path base_dir;
  /// The recipe version it was written with (`sansui_recipe`), which decides the defaults of
  /// keys it leaves out and the erosion model. Not a parameter.
  int version = recipe_version;
  /// Where the recipe came from and what its outputs may overwrite. Not a parameter.
  OutputRules output_rules;
};

const params::Table<WorldParams>& parameter_table(const WorldParams*);
const params::Table<FileSourceParams>& parameter_table(const FileSourceParams*);
const params::Table<ContourSeedParams>& parameter_table(const ContourSeedParams*);
const params::Table<DemGridParams>& parameter_table(const DemGridParams*);
const params::Table<ContourMapSourceParams>& parameter_table(const ContourMapSourceParams*);
const params::Table<MeshSourceParams>& parameter_table(const MeshSourceParams*);
const params::Table<HeightmapOutputParams>& parameter_table(const HeightmapOutputParams*);
const params::Table<GeoreferenceParams>& parameter_table(const GeoreferenceParams*);
const params::Table<SolidParams>& parameter_table(const SolidParams*);
const params::Table<CompareSetup>& parameter_table(const CompareSetup*);
const params::Table<ClimateParams>& parameter_table(const ClimateParams*);
const params::Table<SeasonParams>& parameter_table(const SeasonParams*);
const params::Table<WeatherParams>& parameter_table(const WeatherParams*);
const params::Table<TimeParams>& parameter_table(const TimeParams*);
const params::Table<TreeParams>& parameter_table(const TreeParams*);
const params::Table<ShapeStep>& parameter_table(const ShapeStep*);
const params::Table<Output>& parameter_table(const Output*);

/// Names: "midpoint", "file", ...; "heightmap", "render", ...
std::string_view source_name(SourceKind source);
std::optional<SourceKind> source_from_name(std::string_view name);
std::string_view output_kind_name(OutputKind kind);
std::vector<std::string> source_names();

/// A section of a recipe: a params struct of Recipe, what it is for, and who reads it.
struct Section {
  std::string name;                 ///< [name] in a scene file
  std::string title;                ///< one line, from the table of its struct
  std::vector<SourceKind> sources;  ///< sources that read it
  std::vector<OutputKind> outputs;  ///< outputs that read it
};

/// Every section, in the order scene files list them.
const std::vector<Section>& recipe_sections();

/// One table over the whole recipe: every row of every section, keyed "section.key"
/// ("midpoint.hurst", "render.camera.azimuth"), plus the top-level `source`.
const params::Table<Recipe>& recipe_table();

/// The section a key of recipe_table() belongs to ("" for top-level keys).
std::string_view section_of(std::string_view key);

/// True when `section` is read by the recipe's source or one of its outputs.
bool section_used(const Recipe& recipe, const Section& section);

/// A recipe with the defaults of `source`: the library defaults, except where a source changes
/// them (a contour mountain is drawn with no sea, no vertical exaggeration and rock strata), and
/// for a `version` 1 recipe the defaults of version 1.
Recipe default_recipe(SourceKind source, int version = recipe_version);

/// Hands the world's facts to the sections that act on them: from version 3 on, [world]
/// sea_level becomes every shaping step's and the picture's sea level, and flow routing's when
/// the world has a sea (render.sea), and [world] crs the outputs' CRS; they have no key of their
/// own. Older recipes keep each section's own. Loading, the command line, the
/// viewer after a change and every run call it; calling it again changes nothing.
void settle_world(Recipe& recipe);

/// Whether `recipe` reads the key of `row` (a row of recipe_table() or of a [[shape]] step): a
/// superseded key only in older recipes, [world] sea_level in graphs and from version 3 on.
bool reads_key(const Recipe& recipe, const params::ParamInfo& row);

/// A shaping step with the defaults of a `version` recipe.
ShapeStep default_shape_step(int version = recipe_version);

/// An erode step with the defaults of the current version: the one `sansui terrain` runs
/// unless told --no-erode.
ShapeStep default_erode_step();

/// The defaults that depend on the source, as (key, value, why) for docs.
struct SourceDefault {
  SourceKind source;
  std::string key;
  std::string value;
  std::string why;
};
const std::vector<SourceDefault>& source_defaults();

/// The camera a render output draws with: render.camera, or the one of more_cameras it names.
/// nullptr when no camera has that name.
const look::Camera* camera_for(const Recipe& recipe, const Output& output);

/// The kind of an output: its own, else from the extension. nullopt when neither tells.
std::optional<OutputKind> resolved_kind(const Output& output);

/// The extensions an output kind may have (".png", ...).
std::vector<std::string> extensions_for(OutputKind kind);

}  // namespace sansui::scene
