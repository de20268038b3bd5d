#include "scene/outputs.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "contour/compare.hpp"
#include "contour/extract.hpp"
#include "contour/map_drawing.hpp"
#include "contour/map_raster.hpp"
#include "core/budget.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/extension.hpp"
#include "io/file_formats.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "io/map_svg.hpp"
#include "io/mesh_io.hpp"
#include "io/plant_instances.hpp"
#include "io/text_file.hpp"
#include "io/volume_file.hpp"
#include "look/surface_layers.hpp"
#include "mesh/heightfield_mesh.hpp"
#include "mesh/preview.hpp"
#include "mesh/rasterize.hpp"
#include "scene/contour_geojson.hpp"
#include "scene/engines.hpp"
#include "scene/georeference.hpp"
#include "scene/look.hpp"
#include "scene/output_kinds.hpp"
#include "scene/painter.hpp"
#include "scene/plants.hpp"
#include "scene/scene_parts.hpp"
#include "scene/solid_slice.hpp"
#include "scene/water_geojson.hpp"
#include "scene/water_layers.hpp"
#include "solid/evaluator.hpp"
#include "solid/pictures.hpp"
#include "solid/texture.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::scene::detail {
namespace {

bool any_output(const Recipe& recipe, std::initializer_list<OutputKind> kinds) {
  for (const Output& output : recipe.outputs)
    if (std::find(kinds.begin(), kinds.end(), *resolved_kind(output)) != kinds.end()) return true;
  return false;
}

/// A file name for the report: relative to the working directory when it lies below it.
std::string shown(const std::filesystem::path& path) {
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  const std::filesystem::path relative = absolute.lexically_relative(std::filesystem::current_path());
  return !relative.empty() && *relative.begin() != ".." ? relative.string() : absolute.string();
}

int solid_r2(const Recipe& recipe) {
  return recipe.solid.r2.value_or(std::min(6, recipe.solid_field.levels));
}

solid::SolidTexture solid_texture(const Recipe& recipe) {
  solid::SolidTexture texture = solid::texture_preset(recipe.solid.texture);
  if (recipe.solid.strength) texture.marble.strength = texture.wood.strength = texture.strata.strength = *recipe.solid.strength;
  return texture;
}

/// Wall seconds of the stages of one output, added to the report as they end.
class Stopwatch {
 public:
  explicit Stopwatch(RunReport& report) : report_(report), last_(std::chrono::steady_clock::now()) {}
  void lap(std::string name) {
    const auto now = std::chrono::steady_clock::now();
    report_.seconds.emplace_back(std::move(name), std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }

 private:
  RunReport& report_;
  std::chrono::steady_clock::time_point last_;
};

/// What one run's outputs share: the comparison and the solid field are made once.
class Writer {
 public:
  Writer(const Recipe& recipe, Produced& produced, const RunOptions& options, const Context& context, RunReport& report)
      : recipe_(recipe), produced_(produced), options_(options), context_(context), report_(report) {}

  void write(std::size_t index) {
    const Output& output = recipe_.outputs[index];
    file_ = shown(resolve(recipe_, output.file));
    const OutputKind kind = *resolved_kind(output);
    const std::filesystem::path path = resolve(recipe_, output.file);
    const nlohmann::json provenance = provenance_for(index);
    switch (kind) {
      case OutputKind::heightmap:
        heightmap(path, provenance);
        break;
      case OutputKind::mesh:
        mesh(path, provenance);
        break;
      case OutputKind::render:
        render(path, *camera_for(recipe_, output), provenance);
        break;
      case OutputKind::contours:
        io::write_text_file(path, geojson(contours_to_geojson(*produced_.tree, recipe_.map.index_every)), "contours", with_crs(provenance));
        say("{} contours -> {}", produced_.tree->nodes.size(), file_);
        break;
      case OutputKind::map:
        map(path, contour::layout_contour_map(*produced_.tree, recipe_.map), provenance);
        break;
      case OutputKind::preview:
        io::write_png(path, mesh::shaded_relief(heights()), provenance);
        say("shaded relief {}x{} -> {}", heights().width(), heights().height(), file_);
        break;
      case OutputKind::volume:
      case OutputKind::sphere:
      case OutputKind::cube:
      case OutputKind::slice:
        solid_output(kind, path, provenance);
        break;
      case OutputKind::comparison:
        comparison_output(path, output.file.empty(), provenance);
        break;
      case OutputKind::map_real:
      case OutputKind::map_generated:
        compared_map(kind, path, provenance);
        break;
      case OutputKind::plants:
        plants_output(path, provenance);
        break;
      case OutputKind::tree:
        tree_output(path, provenance);
        break;
      case OutputKind::rivers:
        io::write_text_file(path, geojson(rivers_to_geojson(water().rivers, heights())), "rivers", with_crs(provenance));
        say("{} river reaches -> {}", water().rivers.rivers.size(), file_);
        break;
      case OutputKind::lakes:
        io::write_text_file(path, geojson(lakes_to_geojson(water().lakes, heights())), "lakes", with_crs(provenance));
        say("{} lakes -> {}", water().lakes.lakes.size(), file_);
        break;
      case OutputKind::flow_map:
      case OutputKind::erosion_map:
      case OutputKind::deposition_map:
      case OutputKind::wetness_map:
      case OutputKind::water_depth_map:
        splat_output(kind, path, provenance);
        break;
      case OutputKind::splat_map:
        land_splat_output(path, provenance);
        break;
    }
    if (!output.file.empty()) report_.written.push_back(path);
  }

