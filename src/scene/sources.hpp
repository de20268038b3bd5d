// The sources of the pipeline (internal to scene/). Each makes what the outputs need from the
// recipe and may fill in defaults that depend on the data (recorded in the resolved recipe).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "contour/contour_tree.hpp"
#include "core/context.hpp"
#include "core/contour_lines.hpp"
#include "core/grid.hpp"
#include "core/triangle_mesh.hpp"
#include "io/crs.hpp"
#include "io/heightmap_io.hpp"
#include "mesh/sketch.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe.hpp"
#include "scene/water_layers.hpp"
#include "water/flow.hpp"

namespace sansui::scene::detail {

/// What the outputs ask of the source.
struct Needs {
  bool heights = false;  ///< a heightfield
  bool mesh = false;     ///< the subdivided mesh (mesh source)
  bool tree = false;     ///< the contour tree (contour source)
};

/// What a source made.
struct Produced {
  std::optional<Heightfield> heights;
  /// A tile's heights with one more sample on each side where the world goes on, for outputs
  /// that look at neighbours (the splat map's slopes), so that tiles agree with the whole world;
  /// `heights` starts at apron_offset in it. Shaped by the same steps.
  std::optional<Heightfield> apron;
  std::array<int, 2> apron_offset{0, 0};
  std::optional<contour::ContourTree> tree;
  std::optional<TriangleMesh> mesh;
  /// What the erode steps carved and laid down, summed over the steps (mask outputs). [Units: m]
  std::optional<Grid<float>> eroded_m, deposited_m;
  /// How many of the recipe's shaping steps the source already ran (an eroded world in tiles is
  /// shaped whole at a coarse level before its tile is refined).
  std::size_t shape_steps_done = 0;
  /// Base level of the source's own, above sea level, that erosion must respect: the flat plain
  /// around a contour mountain (water leaves there, sediment does not pile up). [Units: m]
  std::optional<double> base_level_m;
  /// The outputs' coordinate reference system (scene/georeference.hpp); nullopt: a local plane.
  std::optional<io::Crs> crs;
  /// The heights' routing, where a graph's flow node made it: the water outputs take it.
  RoutedHeights routed;
  nlohmann::json statistics = nlohmann::json::object();  ///< figures of the run, for sidecars
  std::vector<std::string> lines;                        ///< report lines
};

/// The file name `path` of a recipe, resolved against its base directory.
std::filesystem::path resolve(const Recipe& recipe, const std::string& path);

/// Reads a heightmap and tells the user (notes on `context`) what the reader did on its own: a
/// GeoTIFF's rectangular cells resampled to square ones, a default range or cell size assumed.
/// Every DEM a recipe reads goes through here, so none is changed silently.
Heightfield read_heightmap_with_notes(const std::filesystem::path& path, const Context& context,
                                      const io::HeightmapReadOptions& options = {});

/// How an erode step erodes: its chain with the base level set, the stage whose response times
/// set its time (nullopt: the chain's own time step; a step of stage `original` has no steps),
/// and the erosion model of the recipe's version.
struct ErosionPlan {
  water::ErosionChainParams chain;
  std::optional<water::ErosionStage> stage;
  int model = 2;
};
ErosionPlan plan_erosion(const ShapeStep& step, int version, std::optional<double> base_level_m);

/// The erosion of one erode step: the chain of water/erode.hpp, of the recipe version's model
/// (1 or 2), with the step's sea level as base level (or `base_level_m` when that is higher) and,
/// unless the step says otherwise, the erosion time of its stage ("original": no fluvial
/// erosion). Refuses (InputError) an erosion estimated over ten minutes without step.force.
/// `routing_of_heights`: as water::erode's (a flow node's routing of these heights).
water::ErosionResult erode_with(const ShapeStep& step, int version, const Heightfield& heights, std::optional<double> base_level_m,
                                const Context& context, const water::FlowRouting* routing_of_heights = nullptr);

/// Checks of each source's own section, before any work (throws InputError).
void check_midpoint_source(const Recipe& recipe);
void check_contour_source(const Recipe& recipe);
void check_mesh_source(const Recipe& recipe);
void check_contour_map_source(const Recipe& recipe);

Produced run_midpoint_source(Recipe& recipe, const RunOptions& options, const Context& context);

/// Whether an output of the recipe looks past a tile's border (the land's splat map: slopes), so
/// that a tile's source also makes Produced::apron.
bool needs_apron(const Recipe& recipe);
/// The extent of the 2^k+1 world the midpoint source generates: 2^k cells. [Units: m]
double world_extent_m(const WorldParams& world);
/// What running a midpoint source fills in the recipe (an unset sigma from the world's extent,
/// the stage steps' sigma, a tile's 16-bit range): done the same whether the heights are made or
/// come from a cache, so that sidecars match.
void resolve_midpoint_recipe(Recipe& recipe);
Produced run_file_source(Recipe& recipe, const Context& context);
Produced run_contour_source(Recipe& recipe, const Needs& needs, const RunOptions& options, const Context& context);
Produced run_mesh_source(Recipe& recipe, const Needs& needs, const Context& context);

/// A coarse mesh to subdivide and its vertex locks: from a mesh file (.obj .glb .gltf, with its
/// locks), the pyramid of the paper's Fig. 3 or a sketch. The mesh source and the mesh node.
struct CoarseMesh {
  TriangleMesh mesh;
  std::vector<std::uint8_t> locked;
};
/// Throws InputError unless exactly one of the three is given and a file has a mesh extension;
/// `names` says what the user calls them ("mesh.file, mesh.pyramid, mesh.sketch").
void check_mesh_inputs(const std::string& file, bool pyramid, const std::string& sketch, std::string_view names);
/// Reads or makes the one given (paths resolved).
CoarseMesh read_coarse_mesh(const std::filesystem::path& file, const std::optional<std::array<double, 2>>& pyramid_m,
                            const std::filesystem::path& sketch, const mesh::SketchParams& sketch_params);
Produced run_contour_map_source(Recipe& recipe, const Context& context);

/// What the mesh source subdivides and where it rasterises it: the coarse mesh (a file, the
/// pyramid or a sketch, paths resolved), the subdivision, whether its roughness is measured, and
/// the DEM's own grid over the fine mesh's footprint (`size` samples along its longer side, or
/// `cell`) with the height around it.
struct MeshInput {
  std::filesystem::path file;
  std::optional<std::array<double, 2>> pyramid_m;
  std::filesystem::path sketch;
  mesh::SketchParams sketch_params;
  mesh::SubdivideParams subdivide;
  bool measure = true;
  std::optional<int> size;
  std::optional<double> cell_m;
  std::optional<double> fill_m;
};
/// What running a mesh source fills in the recipe (5 steps where it gives no stop rule), recorded
/// in its sidecars whether the mesh is made by the source or by its graph.
void resolve_mesh_recipe(Recipe& recipe);
/// The mesh source's input: [mesh], [subdivide], [sketch] and [dem], paths resolved.
MeshInput mesh_input(const Recipe& recipe);
/// The fine mesh (needs.mesh), its DEM on its own grid (needs.heights), the steps' table and the
/// measured roughness as statistics and report lines: the mesh source's, and a mesh node's in a
/// world without a grid.
Produced mesh_on_own_grid(const MeshInput& input, const Needs& needs, const Context& context);

/// What grows a contour mountain: its seed (a file, a DEM at a level, or a ring given inline; the
/// names as written in `seed`, the paths resolved beside them), the generation, the DEM's
/// surround and roughness, and its own grid ([dem]: size, cell, fill).
struct ContourInput {
  ContourSeedParams seed;
  std::filesystem::path file, from_dem, hypsometry;
  std::vector<double> points;  ///< x0, y0, x1, y1, ... metres; or none
  contour::GenerationParams generation;
  contour::DemParams dem;
  DemGridParams grid;
  /// Where the largest seed's centre is moved (a contour node on a world's grid); unset: in place.
  std::optional<std::array<double, 2>> at_m;
  bool base_level = true;     ///< the flat plain around is erosion's base level (recipes of version 2 on)
  bool report_times = false;  ///< a report line with the seconds of each part of the generation
};
/// Checks a contour mountain's seed (one of a file, a DEM with its level, or `points` given
/// inline) and its generation before any work; `prefix` names the keys in messages
/// ("contour_seed." in a recipe, "" for a node).
void check_contour_seed(const ContourSeedParams& seed, bool points, const contour::GenerationParams& generation, std::string_view prefix);
/// The contour source's input: [contour_seed], [contour], [contour_dem] and [dem], paths resolved.
ContourInput contour_input(const Recipe& recipe, bool report_times);
/// The contours grown from the seed, the seed's DEM where it came from one, and the report lines.
struct GrownContours {
  contour::ContourTree tree;
  std::optional<Heightfield> source_dem;
  std::vector<std::string> lines;
};
/// Grows the contours; fills in input.generation's offset and z0 where they were unset (what the
/// sidecars record), and says on `context` what it derived or repaired.
GrownContours grow_contours(ContourInput& input, const Context& context);
/// The contour tree and, for needs.heights, its DEM on its own grid (the seed DEM's, or a frame
/// round the contours) with the plain's base level: the contour source's, and a contour node's in
/// a world without a grid.
Produced contour_on_own_grid(ContourInput& input, const Needs& needs, const Context& context);

/// A contour map (GeoJSON lines with elevations, spot heights too if asked), read in place.
ContourMap read_contour_map(const std::filesystem::path& path, const std::string& elevation_attribute, bool spot_heights);
/// What a contour map's DEM reports in its sidecars: the counts of its lines and spot heights.
nlohmann::json contour_map_statistics(const ContourMap& map);
/// What makes a contour map's DEM on its own grid: the lines, and the grid of a heightmap
/// (grid_from), else `size` samples along the longer side or `cell` over their extent, else a
/// cell of the lines' median vertex spacing (said in a note).
struct ContourMapInput {
  std::filesystem::path file;
  std::string elevation_attribute;
  bool spot_heights = false;
  std::filesystem::path grid_from;
  std::optional<int> size;
  std::optional<double> cell_m;
};
/// The contour_map source's input: [contour_map] and [dem], paths resolved.
ContourMapInput contour_map_input(const Recipe& recipe);
/// The DEM, with the counts of lines and spot heights as statistics (the contour_map source's, and
/// a contour_map node's in a world without a grid).
Produced contour_map_on_own_grid(const ContourMapInput& input, const Context& context);

/// A source, registered once (source_kinds.cpp): its name, the checks of its sections before
/// any work, what it makes, and the example input and outputs of `--print-defaults`. Adding a
/// source is its own file (check and run) and one entry there, besides its enum value and the
/// sections it reads (recipe_sections()).
struct SourceEntry {
  SourceKind kind;
  std::string_view name;
  std::function<void(const Recipe&)> check;
  std::function<Produced(Recipe&, const Needs&, const RunOptions&, const Context&)> run;
  std::function<void(Recipe&)> example;  ///< sets an example input and outputs
  std::string_view example_note;         ///< what of the example to replace
};

/// Every source, in the order docs and choices list them.
const std::vector<SourceEntry>& source_entries();
const SourceEntry& source_entry(SourceKind kind);

/// Runs the recipe's shaping steps [first, end) on produced.heights.
void apply_shape_steps(const Recipe& recipe, Produced& produced, std::size_t first, std::size_t end, const Context& context);

/// The sea level the recipe's first stage step uses (0 without one). [Units: m]
double recipe_sea_level(const Recipe& recipe);

}  // namespace sansui::scene::detail
