#include "viewer/viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <utility>

#include <epoxy/gl.h>

#include <fmt/format.h>
#include <imgui.h>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "io/mesh_io.hpp"
#include "mesh/heightfield_mesh.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::viewer {
namespace {

/// The provenance the viewer's exports record.
scene::RunOptions viewer_run_options() {
  scene::RunOptions options;
  options.provenance = nlohmann::json{{"program", "sansui-viewer"}, {"version", SANSUI_VERSION}};
  return options;
}

constexpr std::size_t max_recent = 8;
// The view counts as still this long after its last change (then it is drawn at full resolution).
constexpr double settle_seconds = 0.3;
constexpr const char* shape_prefix = "shape.";

std::filesystem::path recent_list_file() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  const char* home = std::getenv("HOME");
  if (config != nullptr && *config != '\0') return std::filesystem::path(config) / "sansui" / "viewer-recent.txt";
  if (home != nullptr && *home != '\0') return std::filesystem::path(home) / ".config" / "sansui" / "viewer-recent.txt";
  return {};
}

/// One line: a message from an exception may span several.
std::string first_line(std::string text) {
  const auto end = text.find('\n');
  if (end != std::string::npos) text.resize(end);
  return text;
}

}  // namespace

namespace {

/// Plant levels of detail for the panes: the renderer's defaults budget a second of software
/// rasterising for a picture; a window moving under the mouse gets a tenth of that.
look::PlantLodLimits interactive_plant_limits(bool moving = false) {
  look::PlantLodLimits limits;
  limits.full_triangle_budget = 100'000;
  limits.simplified_triangle_budget = 150'000;
  // While the view moves, far trees are thinned harder (the area they cover stays the same).
  if (moving) limits.thin_below_px = 4.0f;
  return limits;
}

}  // namespace

Viewer::Viewer(ViewerOptions options) : options_(options), renderer_(std::make_unique<render::TerrainRenderer>()) {
  renderer_->set_plant_limits(interactive_plant_limits());
  if (options_.remember_recent) {
    std::ifstream list(recent_list_file());
    for (std::string line; std::getline(list, line) && recent_.size() < max_recent;)
      if (!line.empty()) recent_.emplace_back(line);
  }
  new_scene(scene::SourceKind::midpoint);
}

Viewer::~Viewer() = default;

// ---- actions -------------------------------------------------------------------------------

void Viewer::new_scene(scene::SourceKind source) {
  recipe_ = scene::default_recipe(source);
  if (source == scene::SourceKind::midpoint) recipe_.shape.push_back({});
  recipe_.base_dir = std::filesystem::current_path();
  scene_file_.clear();
  walker_.reset();
  builder_.forget();
  request();
}

bool Viewer::open(const std::filesystem::path& file) {
  try {
    scene::LoadedRecipe loaded = scene::load_recipe(file);
    scene::Recipe next = std::move(loaded.recipe);
    if (next.source == scene::SourceKind::none && next.nodes.empty())
      fail("{} has no source of heights: the viewer shows terrain (give [midpoint], [file], [contour_seed], [mesh] or [[node]] tables)",
           file.string());
    scene::check_recipe(next.outputs.empty() ? [&] {
      scene::Recipe probe = next;  // outputs are checked only when there are some
      probe.outputs.push_back({"probe.png", scene::OutputKind::render, {}, {}});
      probe.base_dir = std::filesystem::temp_directory_path();
      probe.output_rules.confined_to.clear();  // the probe is never written, and lies outside the scene's folder
      return probe;
    }()
                                             : next);
    recipe_ = std::move(next);
    scene_file_ = file;
    walker_.reset();
    error_.clear();
    status_ = fmt::format("opened {}", file.string());
    for (const std::string& warning : loaded.warnings) status_ += "; " + warning;
    remember(file);
    builder_.forget();
    request();
    return true;
  } catch (const std::exception& e) {
    show_error(fmt::format("could not open {}: {} (the current scene stays)", file.string(), first_line(e.what())));
    return false;
  }
}

