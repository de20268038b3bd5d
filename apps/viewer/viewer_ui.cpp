// The viewer's ImGui windows: menu bar, parameter panel, grid view, status bar, file prompts.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/viewer.hpp"

namespace sansui::viewer {
namespace {

// High-level values (seed 003's "information compression"): the rest of the look derives from them.
constexpr std::string_view high_level_sections[] = {"climate", "season", "weather"};
constexpr std::string_view high_level_keys[] = {"time.date", "time.latitude", "midpoint.seed", "midpoint.hurst", "world.sea_level"};
// Low-level values: each is derived from the high-level ones unless set.
constexpr std::string_view look_sections[] = {"land", "sky", "atmosphere", "sea", "vegetation", "rock", "render", "camera"};

ImTextureID texture_id(GLuint name) {
  return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(name));  // NOLINT(performance-no-int-to-ptr)
}

}  // namespace

void Viewer::menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New midpoint terrain")) new_scene(scene::SourceKind::midpoint);
    if (ImGui::MenuItem("Open scene...", "Ctrl+O")) file_action_ = FileAction::open;
    if (ImGui::BeginMenu("Open recent", !recent_.empty())) {
      for (const auto& file : recent_)
        if (ImGui::MenuItem(file.string().c_str())) open(file);
      ImGui::EndMenu();
    }
    if (ImGui::MenuItem("Save scene", "Ctrl+S", false, !scene_file_.empty())) save(scene_file_);
    if (ImGui::MenuItem("Save scene as...")) file_action_ = FileAction::save;
    ImGui::Separator();
    if (ImGui::MenuItem("Export heightmap...")) file_action_ = FileAction::export_heightmap;
    if (ImGui::MenuItem("Export mesh...")) file_action_ = FileAction::export_mesh;
    if (ImGui::MenuItem("Export render...")) file_action_ = FileAction::export_render;
    if (ImGui::MenuItem("Screenshot...", "F12")) file_action_ = FileAction::screenshot;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Four panes", "Tab", layout_ == Layout::four)) layout_ = Layout::four;
    for (look::View view : {look::View::perspective, look::View::front, look::View::side, look::View::top}) {
      const std::string label = fmt::format("{} only", look::view_name(view));
      if (ImGui::MenuItem(label.c_str(), nullptr, layout_ == Layout::single && single_view_ == view)) {
        layout_ = Layout::single;
        single_view_ = view;
      }
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Walkthrough", "F2", walker_.has_value())) walker_ ? stop_walk() : start_walk(0.5, 0.5, 0.0);
    ImGui::MenuItem("Parameters", nullptr, &panel_visible_);
    ImGui::MenuItem("Grid view (2-D)", nullptr, &grid_view_visible_);
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Viewer::section_widgets(std::string_view section) {
  const auto& table = scene::recipe_table();
  const auto edits = table_widgets<scene::Recipe>(table, recipe_, looked_, [&](const params::Param<scene::Recipe>& row) {
    return scene::section_of(row.key) == section && scene::reads_key(recipe_, row);
  });
  for (const RowEdit& edit : edits) apply(edit);
}

void Viewer::shape_widgets() {
  if (!recipe_.nodes.empty()) return;  // a graph shapes its heights with its own nodes
  bool staged = !recipe_.shape.empty();
  if (ImGui::Checkbox("shaping step: stage filter or erosion", &staged)) {
    if (staged) {
      recipe_.shape.push_back(scene::default_shape_step(recipe_.version));
      scene::settle_world(recipe_);
    } else {
      recipe_.shape.clear();
    }
    request();
  }
  if (recipe_.shape.empty()) return;
  const scene::ShapeStep before = recipe_.shape.front();
  const auto edits = table_widgets<scene::ShapeStep>(
      params::table_of<scene::ShapeStep>(), before, before,
      [&](const params::Param<scene::ShapeStep>& row) { return row.key != "step" && scene::reads_key(recipe_, row); });
  for (const RowEdit& edit : edits) apply({"shape." + edit.key, edit.value});
}

void Viewer::high_level_widgets() {
  for (std::string_view section : high_level_sections) section_widgets(section);
  const auto& table = scene::recipe_table();
  for (std::string_view key : high_level_keys) {
    const auto* row = table.find(key);
    if (row == nullptr || !scene::reads_key(recipe_, *row) ||
        (scene::section_of(key) == "midpoint" && recipe_.source != scene::SourceKind::midpoint))
      continue;
    const WidgetEdit edit = param_widget(*row, row->get(recipe_), row->get(looked_));
    if (edit.changed || edit.reset) apply({row->key, edit.reset ? params::Value{} : edit.value});
  }
  // Time of day as a slider over the [time] time key (HH:MM), animated on request.
  float hours = static_cast<float>(time_of_day_hours());
  ImGui::TextUnformatted("time of day");
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##time_of_day", &hours, 0.0f, 23.99f, "%.2f h")) {
    const int minutes = static_cast<int>(std::lround(hours * 60.0f)) % (24 * 60);
    set_value("time.time", fmt::format("{:02d}:{:02d}", minutes / 60, minutes % 60));
  }
  ImGui::Checkbox("animate", &animate_time_);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  float speed = static_cast<float>(animate_hours_per_second_);
  if (ImGui::SliderFloat("##speed", &speed, 0.1f, 6.0f, "%.1f h/s")) animate_hours_per_second_ = speed;
  shape_widgets();
}