 private:
  template <class... Args>
  void say(fmt::format_string<Args...> format, Args&&... args) {
    report_.lines.push_back(fmt::format(format, std::forward<Args>(args)...));
  }

  nlohmann::json provenance_for(std::size_t index) const {
    nlohmann::json provenance = output_provenance(recipe_, index, options_);
    if (!produced_.statistics.empty()) provenance["statistics"] = produced_.statistics;
    return provenance;
  }

  const Heightfield& heights() const { return *produced_.heights; }

  /// A GeoJSON or mesh output's sidecar provenance, with the outputs' CRS under "crs".
  nlohmann::json with_crs(nlohmann::json provenance) const {
    if (produced_.crs) provenance["crs"] = io::crs_to_sidecar(*produced_.crs);
    return provenance;
  }

  /// A GeoJSON output with the CRS it names (detail::named_crs) as its crs member, so that GIS
  /// tools do not read local metres as longitude and latitude.
  std::string geojson(std::string text) const {
    const std::optional<io::Crs> crs = detail::named_crs(produced_.crs, recipe_.version, true);
    return crs ? io::with_geojson_crs(std::move(text), *crs) : text;
  }

  /// Rivers, lakes and wetness, worked out once for every output that needs them.
  const water::SurfaceWater& water() {
    if (!water_) water_ = scene_surface_water(recipe_, heights(), context_, &produced_.routed);
    return *water_;
  }

  /// The drainage area of a flow map: the routing alone, unless another output needs the rivers,
  /// lakes and wetness too (then theirs, routed once). Those took most of a flow map's time.
  const Grid<double>& drainage_area() {
    if (water_ || std::ranges::any_of(recipe_.outputs, [&](const Output& output) { return needs_surface_water(output); }))
      return water().area_m2;
    if (!area_) area_ = scene_drainage_area(recipe_, heights(), context_, &produced_.routed);
    return *area_;
  }

  bool needs_surface_water(const Output& output) const {
    const OutputKind kind = *resolved_kind(output);
    return output_kind_info(kind).surface_water || (kind == OutputKind::render && draws_surface_water(recipe_));
  }

  /// A *_map output's grid, in its unit (flow_map: log10 of the drainage area in m^2; erosion and
  /// deposition: metres; wetness 0..1; water depth: metres).
  Grid<float> splat_map(OutputKind kind) {
    switch (kind) {
      case OutputKind::flow_map:
        return flow_map(drainage_area());
      case OutputKind::wetness_map:
        return water().wetness;
      case OutputKind::water_depth_map:
        return water().depth_m;
      default: {
        const std::optional<Grid<float>>& layer = kind == OutputKind::erosion_map ? produced_.eroded_m : produced_.deposited_m;
        if (!layer) fail("an {} needs an erode step: add [[shape]] step = \"erode\" (or --erode)", output_kind_name(kind));
        return *layer;
      }
    }
  }

  void splat_output(OutputKind kind, const std::filesystem::path& path, const nlohmann::json& provenance) {
    const Grid<float> map = splat_map(kind);
    io::HeightmapWriteOptions options;
    // 0 to the largest value: masks start at nothing; the sidecar says what 65535 stands for.
    float high = 0.0f;
    for (float v : map.values()) high = std::max(high, v);
    options.range = io::HeightRange{0.0, std::max(static_cast<double>(high), 1e-6)};
    options.compression = recipe_.heightmap_output.compression;
    options.provenance = provenance;
    options.crs = detail::named_crs(produced_.crs, recipe_.version, false);
    io::write_heightmap(path, map, options);
    say("{} {}x{} (0 to {:.4g}) -> {}", output_kind_name(kind), map.width(), map.height(), high, file_);
  }