bool Viewer::save(const std::filesystem::path& file) {
  try {
    scene::Recipe saved = recipe_;
    // The camera the perspective pane shows, and a render output, so that `sansui run FILE`
    // draws the picture this viewer shows.
    if (walker_ && heights_)
      saved.render.camera = walker_camera(*walker_, renderer_->width_m(), renderer_->depth_m(), recipe_.render.camera.fov_deg, 0.0);
    saved.render.view = look::View::perspective;
    const bool has_render = std::any_of(saved.outputs.begin(), saved.outputs.end(),
                                        [](const scene::Output& o) { return scene::resolved_kind(o) == scene::OutputKind::render; });
    if (!has_render) saved.outputs.push_back({file.stem().string() + ".png", scene::OutputKind::render, {}, {}});
    // Inputs keep pointing at the same files; outputs are written beside the saved scene, as
    // their names say.
    const std::filesystem::path directory = std::filesystem::absolute(file).parent_path();
    const std::filesystem::path base = std::filesystem::absolute(saved.base_dir.empty() ? std::filesystem::current_path() : saved.base_dir);
    for (scene::Output& output : saved.outputs)
      if (!output.file.empty() && std::filesystem::path(output.file).is_relative())
        output.file = std::filesystem::relative(directory / output.file, base).string();  // save_recipe makes it relative again
    scene::save_recipe(file, saved);
    scene_file_ = file;
    status_ = fmt::format("saved {}", file.string());
    remember(file);
    return true;
  } catch (const std::exception& e) {
    show_error(fmt::format("could not save {}: {} (the scene is kept)", file.string(), first_line(e.what())));
    return false;
  }
}

bool Viewer::set_value(std::string_view key, std::string_view text) {
  try {
    RowEdit edit{std::string(key), {}};
    if (key.starts_with(shape_prefix)) {
      const auto* row = params::table_of<scene::ShapeStep>().find(key.substr(std::string_view(shape_prefix).size()));
      if (row == nullptr) fail("unknown key {}: the stage step has {}", key, "shape.step, shape.stage, ...");
      if (!text.empty()) edit.value = params::parse_text(*row, text, key);
    } else {
      const auto* row = scene::recipe_table().find(key);
      if (row == nullptr) {
        std::vector<std::string> keys;
        for (const auto& r : scene::recipe_table().rows) keys.push_back(r.key);
        const auto near = scene::nearest_key(key, keys);
        fail("unknown key {}{}", key, near ? fmt::format(" (did you mean {}?)", *near) : std::string());
      }
      if (!text.empty()) edit.value = params::parse_text(*row, text, key);
    }
    apply(edit);
    return true;
  } catch (const std::exception& e) {
    show_error(first_line(e.what()));
    return false;
  }
}

void Viewer::apply(const RowEdit& edit) {
  const std::string_view key = edit.key;
  if (key.starts_with(shape_prefix)) {
    const auto* row = params::table_of<scene::ShapeStep>().find(key.substr(std::string_view(shape_prefix).size()));
    if (row == nullptr) return;
    if (recipe_.shape.empty()) recipe_.shape.push_back({});
    if (!std::holds_alternative<std::monostate>(edit.value)) {
      params::require_allowed(*row, edit.value, key);
      row->set(recipe_.shape.front(), edit.value);
    }
    scene::settle_world(recipe_);
    request();
    return;
  }
  const auto* row = scene::recipe_table().find(key);
  if (row == nullptr) return;
  if (!std::holds_alternative<std::monostate>(edit.value)) params::require_allowed(*row, edit.value, key);
  scene::Recipe changed = recipe_;
  row->set(changed, edit.value);
  scene::settle_world(changed);
  recipe_ = std::move(changed);
  if (key == "render.view") single_view_ = recipe_.render.view;
  request();
}

void Viewer::set_orbit(double azimuth_deg, double elevation_deg, double distance) {
  walker_.reset();
  look::Camera& camera = recipe_.render.camera;
  camera.azimuth_deg = azimuth_deg;
  camera.elevation_deg = std::clamp(elevation_deg, 1.0, 89.0);
  camera.distance = distance <= 0.0 ? 0.0 : std::clamp(distance, 0.05, 20.0);
  camera.eye_height_m.reset();
}

