// The page's WebAssembly module (docs/web.md): the library's recipe, evaluator, look and writers
// behind a small embind API that the page's worker (web/page/worker.js) calls. Nothing here
// computes terrain or colours of its own: a session holds a recipe, sets its values through the
// parameter tables (as the viewer's panels and the CLI's options do), makes its heights with
// scene::recipe_heights through one Evaluator (so a change that leaves the terrain's key alone
// costs nothing), resolves its look with scene::resolve_look, and writes downloads with
// scene::run_recipe into the module's in-memory file system, exactly as `sansui run` writes them.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <emscripten/bind.h>
#include <emscripten/emscripten.h>
#include <emscripten/threading.h>
#include <emscripten/val.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/params.hpp"
#include "look/colour_space.hpp"
#include "look/render_params.hpp"
#include "look/sky_dome.hpp"
#include "look/sky_model.hpp"
#include "look/surface_layers.hpp"
#include "scene/evaluator.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/recipe.hpp"
#include "scene/recipe_file.hpp"
#include "vegetation/placement.hpp"
#include "vegetation/species.hpp"

namespace sansui::web {
namespace {

namespace fs = std::filesystem;
using emscripten::val;
using json = nlohmann::json;

/// Where the module keeps its files: dropped drawings, and downloads as `sansui run` writes them.
const fs::path work_dir = "/work";
const fs::path out_dir = "/work/out";

/// The page's high-level controls, in order: rows of the recipe's table (and the shaping step's
/// `stage`, as `shape.stage`), as the viewer's "High level" panel lists them.
constexpr std::string_view control_keys[] = {"world.size",      "midpoint.seed", "midpoint.hurst", "climate.koppen", "season.season",
                                             "weather.weather", "time.time",     "shape.stage",    "world.sea_level"};
constexpr std::string_view shape_prefix = "shape.";

/// The largest world the page makes: 1025 samples per side (the CLI makes larger ones).
constexpr long long page_max_size = 1025;

json limits_json(const params::ParamInfo& row) {
  json limits = json::object();
  if (row.limits.min) limits["min"] = *row.limits.min;
  if (row.limits.max) limits["max"] = *row.limits.max;
  if (row.limits.min_exclusive) limits["min_exclusive"] = true;
  if (row.limits.max_exclusive) limits["max_exclusive"] = true;
  if (!row.limits.choices.empty()) limits["choices"] = row.limits.choices;
  if (!row.limits.rule_text.empty()) limits["rule"] = row.limits.rule_text;
  return limits;
}

/// One control: the row as the tables have it, and its value in `recipe` (and, for rows left
/// unset, the value the look derives: `looked`).
json control_json(const params::ParamInfo& row, const params::Value& value, const params::Value& derived) {
  const bool unset = std::holds_alternative<std::monostate>(value);
  return {{"key", row.key},
          {"kind", params::kind_name(row.kind)},
          {"unit", row.unit},
          {"help", row.help},
          {"group", row.group},
          {"optional", row.optional},
          {"unset_means", row.unset_means},
          {"allowed", params::allowed_text(row)},
          {"limits", limits_json(row)},
          {"value", unset ? "" : params::format_value(value)},
          {"derived", std::holds_alternative<std::monostate>(derived) ? "" : params::format_value(derived)}};
}

std::string first_line(std::string_view text) {
  return std::string(text.substr(0, text.find('\n')));
}

std::vector<std::uint8_t> read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A linear colour as 8-bit sRGB, for the page's textures and uniforms.
std::uint8_t srgb_byte(float linear) {
  const float c = std::max(0.0f, std::min(1.0f, linear));
  const float encoded = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

json rgb_json(const Rgb& colour) {
  return json::array({colour.r, colour.g, colour.b});
}

/// A tree's crown in `season`: its leaves' colour of the season, or its bark when a deciduous
/// tree stands bare in winter.
Rgb crown_colour(const vegetation::Species& species, Season season) {
  if (species.habit == vegetation::Habit::evergreen) return species.leaf_colour;
  switch (season) {
    case Season::spring:
      return species.spring_colour;
    case Season::autumn:
      return species.autumn_colour;
    case Season::winter:
      return species.bark;
    default:
      return species.leaf_colour;
  }
}

}  // namespace

/// One page's world: a recipe, the heights made from it, and what the page draws them with.
class Session {
 public:
  Session() { reset(); }