  void heightmap(const std::filesystem::path& path, const nlohmann::json& provenance) {
    const Engine engine = recipe_.heightmap_output.engine;
    io::HeightmapWriteOptions options;
    if (const auto& range = recipe_.heightmap_output.range_m) options.range = io::HeightRange{(*range)[0], (*range)[1]};
    options.provenance = provenance;
    options.raw_flip_y = recipe_.heightmap_output.raw_flip_y || engine == Engine::unity;  // Unity reads rows bottom-up
    options.compression = recipe_.heightmap_output.compression;
    options.crs = detail::named_crs(produced_.crs, recipe_.version, false);
    std::string engine_note;
    if (engine != Engine::none) {
      const std::string allowed = engine_size_problem(engine, heights().width(), heights().height());
      if (!allowed.empty())
        fail("cannot write {}: heightmap_output.engine {} cannot take {}x{} samples: allowed are {}", file_, engine_name(engine),
             heights().width(), heights().height(), allowed);
      // The scales are the 16-bit range's: the data's own unless one is given.
      if (!options.range) {
        const auto [low, high] = std::minmax_element(heights().values().begin(), heights().values().end());
        options.range = *high > *low ? io::HeightRange{*low, *high} : io::HeightRange{*low, *low + std::max(1.0, std::abs(*low) * 1e-6)};
      }
      EngineImport import = engine_import(engine, heights(), *options.range, path);
      options.engine = std::move(import.sidecar);
      engine_note = std::move(import.note);
    }
    io::write_heightmap(path, heights(), options);
    say("heightmap {}x{} samples of {:.3g} m -> {}", heights().width(), heights().height(), heights().cell_size_m, file_);
    if (!engine_note.empty()) context_.note(engine_note);
  }

  void mesh(const std::filesystem::path& path, const nlohmann::json& provenance) {
    if (produced_.mesh) {
      // A subdivided mesh is draped like a heightfield's: UVs over its footprint seen from above
      // and the band colours of a DEM of it made for the texture alone (1025 samples, whatever
      // DEM the run writes, so the mesh's bytes do not depend on the other outputs).
      TriangleMesh& fine = *produced_.mesh;
      const Heightfield dem = mesh::rasterize(fine, mesh::square_frame(fine, 1025), std::nullopt, context_);
      mesh::set_uvs_over_grid(fine, dem);
      const Image colours = look::band_colour_map(dem, resolved_look(), 2048);
      io::MeshWriteOptions options{with_crs(provenance), true};
      options.base_color = &colours;
      io::write_mesh(path, fine, options);
      say("mesh of {} triangles, band colours {}x{} -> {}", fine.triangle_count(), colours.width(), colours.height(), file_);
      return;
    }
    // The heightfield's mesh has UVs over its extent and the land's band colours as its base
    // colour (a PBR material): at most 2048 texels per side.
    const TriangleMesh surface = mesh::heightfield_to_mesh(heights());
    const Image colours = look::band_colour_map(heights(), resolved_look(), 2048);
    io::MeshWriteOptions options{with_crs(provenance), true};  // vertices at the grid's coordinates
    options.base_color = &colours;
    io::write_mesh(path, surface, options);
    say("mesh of {} triangles, band colours {}x{} -> {}", surface.triangle_count(), colours.width(), colours.height(), file_);
  }

  /// The tile's part of weights made on its apron.
  look::SurfaceWeights crop(const look::SurfaceWeights& apron) const {
    const int dx = produced_.apron_offset[0], dy = produced_.apron_offset[1];
    const int w = heights().width(), h = heights().height();
    const auto cut = [&](const Grid<float>& layer) {
      Grid<float> out(w, h, 0.0f);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out(x, y) = layer(x + dx, y + dy);
      return out;
    };
    return {cut(apron.sand), cut(apron.grass), cut(apron.rock), cut(apron.snow)};
  }

  /// The recipe's look with every value set: its climate, season and weather, then the
  /// renderer's fallbacks.
  look::RenderParams resolved_look() const {
    Recipe looked = recipe_;
    resolve_look(looked);
    return look::with_fallbacks(looked.render);
  }