void Viewer::orbit_by(double degrees) {
  if (walker_) return;
  look::Camera& camera = recipe_.render.camera;
  camera.azimuth_deg = std::fmod(camera.azimuth_deg + degrees + 360.0, 360.0);
}

void Viewer::start_walk(double x, double y, double bearing_deg) {
  Walker walker;
  walker.x_m = std::clamp(x, 0.0, 1.0) * renderer_->width_m();
  walker.z_m = std::clamp(y, 0.0, 1.0) * renderer_->depth_m();
  walker.bearing_deg = bearing_deg;
  walker.speed_m_s = std::max(renderer_->width_m(), renderer_->depth_m()) / 60.0;  // a minute across
  if (!walker_) orbit_camera_ = recipe_.render.camera;
  walker_ = walker;
  walk_by(0.0, 0.0);
}

double Viewer::start_walk_toward(double x0, double y0, double x1, double y1) {
  const double dx = (x1 - x0) * renderer_->width_m(), dz = (y1 - y0) * renderer_->depth_m();
  // Bearing clockwise from north; z points south.
  start_walk(x0, y0, std::atan2(dx, -dz) * 180.0 / std::numbers::pi);
  return std::hypot(dx, dz);
}

void Viewer::turn(double yaw_deg, double pitch_deg) {
  if (!walker_) return;
  look(*walker_, yaw_deg, pitch_deg);
  update_walker_camera();
}

void Viewer::stop_walk() {
  if (walker_) recipe_.render.camera = orbit_camera_;
  walker_.reset();
}

double Viewer::terrain_height_m(double x_m, double z_m) const {
  // Bilinear on the full-resolution heights: the walker's eye stays above detail the drawn
  // (averaged) mesh does not show.
  const Heightfield& h = *heights_;
  const double fx = std::clamp(x_m / h.cell_size_m, 0.0, h.width() - 1.0), fz = std::clamp(z_m / h.cell_size_m, 0.0, h.height() - 1.0);
  const int x0 = std::min(static_cast<int>(fx), h.width() - 2), z0 = std::min(static_cast<int>(fz), h.height() - 2);
  const double u = fx - x0, v = fz - z0;
  return (1 - v) * ((1 - u) * h(x0, z0) + u * h(x0 + 1, z0)) + v * ((1 - u) * h(x0, z0 + 1) + u * h(x0 + 1, z0 + 1));
}

double Viewer::time_of_day_hours() const {
  int hours = 0, minutes = 0;
  if (std::sscanf(recipe_.time.time.c_str(), "%d:%d", &hours, &minutes) != 2) return 12.0;  // NOLINT(cert-err34-c): checked by the table
  return hours + minutes / 60.0;
}

void Viewer::walk_by(double forward_m, double right_m) {
  if (!walker_ || !heights_) return;
  walk(*walker_, forward_m, right_m, renderer_->width_m(), renderer_->depth_m());
  update_walker_camera();
}

void Viewer::update_walker_camera() {
  const look::RenderParams params = pane_params(look::View::perspective, 16, 16);
  const double sea = params.sea_level_m, scale = params.exaggeration;
  const double drawn_ground = (std::max(renderer_->ground_height_m(walker_->x_m, walker_->z_m), sea) - sea) * scale;
  const double terrain = (std::max(terrain_height_m(walker_->x_m, walker_->z_m), sea) - sea) * scale;
  // Where the finer terrain stands above the drawn mesh, the eye rises with it.
  const double extra = std::max(terrain - drawn_ground, 0.0);
  recipe_.render.camera = walker_camera(*walker_, renderer_->width_m(), renderer_->depth_m(), recipe_.render.camera.fov_deg, extra);
  const double eye = drawn_ground + *recipe_.render.camera.eye_height_m;
  walk_log_.push_back(
      {{"x_m", walker_->x_m}, {"z_m", walker_->z_m}, {"eye_y", eye}, {"drawn_ground_y", drawn_ground}, {"terrain_y", terrain}});
}

