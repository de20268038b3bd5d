// The viewer's state and its one frame: seed 003's interface (Fig. 2, SPEC 3.5). A menu bar;
// front, side and top orthographic panes and a perspective pane (or one pane); parameter
// panels generated from the recipe's parameter tables; a 2-D grid view of the terrain and the
// cloud image; orbit and walkthrough navigation; scene files, exports and screenshots.
//
// Every action a user takes through the window (set a value, switch a view, move the camera,
// open, save, export) is a public member, so scripts (viewer/script.hpp) drive the same code.
// Needs a current OpenGL 3.3 core context and a Dear ImGui frame in progress for frame().
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/color.hpp"
#include "render/gl_util.hpp"
#include "render/offscreen_target.hpp"
#include "render/terrain_renderer.hpp"
#include "scene/recipe.hpp"
#include "viewer/param_widgets.hpp"
#include "viewer/scene_builder.hpp"
#include "viewer/walker.hpp"

namespace sansui::viewer {

enum class Layout { four, single };

/// A key pressed since the last frame (GLFW key codes: letters are their capitals).
struct KeyPress {
  int key = 0;
  bool control = false;
};
inline constexpr int key_tab = 258, key_f2 = 291, key_f12 = 301;

struct ViewerOptions {
  int samples = 1;                ///< antialiasing samples of the panes (software GL pays per sample)
  bool remember_recent = true;    ///< keep the recent-files list in the user's config directory
  int mesh_picture_width = 1280;  ///< the picture width the terrain mesh is sized for
  double moving_scale = 0.5;      ///< resolution of the panes while the view changes (1: full)
};

/// One pane: where it is in the window (pixels, top-left origin) and what it shows.
struct Pane {
  look::View view = look::View::perspective;
  int x = 0, y = 0, width = 0, height = 0;
  bool contains(double px, double py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

class Viewer {
 public:
  explicit Viewer(ViewerOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // ---- actions (menu, widgets, keys and scripts all come here) -----------------------------
  /// Starts from a scene file. A file that does not load leaves the current scene and shows why.
  bool open(const std::filesystem::path& file);
  /// A scene of the given source's defaults.
  void new_scene(scene::SourceKind source);
  /// Writes the scene (with the current camera and a render output, so `sansui run FILE` makes
  /// the perspective pane's picture). Failure is shown; nothing is lost.
  bool save(const std::filesystem::path& file);
  /// Sets `key` ("season.season", "midpoint.hurst", "shape.stage") from text as on the command
  /// line; "" resets an optional key to derived. Shows and returns false on a bad key or value.
  bool set_value(std::string_view key, std::string_view text);
  void apply(const RowEdit& edit);
  void set_layout(Layout layout) { layout_ = layout; }
  void set_single_view(look::View view) { single_view_ = view; }
  void set_orbit(double azimuth_deg, double elevation_deg, double distance);
  /// Turns the orbiting camera round its target (degrees clockwise), as dragging does.
  void orbit_by(double degrees);
  /// Starts walking at X,Y fractions of the terrain (x east, y south), looking toward `bearing_deg`.
  void start_walk(double x, double y, double bearing_deg);
  /// Starts walking at X0,Y0 looking toward X1,Y1 (fractions); returns the distance between them in metres.
  double start_walk_toward(double x0, double y0, double x1, double y1);
  void stop_walk();
  /// Turns the walker's view (degrees clockwise, and up), as dragging the mouse does.
  void turn(double yaw_deg, double pitch_deg);
  /// Moves the walker (metres), as the W/A/S/D keys do, and logs where the eye is.
  void walk_by(double forward_m, double right_m);
  bool export_heightmap(const std::filesystem::path& file);
  bool export_mesh(const std::filesystem::path& file);
  bool export_render(const std::filesystem::path& file);
  /// Writes the last drawn window picture (row 0 at the top).
  bool save_screenshot(const std::filesystem::path& file);
  /// Writes the window's picture to `file` once this frame is drawn (see capture_window).
  void request_screenshot(std::filesystem::path file) { pending_screenshot_ = std::move(file); }
  bool wants_capture() const { return pending_screenshot_.has_value(); }
  void set_panel_visible(bool visible) { panel_visible_ = visible; }
  /// Keys pressed since the last frame. Dear ImGui 1.86 sees only keys still down when a frame
  /// starts, so a quick tap (or xdotool's) between two frames would be lost without this.
  void key_pressed(KeyPress press) { pressed_keys_.push_back(press); }
  void set_grid_view_visible(bool visible) { grid_view_visible_ = visible; }

  // ---- the frame ---------------------------------------------------------------------------
  /// Takes finished builds, handles input, draws the panes into the window's framebuffer and
  /// builds the ImGui windows (call between ImGui::NewFrame and ImGui::Render).
  void frame(int framebuffer_width, int framebuffer_height, double seconds);
  /// Reads the window's framebuffer after ImGui has drawn (before the swap) and writes the
  /// requested screenshot.
  void capture_window(int framebuffer_width, int framebuffer_height);

  /// No build running or waiting, the last one on screen, every pane at full resolution.
  bool idle() const;
  const std::string& error() const { return error_; }
  const scene::Recipe& recipe() const { return recipe_; }
  /// What happened, for tests and benchmarks: errors shown, the walk log, regeneration times.
  nlohmann::json report() const;
  /// Records a frame's time while every frame is drawn (set_always_redraw).
  void note_frame_seconds(double seconds) {
    if (recording_frames_ && !frame_seconds_.empty()) frame_seconds_.back().push_back(seconds);
  }
  void set_recording_frames(bool on) { recording_frames_ = on; }
  /// Starts a new series of frame times (each `measure` step of a script is one).
  void start_frame_series() { frame_seconds_.emplace_back(); }
  /// Draws every pane every frame (to measure frame times); otherwise only after a change.
  void set_always_redraw(bool on) { always_redraw_ = on; }

 private:
  void request();
  void take_build();
  void upload(const SceneBuild& build);
  look::RenderParams pane_params(look::View view, int width, int height) const;
  void layout_panes(int width, int height);
  void draw_panes(int framebuffer_height);
  bool pane_changed(std::size_t index) const;
  void handle_input(double seconds);
  void update_walker_camera();
  double terrain_height_m(double x_m, double z_m) const;
  double time_of_day_hours() const;  // [time] time as hours since midnight
  void show_error(std::string message);
  void remember(const std::filesystem::path& file);

  // UI parts (viewer_ui.cpp)
  void menu_bar();
  void parameter_panel();
  void high_level_widgets();
  void section_widgets(std::string_view section);
  void shape_widgets();
  void grid_view();
  void status_bar();
  void pane_labels();
  void file_popups();
  void error_window();

  ViewerOptions options_;
  scene::Recipe recipe_;  // as the user set it: unset look values are derived
  scene::Recipe looked_;  // the same with the look resolved, for drawing and derived values
  std::filesystem::path scene_file_;
  std::shared_ptr<const Heightfield> heights_;
  Image rock_;                        // the rock texture on cliffs (empty: the palette's)
  scene::SurfaceWater water_;         // rivers and lakes drawn (empty: none)
  look::PlantKindCache plant_kinds_;  // the models of the plants drawn, kept for the next edit
  SceneBuilder builder_;
  std::unique_ptr<render::TerrainRenderer> renderer_;
  std::array<std::unique_ptr<render::OffscreenTarget>, 4> targets_;
  std::vector<Pane> panes_;
  Layout layout_ = Layout::four;
  look::View single_view_ = look::View::perspective;
  bool has_scene_ = false, upload_pending_ = false;
  bool panel_visible_ = true, grid_view_visible_ = false;

  std::vector<KeyPress> pressed_keys_;
  std::optional<Walker> walker_;
  look::Camera orbit_camera_;  // the orbiting camera to return to after a walk
  // What the panes last drew: they are drawn again only when something changed.
  struct DrawnPane {
    std::uint64_t version = ~std::uint64_t{0};
    look::Camera camera;
    look::View view = look::View::perspective;
    int width = 0, height = 0;
    double scale = 1.0;
  };
  std::uint64_t version_ = 0;
  std::vector<DrawnPane> drawn_;
  bool always_redraw_ = false, recording_frames_ = false;
  std::chrono::steady_clock::time_point last_change_{};
  nlohmann::json walk_log_ = nlohmann::json::array();
  bool animate_time_ = false;
  double animate_hours_per_second_ = 1.0;

  // the 2-D grid view's pictures
  render::GlName heights_texture_, clouds_texture_;
  int heights_texture_size_[2] = {0, 0};
  bool has_clouds_texture_ = false;

  std::string error_, status_;
  std::vector<std::string> errors_shown_;
  std::deque<std::filesystem::path> recent_;
  std::string path_input_;
  enum class FileAction { none, open, save, export_heightmap, export_mesh, export_render, screenshot } file_action_ = FileAction::none;

  Image last_window_;  // the last captured window picture
  std::vector<std::vector<double>> frame_seconds_;
  std::optional<std::chrono::steady_clock::time_point> heights_requested_;
  nlohmann::json regenerations_ = nlohmann::json::array();
  double last_build_seconds_ = 0.0, last_upload_seconds_ = 0.0, last_draw_seconds_ = 0.0;
  int screenshot_count_ = 0;
  std::optional<std::filesystem::path> pending_screenshot_;
};

}  // namespace sansui::viewer