  /// The land's four band layers as one RGBA PNG: 8-bit weights that sum to exactly 255 at
  /// every pixel (largest remainders get the leftover units), with the heightmap's grid in the
  /// sidecar.
  void land_splat_output(const std::filesystem::path& path, const nlohmann::json& provenance) {
    // A tile's weights come from its apron (slopes across its borders), cut to the tile.
    const look::SurfaceWeights weights = produced_.apron ? crop(look::surface_weights(*produced_.apron, resolved_look()))
                                                         : look::surface_weights(heights(), resolved_look());
    const Image image = look::splat_weights_image(weights);
    const Heightfield& h = heights();
    const nlohmann::json grid = {
        {"kind", "splat_map"},
        {"cell_size_m", h.cell_size_m},
        {"origin", {{"east_m", h.origin_x_m}, {"south_m", h.origin_y_m}}},
        {"axes",
         "sample (i, j) of row j stands at east_m + i * cell_size_m, south_m + j * cell_size_m; rows run north to south (as the "
         "heightmap's)"},
        {"layers",
         {{"r", "sand: beach above the sea, seabed below it"},
          {"g", "grass: the forest band"},
          {"b", "rock: above the tree line and on steep slopes"},
          {"a", "snow: above the snow line on gentle slopes"}}},
        {"encoding", "weights 0..1 as 0..255; r + g + b + a = 255 at every pixel"}};
    io::write_png(path, image, provenance, grid);
    say("splat map {}x{} (sand, grass, rock, snow) -> {}", image.width(), image.height(), file_);
  }

  void render(const std::filesystem::path& path, const look::Camera& camera, const nlohmann::json& provenance) {
    // The look: what the recipe leaves unset comes from its climate, season, weather and time.
    Recipe looked = recipe_;
    looked.render.camera = camera;
    resolve_look(looked);
    budget::check(look::render_cost(looked.render, look::resolved_height(looked.render, heights())));  // before clouds, sky and GL
    // Cliffs and bare rock show a solid texture evaluated at each surface point (seeds/002).
    const std::shared_ptr<const Image> rock = scene_rock(recipe_, heights(), {}, context_);
    look::TerrainLayers layers;
    if (!rock->empty()) layers.cliff_albedo = rock.get();
    // Clouds (the paper's 2-D midpoint-displacement image) and the sky baked with them.
    Stopwatch watch(report_);
    const std::shared_ptr<const SceneSky> sky = scene_sky(looked, {}, context_);
    if (!sky->clouds.empty()) layers.clouds = &sky->clouds;
    layers.sky = &sky->dome;
    watch.lap("clouds and sky");
    // Rivers and lakes: lakes drawn flat at their level, water shaded over the ground.
    const bool with_water = draws_surface_water(recipe_);
    if (with_water) {
      layers.water_depth = &water().depth_m;
      layers.wetness = &water().wetness;
    }
    const Heightfield& ground = with_water ? water().surface : heights();
    watch.lap("rivers and lakes");
    vegetation::Placement plants = plants_for_picture(looked, heights(), context_);
    if (with_water) remove_plants_in_water(plants, water());
    look::PlantKindCache kinds;
    layers.plants = kinds.plants_to_draw(plants, plant_look(looked));
    watch.lap("plants");
    const Image image = paint(ground, looked.render, layers, context_);
    watch.lap("render");
    io::write_png(path, image, provenance);
    watch.lap("png write");
    say("picture {}x{} -> {}", image.width(), image.height(), file_);
  }

  void plants_output(const std::filesystem::path& path, const nlohmann::json& provenance) {
    Recipe looked = recipe_;
    resolve_look(looked);
    const vegetation::Placement plants = place_scene_plants(looked, heights(), context_);
    write_plant_instances(path, plants, provenance);
    say("{} trees and {} ground plants -> {}", plants.trees.size(), plants.ground.size(), file_);
  }

  void tree_output(const std::filesystem::path& path, const nlohmann::json& provenance) {
    if (io::lower_extension(path) == ".png") {
      const Image image = tree_picture(recipe_, context_);
      io::write_png(path, image, provenance);
      say("{} ({}) {}x{} -> {}", recipe_.tree.species, name_of(season_of(recipe_)), image.width(), image.height(), file_);
      return;
    }
    const TriangleMesh plant = tree_mesh_of(recipe_);
    // The glTF's node is named after the species (recipes before version 4: "terrain", their bytes).
    io::write_mesh(path, plant, {provenance, true, nullptr, recipe_.version >= 4 ? recipe_.tree.species : std::string("terrain")});
    say("{} ({}) of {} triangles -> {}", recipe_.tree.species, name_of(season_of(recipe_)), plant.triangle_count(), file_);
  }