bool Viewer::export_heightmap(const std::filesystem::path& file) {
  try {
    if (!heights_) fail("no terrain yet: wait for it to be built");
    io::HeightmapWriteOptions options;
    scene::Recipe r = recipe_;
    r.outputs = {{file.string(), scene::OutputKind::heightmap, {}, {}}};
    options.provenance = scene::output_provenance(r, 0, viewer_run_options());
    io::write_heightmap(file, *heights_, options);
    status_ = fmt::format("heightmap -> {}", file.string());
    return true;
  } catch (const std::exception& e) {
    show_error(fmt::format("could not export {}: {}", file.string(), first_line(e.what())));
    return false;
  }
}

bool Viewer::export_mesh(const std::filesystem::path& file) {
  try {
    if (!heights_) fail("no terrain yet: wait for it to be built");
    scene::Recipe r = recipe_;
    r.outputs = {{file.string(), scene::OutputKind::mesh, {}, {}}};
    const nlohmann::json provenance = scene::output_provenance(r, 0, viewer_run_options());
    io::write_mesh(file, mesh::heightfield_to_mesh(*heights_), {provenance, true});
    status_ = fmt::format("mesh -> {}", file.string());
    return true;
  } catch (const std::exception& e) {
    show_error(fmt::format("could not export {}: {}", file.string(), first_line(e.what())));
    return false;
  }
}

bool Viewer::export_render(const std::filesystem::path& file) {
  try {
    if (!heights_) fail("no terrain yet: wait for it to be built");
    io::check_writable(file);
    // The perspective pane's picture at the scene's picture size and antialiasing.
    look::RenderParams params =
        pane_params(look::View::perspective, recipe_.render.width, look::resolved_height(recipe_.render, *heights_));
    params.samples = recipe_.render.samples;
    const render::OffscreenTarget target(params.width, *params.height, params.samples);
    renderer_->set_plant_limits({});  // the picture `sansui render` draws
    renderer_->draw(params, params.width, *params.height);
    renderer_->set_plant_limits(interactive_plant_limits());
    const Image image = target.read_pixels();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    scene::Recipe r = recipe_;
    r.outputs = {{file.string(), scene::OutputKind::render, {}, {}}};
    io::write_png(file, image, scene::output_provenance(r, 0, viewer_run_options()));
    status_ = fmt::format("picture {}x{} -> {}", image.width(), image.height(), file.string());
    return true;
  } catch (const std::exception& e) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    show_error(fmt::format("could not export {}: {}", file.string(), first_line(e.what())));
    return false;
  }
}

bool Viewer::save_screenshot(const std::filesystem::path& file) {
  try {
    if (last_window_.empty()) fail("nothing drawn yet");
    io::write_png(file, last_window_);
    status_ = fmt::format("screenshot -> {}", file.string());
    return true;
  } catch (const std::exception& e) {
    show_error(fmt::format("could not write the screenshot {}: {}", file.string(), first_line(e.what())));
    return false;
  }
}

void Viewer::show_error(std::string message) {
  error_ = std::move(message);
  errors_shown_.push_back(error_);
}

void Viewer::remember(const std::filesystem::path& file) {
  const std::filesystem::path absolute = std::filesystem::absolute(file);
  std::erase(recent_, absolute);
  recent_.push_front(absolute);
  if (recent_.size() > max_recent) recent_.pop_back();
  if (!options_.remember_recent) return;
  const std::filesystem::path list = recent_list_file();
  if (list.empty()) return;
  std::error_code ignored;  // a list that cannot be kept is no reason to stop
  std::filesystem::create_directories(list.parent_path(), ignored);
  std::ofstream out(list);
  for (const auto& path : recent_) out << path.string() << '\n';
}

// ---- building and uploading ----------------------------------------------------------------