  /// A fresh midpoint world with the default erosion step, as the viewer's "New midpoint terrain".
  void reset() {
    recipe_ = scene::default_recipe(scene::SourceKind::midpoint);
    recipe_.shape.push_back(scene::default_erode_step());
    recipe_.world.size = 513;
    recipe_.base_dir = work_dir;
    scene::settle_world(recipe_);
    fs::create_directories(out_dir);
  }

  /// The controls of the page, from the parameter tables: JSON array of rows with their values.
  std::string controls() const {
    scene::Recipe looked = recipe_;
    try {
      scene::resolve_look(looked);
    } catch (const std::exception&) {
      looked = recipe_;  // a look that cannot be resolved shows no derived values
    }
    json rows = json::array();
    for (std::string_view key : control_keys) {
      if (key.starts_with(shape_prefix)) {
        const auto* row = params::table_of<scene::ShapeStep>().find(key.substr(shape_prefix.size()));
        if (row == nullptr || recipe_.shape.empty()) continue;
        json control = control_json(*row, row->get(recipe_.shape.front()), row->get(recipe_.shape.front()));
        control["key"] = std::string(key);
        rows.push_back(std::move(control));
        continue;
      }
      const auto* row = scene::recipe_table().find(key);
      if (row == nullptr || !scene::reads_key(recipe_, *row)) continue;
      json control = control_json(*row, row->get(recipe_), row->get(looked));
      if (key == "world.size") control["page_max"] = page_max_size;
      rows.push_back(std::move(control));
    }
    return rows.dump();
  }

  /// Sets `key` to `text` as a scene file would ("" unsets an optional value). Returns "" or the
  /// message for the page (the recipe is left as it was).
  std::string set(const std::string& key, const std::string& text) {
    try {
      if (key.starts_with(shape_prefix)) {
        const auto* row = params::table_of<scene::ShapeStep>().find(std::string_view(key).substr(shape_prefix.size()));
        if (row == nullptr) fail("unknown key {}", key);
        scene::Recipe changed = recipe_;
        if (changed.shape.empty()) changed.shape.push_back(scene::default_erode_step());
        const params::Value value = text.empty() ? params::Value{} : params::parse_text(*row, text, key);
        if (!text.empty()) params::require_allowed(*row, value, key);
        row->set(changed.shape.front(), value);
        scene::settle_world(changed);
        recipe_ = std::move(changed);
        return "";
      }
      const auto* row = scene::recipe_table().find(key);
      if (row == nullptr) fail("unknown key {}", key);
      const params::Value value = text.empty() ? params::Value{} : params::parse_text(*row, text, key);
      if (!text.empty()) params::require_allowed(*row, value, key);
      if (key == "world.size" && std::holds_alternative<std::int64_t>(value) && std::get<std::int64_t>(value) > page_max_size)
        fail(
            "world.size {} is larger than this page makes ({} samples per side): the sansui command-line tool makes it "
            "from the recipe (Download recipe)",
            text, page_max_size);
      scene::Recipe changed = recipe_;
      row->set(changed, value);
      scene::settle_world(changed);
      recipe_ = std::move(changed);
      return "";
    } catch (const std::exception& e) {
      return first_line(e.what());
    }
  }

  /// Calls `callback(stage, fraction)` while the heights are made (at most 20 times a second).
  void set_progress(val callback) { progress_ = std::move(callback); }