  void map(const std::filesystem::path& path, const contour::MapDrawing& drawing, const nlohmann::json& provenance) {
    const io::FileFormat* drawing_format = io::file_format_for(path, io::FormatData::vector, io::Access::write);
    if (drawing_format && drawing_format->name == "svg")
      io::write_text_file(path, io::map_to_svg(drawing), "map", provenance);
    else
      io::write_png(path, contour::rasterize_map(drawing), provenance);
    say("contour map {}x{} -> {}", drawing.width_px, drawing.height_px, file_);
  }

  solid::FieldEvaluator& field() {
    if (!field_) {
      // Checked up front: a Type I field the machine cannot hold is refused before any work.
      field_ = solid::make_evaluator(recipe_.solid.type, recipe_.solid_field, {solid_r2(recipe_), recipe_.solid.reuse}, context_);
    }
    return *field_;
  }

  void solid_output(OutputKind kind, const std::filesystem::path& path, const nlohmann::json& provenance) {
    const solid::SolidTexture texture = solid_texture(recipe_);
    const int size = recipe_.solid.picture_size;
    switch (kind) {
      case OutputKind::slice: {
        const SliceSpec slice = parse_slice(recipe_.solid.slice_at, recipe_.solid_field.levels);
        io::write_png(path, solid::render_slice(field(), texture, slice.axis, slice.position, size, context_), provenance);
        break;
      }
      case OutputKind::sphere:
        io::write_png(path, solid::render_sphere(field(), texture, size, context_), provenance);
        break;
      case OutputKind::cube:
        io::write_png(path, solid::render_cube(field(), texture, size, context_), provenance);
        break;
      default:
        io::write_volume_r32(path, field_volume(field()), provenance, context_);
        break;
    }
    say("solid {} -> {}", output_kind_name(kind), file_);
  }

  const contour::Comparison& comparison() {
    if (!comparison_) {
      contour::CompareParams params = recipe_.compare.measures;
      std::optional<contour::Ring> inside;
      if (!recipe_.compare.inside.empty()) {
        const contour::ContourTree tree =
            contours_from_geojson(io::read_text_file(resolve(recipe_, recipe_.compare.inside)), recipe_.compare.inside);
        if (tree.nodes.empty()) fail("{} holds no contour", recipe_.compare.inside);
        params.inside = tree.nodes[static_cast<std::size_t>(tree.seed)].ring;
      }
      real_ = read_heightmap_with_notes(resolve(recipe_, recipe_.compare.real), context_);
      comparison_ = contour::compare_dems(*real_, heights(), params, context_);
    }
    return *comparison_;
  }

  void comparison_output(const std::filesystem::path& path, bool printed_only, const nlohmann::json& provenance) {
    const contour::Comparison& c = comparison();
    if (!table_printed_) {
      // One report line per row, so that the table prints as a table (a line's own newlines are
      // shown as " / ", as in a file name).
      const std::string table = contour::comparison_table(c);
      for (std::size_t start = 0; start < table.size();) {
        const std::size_t end = std::min(table.find('\n', start), table.size());
        std::string row = table.substr(start, end - start);
        while (!row.empty() && row.back() == ' ') row.pop_back();
        if (!row.empty()) report_.lines.push_back(std::move(row));
        start = end + 1;
      }
      table_printed_ = true;
    }
    if (printed_only) return;
    auto measures = [](const contour::DemMeasures& m) {
      return nlohmann::json{{"cells", m.cells},
                            {"min_m", m.min_m},
                            {"max_m", m.max_m},
                            {"hypsometric_integral", m.hypsometric_integral},
                            {"hypsometry", m.hypsometry},
                            {"mean_slope_deg", m.mean_slope_deg},
                            {"slope_histogram", m.slope_histogram},
                            {"gradient_p50", m.gradient_p50},
                            {"gradient_p90", m.gradient_p90},
                            {"summits", m.summits},
                            {"levels_m", m.levels_m},
                            {"contour_length_m", m.contour_length_m},
                            {"contour_spectrum_slope", m.contour_spectrum_slope},
                            {"dem_spectrum_slope", m.dem_spectrum_slope}};
    };
    const nlohmann::json out{{"real", measures(c.real)},
                             {"generated", measures(c.generated)},
                             {"hypsometric_difference", c.hypsometric_difference},
                             {"slope_distance_deg", c.slope_distance_deg},
                             {"length_ratio", c.length_ratio},
                             {"interval_m", *c.params.interval_m},
                             {"prominence_m", *c.params.prominence_m}};
    io::write_text_file(path, out.dump(2) + "\n", "comparison", provenance);
    say("comparison -> {}", file_);
  }