void Viewer::request() {
  // The look is cheap to resolve: the panes draw new colours at once; the builder redoes what
  // takes time, which is what the change made stale (each thing it builds has the key of what
  // it is made from).
  looked_ = recipe_;
  Stale stale;
  try {
    scene::resolve_look(looked_);
    stale = builder_.request(recipe_);
  } catch (const std::exception& e) {
    show_error(first_line(e.what()));
    return;
  }
  // New heights are drawn when they arrive (upload); anything else may change the picture now.
  if (!stale.heights) ++version_;
  if (stale.heights) heights_requested_ = std::chrono::steady_clock::now();
}

void Viewer::take_build() {
  std::optional<SceneBuild> build = builder_.take();
  if (!build) return;
  if (!build->error.empty()) {
    show_error(first_line(build->error));
    return;
  }
  upload(*build);
}

void Viewer::upload(const SceneBuild& build) {
  const auto start = std::chrono::steady_clock::now();
  last_build_seconds_ = build.seconds;
  const bool new_heights = build.built.heights || !has_scene_;
  heights_ = build.heights;
  const look::RenderParams params = pane_params(look::View::perspective, options_.mesh_picture_width, 720);
  if (build.rock) rock_ = *build.rock;
  if (build.water) water_ = *build.water;
  look::TerrainLayers layers;
  if (!rock_.empty()) layers.cliff_albedo = &rock_;
  const bool with_water = !water_.depth_m.empty();
  if (with_water) {
    layers.water_depth = &water_.depth_m;
    layers.wetness = &water_.wetness;
  }
  // Lakes are drawn flat at their level.
  if (new_heights || build.built.rock || build.built.water) renderer_->set_terrain(with_water ? water_.surface : *heights_, params, layers);
  if (build.plants) renderer_->set_plants(plant_kinds_.plants_to_draw(*build.plants, scene::plant_look(build.looked)));
  if (build.sky) renderer_->set_sky(build.sky->dome, params);
  if (build.sky) {
    // The grid view's cloud picture.
    if (!clouds_texture_) clouds_texture_ = render::make_texture();
    glBindTexture(GL_TEXTURE_2D, clouds_texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const Grid<float>& clouds = build.sky->clouds;
    std::vector<std::uint8_t> grey(clouds.size());
    for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = static_cast<std::uint8_t>(std::clamp(clouds.values()[i], 0.0f, 1.0f) * 255.0f);
    const int w = clouds.width(), h = clouds.height();
    if (w > 0 && h > 0) glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, w, h, 0, GL_RED, GL_UNSIGNED_BYTE, grey.data());
    const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    has_clouds_texture_ = w > 0 && h > 0;
  }
  if (new_heights) {
    // The grid view's terrain picture: heights as grey, at most 512 per side.
    const Heightfield& h = *heights_;
    const int step = std::max(1, (std::max(h.width(), h.height()) + 511) / 512);
    const int w = (h.width() + step - 1) / step, d = (h.height() + step - 1) / step;
    float low = h.values()[0], high = low;
    for (float v : h.values()) low = std::min(low, v), high = std::max(high, v);
    std::vector<std::uint8_t> grey(static_cast<std::size_t>(w) * d);
    for (int y = 0; y < d; ++y)
      for (int x = 0; x < w; ++x)
        grey[static_cast<std::size_t>(y) * w + x] =
            static_cast<std::uint8_t>(255.0f * (h(x * step, y * step) - low) / std::max(high - low, 1e-6f));
    if (!heights_texture_) heights_texture_ = render::make_texture();
    glBindTexture(GL_TEXTURE_2D, heights_texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, w, d, 0, GL_RED, GL_UNSIGNED_BYTE, grey.data());
    const GLint swizzle[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    heights_texture_size_[0] = w;
    heights_texture_size_[1] = d;
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  has_scene_ = true;
  ++version_;
  upload_pending_ = true;  // on screen after this frame's draw
  last_upload_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (walker_) update_walker_camera();
  status_ = fmt::format("built in {:.2f} s", build.seconds);
}

look::RenderParams Viewer::pane_params(look::View view, int width, int height) const {
  look::RenderParams params = look::with_fallbacks(looked_.render);
  params.camera = recipe_.render.camera;
  params.view = view;
  params.width = std::max(width, 16);
  params.height = std::max(height, 16);
  params.samples = options_.samples;
  if (heights_) {
    params.sea_level_m = look::effective_sea_level(looked_.render, *heights_);
    params.sea = true;
  }
  // The ortho views and an orbit camera ignore the walker.
  if (view != look::View::perspective) params.camera.eye_height_m.reset();
  return params;
}

// ---- the frame -----------------------------------------------------------------------------

void Viewer::layout_panes(int width, int height) {
  const float scale = ImGui::GetIO().DisplayFramebufferScale.x;
  const int top = static_cast<int>(ImGui::GetFrameHeight() * scale);
  const int bottom = static_cast<int>(ImGui::GetFrameHeightWithSpacing() * scale);
  const int left = panel_visible_ ? static_cast<int>(380 * scale) : 0;
  const int w = std::max(width - left, 32), h = std::max(height - top - bottom, 32);
  panes_.clear();
  if (layout_ == Layout::single) {
    panes_.push_back({single_view_, left, top, w, h});
    return;
  }
  // Fig. 2: front and side above, top and perspective below.
  const int half_w = w / 2, half_h = h / 2;
  panes_.push_back({look::View::front, left, top, half_w, half_h});
  panes_.push_back({look::View::side, left + half_w, top, w - half_w, half_h});
  panes_.push_back({look::View::top, left, top + half_h, half_w, h - half_h});
  panes_.push_back({look::View::perspective, left + half_w, top + half_h, w - half_w, h - half_h});
}

namespace {

bool same_camera(const look::Camera& a, const look::Camera& b) {
  return a.azimuth_deg == b.azimuth_deg && a.elevation_deg == b.elevation_deg && a.distance == b.distance && a.fov_deg == b.fov_deg &&
         a.target_x == b.target_x && a.target_y == b.target_y && a.eye_height_m == b.eye_height_m;
}

}  // namespace

bool Viewer::idle() const {
  if (builder_.busy() || !has_scene_ || upload_pending_) return false;
  return std::all_of(drawn_.begin(), drawn_.end(), [](const DrawnPane& pane) { return pane.scale == 1.0; }) && !drawn_.empty();
}

bool Viewer::pane_changed(std::size_t index) const {
  if (always_redraw_ || index >= drawn_.size()) return true;
  const Pane& pane = panes_[index];
  const DrawnPane& drawn = drawn_[index];
  // Only the perspective pane follows the camera; the level and top views stay put.
  const bool camera_moved = pane.view == look::View::perspective && !same_camera(recipe_.render.camera, drawn.camera);
  return drawn.version != version_ || camera_moved || drawn.view != pane.view || drawn.width != pane.width || drawn.height != pane.height;
}

void Viewer::draw_panes(int framebuffer_height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (!has_scene_) return;
  // A pane whose picture would not change shows its last one again, so an idle window costs
  // little and a finished build is picked up at once. While the view keeps changing
  // (orbiting, walking, dragging a slider) panes are drawn at half resolution and stretched,
  // a level of detail in screen space; a moment after it stops, at full resolution.
  const auto now = std::chrono::steady_clock::now();
  std::vector<bool> changed(panes_.size());
  for (std::size_t i = 0; i < panes_.size(); ++i) changed[i] = pane_changed(i);
  // Moving: the camera moved, or a widget is held (a slider dragged); a single edit or a
  // finished build is drawn at full resolution at once.
  bool camera_moved = false;
  for (std::size_t i = 0; i < panes_.size() && i < drawn_.size(); ++i)
    camera_moved |= panes_[i].view == look::View::perspective && !same_camera(recipe_.render.camera, drawn_[i].camera);
  if (!always_redraw_ && (camera_moved || ImGui::IsAnyItemActive())) last_change_ = now;
  const bool moving = std::chrono::duration<double>(now - last_change_).count() < settle_seconds;
  const double scale = moving && options_.moving_scale < 1.0 ? options_.moving_scale : 1.0;
  drawn_.resize(panes_.size());
  renderer_->set_plant_limits(interactive_plant_limits(scale < 1.0));
  for (std::size_t i = 0; i < panes_.size(); ++i) {
    const Pane& pane = panes_[i];
    DrawnPane& drawn = drawn_[i];
    // A pane drawn at half resolution is drawn again at full once the view is still.
    const bool redraw = changed[i] || (drawn.scale != scale && (changed[i] || scale == 1.0));
    const double pane_scale = redraw ? scale : drawn.scale;
    const int width = std::max(16, static_cast<int>(std::lround(pane.width * pane_scale)));
    const int height = std::max(16, static_cast<int>(std::lround(pane.height * pane_scale)));
    auto& target = targets_[i];
    const bool resized = !target || target->width() != width || target->height() != height;
    if (resized) target = std::make_unique<render::OffscreenTarget>(width, height, options_.samples);
    target->bind();
    if (redraw || resized) {
      renderer_->draw(pane_params(pane.view, width, height), width, height);
      drawn = {version_, recipe_.render.camera, pane.view, pane.width, pane.height, pane_scale};
    }
    // Into the window: GL's rows start at the bottom.
    target->blit_to_window(pane.x, framebuffer_height - pane.y - pane.height, pane.width, pane.height);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 1, 1);
}

void Viewer::handle_input(double seconds) {
  ImGuiIO& io = ImGui::GetIO();
  if (!io.WantCaptureKeyboard) {
    for (const KeyPress& press : pressed_keys_) {
      if (press.key == key_tab) layout_ = layout_ == Layout::four ? Layout::single : Layout::four;
      if (press.key == key_f12) pending_screenshot_ = fmt::format("sansui-screenshot-{}.png", ++screenshot_count_);
      if (press.key == key_f2) walker_ ? stop_walk() : start_walk(0.5, 0.5, recipe_.render.camera.azimuth_deg + 180.0);
      if (press.key == 'O' && press.control) file_action_ = FileAction::open;
      if (press.key == 'S' && press.control && !scene_file_.empty()) save(scene_file_);
    }
    if (walker_) {
      const double speed = walker_->speed_m_s * (io.KeyShift ? 10.0 : 1.0) * seconds;
      const double forward = (ImGui::IsKeyDown('W') ? 1.0 : 0.0) - (ImGui::IsKeyDown('S') ? 1.0 : 0.0);
      const double right = (ImGui::IsKeyDown('D') ? 1.0 : 0.0) - (ImGui::IsKeyDown('A') ? 1.0 : 0.0);
      if (forward != 0.0 || right != 0.0) walk_by(forward * speed, right * speed);
    }
  }
  pressed_keys_.clear();
  if (animate_time_) {
    const double hours = std::fmod(time_of_day_hours() + animate_hours_per_second_ * seconds, 24.0);
    set_value("time.time", fmt::format("{:02d}:{:02d}", static_cast<int>(hours), static_cast<int>(std::fmod(hours, 1.0) * 60.0)));
  }
  if (io.WantCaptureMouse) return;
  const float scale = io.DisplayFramebufferScale.x;
  const double mx = io.MousePos.x * scale, my = io.MousePos.y * scale;
  const Pane* hovered = nullptr;
  for (const Pane& pane : panes_)
    if (pane.contains(mx, my)) hovered = &pane;
  if (hovered == nullptr || hovered->view != look::View::perspective) return;
  look::Camera& camera = recipe_.render.camera;
  const ImVec2 drag = io.MouseDelta;
  if (walker_) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
      turn(drag.x * 0.2, -drag.y * 0.2);
    }
    return;
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    camera.azimuth_deg = std::fmod(camera.azimuth_deg - drag.x * 0.3 + 360.0, 360.0);
    camera.elevation_deg = std::clamp(camera.elevation_deg + drag.y * 0.2, 1.0, 89.0);
  }
  if (ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
    // Pan: the target moves across the ground, in the picture's directions.
    const double bearing = camera.azimuth_deg * std::numbers::pi / 180.0;
    const double along = 0.002 * std::max(camera.distance, 0.5);
    camera.target_x = std::clamp(camera.target_x - along * (drag.x * std::cos(bearing) + drag.y * std::sin(bearing)), 0.0, 1.0);
    camera.target_y = std::clamp(camera.target_y - along * (drag.x * std::sin(bearing) - drag.y * std::cos(bearing)), 0.0, 1.0);
  }
  if (io.MouseWheel != 0.0f) {
    const double distance = camera.distance > 0.0 ? camera.distance : 1.3;
    camera.distance = std::clamp(distance * std::pow(0.9, io.MouseWheel), 0.05, 20.0);
  }
}