  /// Makes the heights and the look of the recipe. Returns JSON: {"error": ...} or the world's
  /// facts (size, cell, range, sea level, seconds) and its look (sun, sky, sea, lines).
  std::string build() {
    const auto start = std::chrono::steady_clock::now();
    try {
      Context context;
      double last_report = -1.0;
      context.on_progress = [&](std::string_view stage, double fraction) {
        // A report from a worker thread of the threaded module is dropped: JavaScript values
        // belong to the module's own thread, whose next report shows the progress.
        if (emscripten_is_main_runtime_thread() == 0) return;
        const double now = emscripten_get_now();
        if (progress_.isUndefined() || (now - last_report < 50.0 && fraction < 1.0)) return;
        last_report = now;
        progress_(std::string(stage), fraction);
      };
      heights_ = scene::recipe_heights(recipe_, evaluator_, context);
      ++built_;
      const double heights_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      json facts = look(*heights_);
      facts["heights_seconds"] = heights_seconds;
      facts["threads"] = parallel_detail::thread_slots();  // 1 in the serial module
      facts["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return facts.dump();
    } catch (const Cancelled&) {
      return json{{"error", "cancelled"}}.dump();
    } catch (const std::exception& e) {
      heights_.reset();
      return json{{"error", first_line(e.what())}}.dump();
    }
  }

  /// The heights (metres, row-major, row 0 the north row) as a Float32Array over the module's
  /// memory: copy it before calling into the module again.
  val heights() const {
    if (!heights_) return val::null();
    return val(emscripten::typed_memory_view(heights_->size(), heights_->data()));
  }

  /// The look's band colours (sRGB RGBA8, one texel per sample): look::band_colour_map.
  val colours() const { return val(emscripten::typed_memory_view(colours_.size(), colours_.data())); }

  /// The sky around the viewer (look::bake_sky_dome) as sRGB RGBA8, width x height in look().
  val sky() const { return val(emscripten::typed_memory_view(sky_.size(), sky_.data())); }

  /// The recipe as the TOML scene file that `sansui run` turns into the same heightmaps: outputs
  /// heightmap.png (16-bit) and heightmap.r32, each with its JSON sidecar.
  std::string recipe_toml() const {
    return scene::recipe_to_toml(with_downloads(),
                                 "# Made in the Sansui page (docs/web.md): `sansui run` this file for the same heightmaps.\n");
  }

  /// Writes the downloads with scene::run_recipe, as `sansui run` writes them (the heights come
  /// from the evaluator's memory). Returns JSON: {"files": [names]} or {"error": ...}.
  std::string write_downloads() {
    try {
      fs::remove_all(out_dir);
      scene::RunOptions options;
      options.evaluator = shared_evaluator();
      options.provenance = {{"program", "sansui-web"}, {"version", SANSUI_VERSION}, {"command", "page"}};
      scene::Recipe recipe = scene::with_outputs_in(with_downloads(), out_dir);
      const scene::RunReport report = scene::run_recipe(recipe, options);
      json files = json::array();
      for (const auto& file : report.written) {
        files.push_back(file.filename().string());
        files.push_back(file.filename().string() + ".json");
      }
      return json{{"files", files}}.dump();
    } catch (const std::exception& e) {
      return json{{"error", first_line(e.what())}}.dump();
    }
  }

  /// The bytes of a file that write_downloads() wrote.
  val download(const std::string& name) {
    download_ = read_bytes(out_dir / fs::path(name).filename());
    return val(emscripten::typed_memory_view(download_.size(), download_.data()));
  }

  /// A dropped contour drawing (GeoJSON or SVG, its name and text): the world becomes a contour
  /// mountain grown from it (seed 000), on a grid of the current world's size. Returns "" or the
  /// message for the page (the world stays as it was).
  std::string use_contour(const std::string& name, const std::string& text) {
    const std::string extension = fs::path(name).extension().string();
    const fs::path file = work_dir / ("drawing" + (extension.empty() ? std::string(".geojson") : extension));
    std::ofstream(file, std::ios::binary) << text;
    scene::Recipe changed = scene::default_recipe(scene::SourceKind::contour);
    changed.base_dir = work_dir;
    changed.contour_seed.file = file.filename().string();
    changed.dem.size = static_cast<int>(recipe_.world.size);
    changed.climate = recipe_.climate;
    changed.season = recipe_.season;
    changed.weather = recipe_.weather;
    changed.time = recipe_.time;
    try {
      scene::Recipe previous = std::move(recipe_);
      recipe_ = std::move(changed);
      const std::string built = build();
      if (json::parse(built).contains("error")) {
        recipe_ = std::move(previous);
        return json::parse(built)["error"].get<std::string>();
      }
      return "";
    } catch (const std::exception& e) {
      return first_line(e.what());
    }
  }

  std::string source() const { return std::string(scene::source_name(recipe_.source)); }

  /// The trees of strip `strip` of `strips` (rows of the world last built, north to south),
  /// placed by the library as the whole world places them (vegetation::place_plants keys each
  /// plant by its world position, and a strip owns the half-open rows it starts), the ground
  /// layer left out (grass is far below a pixel here). The page asks strip by strip, so a change
  /// made meanwhile waits for one strip, not for the whole placement. A Float32Array over the
  /// module's memory of nine values a tree: east and south of sample (0, 0) and the ground's
  /// height (metres), the tree's height and crown radius (metres), its crown colour in the
  /// season (sRGB 0..1) and its shape (0 a cone, 1 a rounded crown).
  val plants(int strip, int strips) {
    if (!heights_ || strips < 1 || strip < 0 || strip >= strips) return val::null();
    const Heightfield& whole = *heights_;
    if (plants_built_ != built_ || !plant_rules_) {
      plant_recipe_ = recipe_;
      scene::resolve_look(plant_recipe_);
      plant_recipe_.vegetation.ground_density = 0.0;
      plant_rules_ = scene::placement_rules(plant_recipe_, whole);
      plants_built_ = built_;
    }
    plants_.clear();
    if (!plant_recipe_.vegetation.enabled) return val(emscripten::typed_memory_view(plants_.size(), plants_.data()));
    // Rows [first, last]: the strip's own, and the next strip's first row, which it does not own.
    const int rows = whole.height() - 1;
    const int first = strip * rows / strips, last = (strip + 1) * rows / strips;
    Heightfield part = Heightfield::uninitialized(whole.width(), last - first + 1, whole.cell_size_m);
    part.origin_x_m = whole.origin_x_m;
    part.origin_y_m = whole.origin_y_m + first * whole.cell_size_m;
    for (int y = first; y <= last; ++y)
      for (int x = 0; x < whole.width(); ++x) part(x, y - first) = whole(x, y);
    const vegetation::Placement placement = vegetation::place_plants(part, plant_recipe_.vegetation, *plant_rules_);
    const Season season = scene::season_of(plant_recipe_);
    for (const vegetation::Instance& tree : placement.trees) {
      const vegetation::Species& species = placement.library()[tree.species];
      const double height = species.height_m * tree.scale;
      const bool cone = species.form == vegetation::Form::conifer;
      const Rgb crown = crown_colour(species, season);
      plants_.insert(plants_.end(), {static_cast<float>(tree.x_m - whole.origin_x_m), static_cast<float>(tree.y_m - whole.origin_y_m),
                                     tree.height_m, static_cast<float>(height), static_cast<float>(height * (cone ? 0.22 : 0.36)), crown.r,
                                     crown.g, crown.b, cone ? 0.0f : 1.0f});
    }
    return val(emscripten::typed_memory_view(plants_.size(), plants_.data()));
  }

 private:
  scene::Recipe with_downloads() const {
    scene::Recipe recipe = recipe_;
    recipe.outputs = {{"heightmap.png", scene::OutputKind::heightmap, {}, {}}, {"heightmap.r32", scene::OutputKind::heightmap, {}, {}}};
    return recipe;
  }

  std::shared_ptr<scene::Evaluator> shared_evaluator() {
    return std::shared_ptr<scene::Evaluator>(std::shared_ptr<void>(), &evaluator_);  // not owned: the session's own
  }

  /// The look of `heights`: band colours and sky as textures, and the values the page's shader
  /// takes, all from look/ through the scene's resolved look.
  json look(const Heightfield& heights) {
    scene::Recipe looked = recipe_;
    scene::resolve_look(looked);
    const look::RenderParams resolved = look::with_fallbacks(looked.render);
    const Image bands = look::band_colour_map(heights, resolved, static_cast<int>(page_max_size));
    colours_.assign(reinterpret_cast<const std::uint8_t*>(bands.data()),
                    reinterpret_cast<const std::uint8_t*>(bands.data()) + bands.size() * 4);
    constexpr int sky_width = 256, sky_height = 64;
    // The sky is baked again only when what it is made from changes (not for new heights).
    if (const std::string key = scene::sky_key(looked); key != sky_key_) {
      const look::SkyDome dome = look::bake_sky_dome(resolved, nullptr, sky_width, sky_height);
      sky_.resize(dome.rgba.size());
      for (std::size_t k = 0; k < dome.rgba.size(); k += 4) {
        for (std::size_t c = 0; c < 3; ++c) sky_[k + c] = srgb_byte(dome.rgba[k + c]);
        sky_[k + 3] = 255;
      }
      sky_light_ = {srgb_byte(dome.sky_light.x) / 255.0, srgb_byte(dome.sky_light.y) / 255.0, srgb_byte(dome.sky_light.z) / 255.0};
      sky_key_ = key;
    }
    const double sun_azimuth = resolved.sun_azimuth_deg.value_or(180.0), sun_elevation = resolved.sun_elevation_deg.value_or(45.0);
    const glm::vec3 sun = look::direction_of(sun_azimuth, sun_elevation);
    float low = heights.values().empty() ? 0.0f : heights.values()[0], high = low;
    for (float h : heights.values()) low = std::min(low, h), high = std::max(high, h);
    return {{"width", heights.width()},
            {"height", heights.height()},
            {"cell_m", heights.cell_size_m},
            {"min_m", low},
            {"max_m", high},
            {"sea_level_m", look::effective_sea_level(resolved, heights)},
            {"sea", resolved.sea},
            {"exaggeration", resolved.exaggeration},
            {"colours", {{"width", bands.width()}, {"height", bands.height()}}},
            {"sky", {{"width", sky_width}, {"height", sky_height}, {"top_deg", look::dome_top_deg}, {"bottom_deg", look::dome_bottom_deg}}},
            {"sun", {{"azimuth_deg", sun_azimuth}, {"elevation_deg", sun_elevation}, {"direction", {sun.x, sun.y, sun.z}}}},
            {"sun_colour", rgb_json(look::sun_colour(sun_elevation))},
            {"sky_light", sky_light_},
            {"water_shallow", rgb_json(resolved.water.shallow.value_or(Rgb{0.2f, 0.45f, 0.5f}))},
            {"water_deep", rgb_json(resolved.water.deep.value_or(Rgb{0.05f, 0.15f, 0.3f}))},
            {"source", std::string(scene::source_name(recipe_.source))}};
  }

  scene::Recipe recipe_;
  scene::Evaluator evaluator_;
  std::shared_ptr<const Heightfield> heights_;
  std::vector<std::uint8_t> colours_, sky_, download_;
  std::string sky_key_;             ///< what sky_ was baked from (scene::sky_key)
  std::uint64_t built_ = 0;         ///< heights made so far
  std::uint64_t plants_built_ = 0;  ///< the heights plant_rules_ were made for
  scene::Recipe plant_recipe_;      ///< the recipe's look resolved, without the ground layer
  std::optional<vegetation::PlacementRules> plant_rules_;
  std::vector<float> plants_;
  json sky_light_;
  val progress_ = val::undefined();
};

}  // namespace sansui::web

EMSCRIPTEN_BINDINGS(sansui_web) {
  using sansui::web::Session;
  emscripten::class_<Session>("Session")
      .constructor<>()
      .function("reset", &Session::reset)
      .function("controls", &Session::controls)
      .function("set", &Session::set)
      .function("setProgress", &Session::set_progress)
      .function("build", &Session::build)
      .function("heights", &Session::heights)
      .function("colours", &Session::colours)
      .function("sky", &Session::sky)
      .function("recipeToml", &Session::recipe_toml)
      .function("writeDownloads", &Session::write_downloads)
      .function("download", &Session::download)
      .function("useContour", &Session::use_contour)
      .function("source", &Session::source)
      .function("plants", &Session::plants);
}