  /// A contour map of the real or generated DEM at the compared levels (index contours every
  /// 5 levels from the lowest).
  void compared_map(OutputKind kind, const std::filesystem::path& path, const nlohmann::json& provenance) {
    const contour::Comparison& c = comparison();
    std::vector<double> levels = c.real.levels_m;
    if (!levels.empty()) levels.insert(levels.begin(), levels.front() - *c.params.interval_m);
    const Heightfield& dem = kind == OutputKind::map_real ? *real_ : heights();
    map(path, contour::layout_contour_map(contour::contours_of_dem(dem, levels), recipe_.map), provenance);
  }

  const Recipe& recipe_;
  std::string file_;  ///< the output being written, as the report names it
  Produced& produced_;
  const RunOptions& options_;
  const Context& context_;
  RunReport& report_;
  std::unique_ptr<solid::FieldEvaluator> field_;
  std::optional<water::SurfaceWater> water_;
  std::optional<Grid<double>> area_;  ///< drainage_area() without water_
  std::optional<Heightfield> real_;
  std::optional<contour::Comparison> comparison_;
  bool table_printed_ = false;
};

}  // namespace

void check_output_settings(const Recipe& recipe) {
  using O = OutputKind;
  if (any_output(recipe, {O::render})) {
    if (!has_painter()) (void)paint({}, {}, {}, quiet_context());  // refused here, before any work
    recipe.render.validate();
    // Before the terrain too, where the picture's height does not wait for the terrain's aspect.
    if (recipe.render.height || recipe.render.view != look::View::top)
      budget::check(look::render_cost(recipe.render, look::resolved_height(recipe.render, {})));
    recipe.rock.validate();
  }
  if (any_output(recipe, {O::volume, O::sphere, O::cube, O::slice})) {
    recipe.solid_field.validate();
    const int r2 = solid_r2(recipe);
    if (recipe.solid.type == solid::EvaluatorType::type4 && r2 > recipe.solid_field.levels)
      fail("solid.r2 {} is not allowed: it must be 0..R (R = {})", r2, recipe.solid_field.levels);
    (void)solid_texture(recipe);
    if (any_output(recipe, {O::slice})) (void)parse_slice(recipe.solid.slice_at, recipe.solid_field.levels);
    const std::size_t budget =
        recipe.solid.memory_mb > 0.0 ? static_cast<std::size_t>(recipe.solid.memory_mb * 1e6) : available_memory_bytes();
    // Type II's map: the whole lattice for a volume, a picture's pixels' ancestors for the
    // pictures (each drawn with fresh maps, so the largest counts).
    const double side = recipe.solid_field.side();
    const bool volume = any_output(recipe, {O::volume}), pictures = any_output(recipe, {O::sphere, O::cube, O::slice});
    const double nodes = std::max(volume ? side * side * side : 0.0,
                                  pictures ? solid::type2_picture_nodes(recipe.solid_field.levels, recipe.solid.picture_size) : 0.0);
    solid::check_fits(recipe.solid.type, recipe.solid_field, r2, nodes, budget);
    if (recipe.solid.type == solid::EvaluatorType::type2)
      budget::check(solid::type2_cost(recipe.solid_field, nodes,
                                      volume ? std::string("the volume") : fmt::format("{} px pictures", recipe.solid.picture_size)));
  }
  if (const Engine engine = recipe.heightmap_output.engine; engine != Engine::none) {
    const std::vector<std::string> allowed = engine_extensions(engine);
    for (const Output& output : recipe.outputs)
      if (resolved_kind(output) == O::heightmap && std::ranges::find(allowed, io::lower_extension(output.file)) == allowed.end())
        fail("heightmap output {} is not allowed with heightmap_output.engine {}: its importer reads {}", output.file, engine_name(engine),
             fmt::format("{}", fmt::join(allowed, " ")));
  }
  if (any_output(recipe, {O::comparison, O::map_real, O::map_generated}) && recipe.compare.real.empty())
    fail("compare.real is missing: a comparison needs the real DEM");
}

void write_outputs(const Recipe& recipe, Produced& produced, const RunOptions& options, const Context& context, RunReport& report) {
  Writer writer(recipe, produced, options, context, report);
  for (std::size_t i = 0; i < recipe.outputs.size(); ++i) writer.write(i);
}

}  // namespace sansui::scene::detail