void Viewer::frame(int framebuffer_width, int framebuffer_height, double seconds) {
  take_build();
  layout_panes(framebuffer_width, framebuffer_height);
  handle_input(seconds);
  const auto draw_start = std::chrono::steady_clock::now();
  draw_panes(framebuffer_height);
  if (upload_pending_) {
    glFinish();
    last_draw_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - draw_start).count();
  }
  menu_bar();
  if (panel_visible_) parameter_panel();
  if (grid_view_visible_) grid_view();
  status_bar();
  pane_labels();
  file_popups();
  error_window();
  if (heights_requested_ && (upload_pending_ || !regenerations_.empty())) {
    const double since_request = std::chrono::duration<double>(std::chrono::steady_clock::now() - *heights_requested_).count();
    if (upload_pending_) {
      // The new terrain's first picture (at half resolution if the view is still changing).
      glFinish();
      regenerations_.push_back({{"seconds_to_screen", since_request},
                                {"build_seconds", last_build_seconds_},
                                {"upload_seconds", last_upload_seconds_},
                                {"draw_seconds", last_draw_seconds_}});
    } else if (idle()) {
      regenerations_.back()["seconds_to_full_resolution"] = since_request;
      heights_requested_.reset();
    }
  }
  upload_pending_ = false;
}