void Viewer::parameter_panel() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float top = ImGui::GetFrameHeight(), bottom = ImGui::GetFrameHeightWithSpacing();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + top));
  ImGui::SetNextWindowSize(ImVec2(380.0f, viewport->Size.y - top - bottom));
  ImGui::Begin("Parameters", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-1.0f);
  if (ImGui::CollapsingHeader("High level", ImGuiTreeNodeFlags_DefaultOpen)) high_level_widgets();
  if (ImGui::CollapsingHeader("Terrain")) {
    for (const scene::Section& section : scene::recipe_sections()) {
      const bool read_by_source = std::find(section.sources.begin(), section.sources.end(), recipe_.source) != section.sources.end();
      if (!read_by_source || section.name == "heightmap_output") continue;
      if (ImGui::TreeNode(section.name.c_str())) {
        section_widgets(section.name);
        ImGui::TreePop();
      }
    }
  }
  if (ImGui::CollapsingHeader("Low level (derived unless set)", ImGuiTreeNodeFlags_DefaultOpen)) {
    for (std::string_view section : look_sections) {
      const std::string name(section);
      if (ImGui::TreeNodeEx(name.c_str(), section == "land" ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
        section_widgets(section);
        ImGui::TreePop();
      }
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void Viewer::grid_view() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + 400.0f, viewport->Pos.y + 60.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(720.0f, 560.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Grid view (2-D)", &grid_view_visible_)) {
    ImGui::End();
    return;
  }
  // The paper's 2-D views: the terrain as a grey grid and the cloud image, each with the
  // controls that change it below (the stage filter and H; the cloud fineness and cover).
  if (ImGui::BeginTable("grids", 2, ImGuiTableFlags_SizingStretchSame)) {
    ImGui::TableNextColumn();
    const float side = std::max(64.0f, ImGui::GetContentRegionAvail().x);
    ImGui::TextUnformatted("terrain (heights as grey)");
    if (heights_texture_) {
      const float aspect = static_cast<float>(heights_texture_size_[1]) / static_cast<float>(std::max(heights_texture_size_[0], 1));
      ImGui::Image(texture_id(heights_texture_.id()), ImVec2(side, side * aspect));
    }
    shape_widgets();
    if (recipe_.source == scene::SourceKind::midpoint) {
      const auto* row = scene::recipe_table().find("midpoint.hurst");
      const WidgetEdit edit = param_widget(*row, row->get(recipe_), row->get(looked_));
      if (edit.changed) apply({row->key, edit.value});
    }
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("clouds (density)");
    if (has_clouds_texture_) {
      ImGui::Image(texture_id(clouds_texture_.id()), ImVec2(side, side));
    } else {
      ImGui::Dummy(ImVec2(side, side));
    }
    for (std::string_view key : {"sky.cloud_fineness", "sky.cloud_cover"}) {
      const auto* row = scene::recipe_table().find(key);
      const WidgetEdit edit = param_widget(*row, row->get(recipe_), row->get(looked_));
      if (edit.changed || edit.reset) apply({row->key, edit.reset ? params::Value{} : edit.value});
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void Viewer::status_bar() {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float height = ImGui::GetFrameHeightWithSpacing();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + viewport->Size.y - height));
  ImGui::SetNextWindowSize(ImVec2(viewport->Size.x, height));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(6.0f, 2.0f));
  ImGui::Begin("##status", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  if (builder_.busy()) {
    const auto [stage, fraction] = builder_.progress();
    ImGui::ProgressBar(static_cast<float>(fraction), ImVec2(240.0f, 0.0f), stage.c_str());
    ImGui::SameLine();
  }
  const std::string where = scene_file_.empty() ? std::string("(unsaved scene)") : scene_file_.string();
  ImGui::Text("%s  |  %s%s", where.c_str(), walker_ ? "walking (WASD, drag to look, F2 to stop)  |  " : "", status_.c_str());
  ImGui::End();
  ImGui::PopStyleVar();
}

void Viewer::pane_labels() {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float scale = ImGui::GetIO().DisplayFramebufferScale.x;
  for (const Pane& pane : panes_) {
    const ImVec2 corner(static_cast<float>(pane.x) / scale + 6.0f, static_cast<float>(pane.y) / scale + 4.0f);
    const std::string label(look::view_name(pane.view));
    draw->AddText(ImVec2(corner.x + 1.0f, corner.y + 1.0f), IM_COL32(0, 0, 0, 200), label.c_str());
    draw->AddText(corner, IM_COL32(255, 255, 255, 230), label.c_str());
    draw->AddRect(ImVec2(static_cast<float>(pane.x) / scale, static_cast<float>(pane.y) / scale),
                  ImVec2(static_cast<float>(pane.x + pane.width) / scale, static_cast<float>(pane.y + pane.height) / scale),
                  IM_COL32(20, 20, 20, 255));
  }
  if (!has_scene_) {
    const auto [stage, fraction] = builder_.progress();
    draw->AddText(ImVec2(400.0f, 60.0f), IM_COL32(255, 255, 255, 255),
                  fmt::format("building the terrain: {} {:.0f} %", stage, 100.0 * fraction).c_str());
  }
}

void Viewer::file_popups() {
  static constexpr const char* titles[] = {"",          "Open scene", "Save scene as", "Export heightmap", "Export mesh", "Export render",
                                           "Screenshot"};
  if (file_action_ != FileAction::none && !ImGui::IsPopupOpen(titles[static_cast<int>(file_action_)])) {
    ImGui::OpenPopup(titles[static_cast<int>(file_action_)]);
    if (path_input_.empty()) path_input_ = scene_file_.empty() ? std::string("scene.toml") : scene_file_.string();
  }
  for (int i = 1; i < static_cast<int>(std::size(titles)); ++i) {
    if (!ImGui::BeginPopupModal(titles[i], nullptr, ImGuiWindowFlags_AlwaysAutoResize)) continue;
    ImGui::TextUnformatted("File:");
    ImGui::SetNextItemWidth(480.0f);
    const bool entered = ImGui::InputText("##path", &path_input_, ImGuiInputTextFlags_EnterReturnsTrue);
    const bool ok = ImGui::Button("OK") || entered;
    ImGui::SameLine();
    const bool cancel = ImGui::Button("Cancel");
    if (ok) {
      const std::filesystem::path file = path_input_;
      switch (static_cast<FileAction>(i)) {
        case FileAction::open:
          open(file);
          break;
        case FileAction::save:
          save(file);
          break;
        case FileAction::export_heightmap:
          export_heightmap(file);
          break;
        case FileAction::export_mesh:
          export_mesh(file);
          break;
        case FileAction::export_render:
          export_render(file);
          break;
        case FileAction::screenshot:
        case FileAction::none:
          request_screenshot(file);
          break;
      }
    }
    if (ok || cancel) {
      file_action_ = FileAction::none;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void Viewer::error_window() {
  if (error_.empty()) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x * 0.5f, viewport->Pos.y + 60.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(300.0f, 0.0f), ImVec2(viewport->Size.x * 0.8f, 300.0f));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.45f, 0.08f, 0.08f, 0.95f));
  ImGui::Begin("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushTextWrapPos(viewport->Size.x * 0.75f);
  ImGui::TextUnformatted(error_.c_str());
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Dismiss")) error_.clear();
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace sansui::viewer