void Viewer::capture_window(int framebuffer_width, int framebuffer_height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<Rgba8> pixels(static_cast<std::size_t>(framebuffer_width) * framebuffer_height);
  glReadPixels(0, 0, framebuffer_width, framebuffer_height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  last_window_ = Image::uninitialized(framebuffer_width, framebuffer_height);
  for (int y = 0; y < framebuffer_height; ++y)
    std::copy_n(pixels.data() + static_cast<std::size_t>(framebuffer_height - 1 - y) * framebuffer_width, framebuffer_width,
                last_window_.row(y).data());
  for (Rgba8& pixel : last_window_.values()) pixel.a = 255;
  if (pending_screenshot_) {
    save_screenshot(*pending_screenshot_);
    pending_screenshot_.reset();
  }
}

nlohmann::json Viewer::report() const {
  nlohmann::json report;
  report["errors"] = errors_shown_;
  report["scene_file"] = scene_file_.string();
  const look::Camera& camera = recipe_.render.camera;
  report["camera"] = {{"azimuth", camera.azimuth_deg},
                      {"elevation", camera.elevation_deg},
                      {"distance", camera.distance},
                      {"walking", walker_.has_value()},
                      {"orbit_azimuth", (walker_ ? orbit_camera_ : camera).azimuth_deg}};
  report["layout"] = layout_ == Layout::four ? "four" : "single";
  report["walk"] = walk_log_;
  report["regenerations"] = regenerations_;
  nlohmann::json panes = nlohmann::json::array();
  for (const Pane& pane : panes_)
    panes.push_back({{"view", look::view_name(pane.view)}, {"x", pane.x}, {"y", pane.y}, {"width", pane.width}, {"height", pane.height}});
  report["panes"] = panes;
  report["frames"] = nlohmann::json::array();
  for (std::vector<double> series : frame_seconds_) {
    if (series.empty()) continue;
    std::sort(series.begin(), series.end());
    double sum = 0.0;
    for (double s : series) sum += s;
    report["frames"].push_back({{"count", series.size()},
                                {"mean_ms", 1e3 * sum / static_cast<double>(series.size())},
                                {"median_ms", 1e3 * series[series.size() / 2]},
                                {"max_ms", 1e3 * series.back()}});
  }
  if (heights_) report["terrain"] = {{"width", heights_->width()}, {"height", heights_->height()}};
  return report;
}

}  // namespace sansui::viewer
