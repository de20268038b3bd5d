#include "viewer/script.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>

#include "core/error.hpp"

namespace sansui::viewer {
namespace {

constexpr double wait_limit_s = 600.0;

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Usage {
  std::string_view name;
  std::size_t min_words, max_words;  // including the name
  std::string_view form;
};
constexpr Usage usages[] = {
    {"open", 2, 2, "open FILE"},
    {"save", 2, 2, "save FILE"},
    {"set", 3, 99, "set KEY VALUE"},
    {"reset", 2, 2, "reset KEY"},
    {"export", 3, 3, "export heightmap|mesh|render FILE"},
    {"layout", 2, 2, "layout four|single"},
    {"view", 2, 2, "view perspective|front|side|top"},
    {"panel", 2, 2, "panel on|off"},
    {"gridview", 2, 2, "gridview on|off"},
    {"orbit", 3, 4, "orbit AZIMUTH ELEVATION [DISTANCE]"},
    {"walk", 4, 4, "walk X Y BEARING"},
    {"forward", 2, 2, "forward METRES"},
    {"strafe", 2, 2, "strafe METRES"},
    {"turn", 2, 3, "turn YAW [PITCH]"},
    {"walkpath", 6, 6, "walkpath X0 Y0 X1 Y1 STEPS"},
    {"stopwalk", 1, 1, "stopwalk"},
    {"wait", 1, 1, "wait"},
    {"frames", 2, 2, "frames N"},
    {"sleep", 2, 2, "sleep SECONDS"},
    {"waitfor", 2, 2, "waitfor FILE"},
    {"measure", 2, 2, "measure N"},
    {"measure-orbit", 2, 2, "measure-orbit N"},
    {"screenshot", 2, 2, "screenshot FILE"},
    {"quit", 1, 1, "quit"},
};

double number(const std::string& word, const std::string& where) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0' || !std::isfinite(value)) fail("{}: '{}' is not a number", where, word);
  return value;
}

bool on_off(const std::string& word, const std::string& where) {
  if (word == "on") return true;
  if (word == "off") return false;
  fail("{}: '{}' must be on or off", where, word);
}

}  // namespace

Script Script::parse(std::string_view text, const std::string& source) {
  Script script;
  script.source_ = source;
  std::string all(text);
  for (char& c : all)
    if (c == ';') c = '\n';
  std::istringstream lines(all);
  int number_of_line = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number_of_line;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    Step step;
    step.line = number_of_line;
    for (std::string word; words >> word;) step.words.push_back(word);
    if (step.words.empty()) continue;
    const std::string where = fmt::format("{}:{}", source, number_of_line);
    const Usage* usage = nullptr;
    for (const Usage& u : usages)
      if (u.name == step.words[0]) usage = &u;
    if (usage == nullptr) {
      std::string names;
      for (const Usage& u : usages) names += (names.empty() ? "" : ", ") + std::string(u.name);
      fail("{}: unknown step '{}': steps are {}", where, step.words[0], names);
    }
    if (step.words.size() < usage->min_words || step.words.size() > usage->max_words)
      fail("{}: the step is written {}", where, usage->form);
    if (step.words.size() > 2) {
      // The value of `set` may hold spaces: everything after the key.
      const auto key_at = line.find(step.words[1], line.find(step.words[0]) + step.words[0].size());
      step.rest = line.substr(key_at + step.words[1].size());
      step.rest.erase(0, step.rest.find_first_not_of(" \t"));
      step.rest.erase(step.rest.find_last_not_of(" \t\r") + 1);
    }
    script.steps_.push_back(std::move(step));
  }
  return script;
}

void Script::advance(Viewer& viewer) {
  if (frames_to_wait_ > 0) {
    --frames_to_wait_;
    return;
  }
  if (orbit_frames_left_ > 0) {
    // A user dragging the camera: a degree further round every frame.
    viewer.orbit_by(1.0);
    --orbit_frames_left_;
    return;
  }
  if (!wait_for_file_.empty()) {
    // Another program (a test driving the window with X events) says when it is done.
    std::error_code ignored;
    if (!std::filesystem::exists(wait_for_file_, ignored)) {
      if (now_s() - idle_wait_started_ > wait_limit_s) fail("{}: {} did not appear within {} s", source_, wait_for_file_, wait_limit_s);
      return;
    }
    wait_for_file_.clear();
  }
  if (sleep_until_s_ > 0.0) {
    if (now_s() < sleep_until_s_) return;  // frames go on (input is handled), steps wait
    sleep_until_s_ = 0.0;
  }
  // A measurement ends with the frames it asked for.
  viewer.set_always_redraw(false);
  viewer.set_recording_frames(false);
  if (waiting_idle_) {
    if (!viewer.idle()) {
      if (now_s() - idle_wait_started_ > wait_limit_s) fail("{}: the scene was not built within {} s", source_, wait_limit_s);
      return;
    }
    waiting_idle_ = false;
    frames_to_wait_ = 1;  // one more frame draws what was uploaded last
    return;
  }
  if (path_steps_left_ > 0) {
    viewer.walk_by(path_step_m_, 0.0);
    --path_steps_left_;
    return;
  }
  while (next_ < steps_.size() && frames_to_wait_ == 0 && !waiting_idle_ && path_steps_left_ == 0 && orbit_frames_left_ == 0)
    run(steps_[next_++], viewer);
}

void Script::run(const Step& step, Viewer& viewer) {
  const std::string where = fmt::format("{}:{}", source_, step.line);
  const auto& w = step.words;
  const std::string& name = w[0];
  if (name == "open") {
    viewer.open(w[1]);
  } else if (name == "save") {
    viewer.save(w[1]);
  } else if (name == "set") {
    viewer.set_value(w[1], step.rest);
  } else if (name == "reset") {
    viewer.set_value(w[1], "");
  } else if (name == "export") {
    if (w[1] == "heightmap") {
      viewer.export_heightmap(w[2]);
    } else if (w[1] == "mesh") {
      viewer.export_mesh(w[2]);
    } else if (w[1] == "render") {
      viewer.export_render(w[2]);
    } else {
      fail("{}: export '{}': allowed are heightmap, mesh, render", where, w[1]);
    }
  } else if (name == "layout") {
    if (w[1] != "four" && w[1] != "single") fail("{}: layout '{}': allowed are four, single", where, w[1]);
    viewer.set_layout(w[1] == "four" ? Layout::four : Layout::single);
    frames_to_wait_ = 1;
  } else if (name == "view") {
    const auto view = look::view_from_name(w[1]);
    if (!view) fail("{}: view '{}': allowed are perspective, front, side, top", where, w[1]);
    viewer.set_layout(Layout::single);
    viewer.set_single_view(*view);
    frames_to_wait_ = 1;
  } else if (name == "panel") {
    viewer.set_panel_visible(on_off(w[1], where));
  } else if (name == "gridview") {
    viewer.set_grid_view_visible(on_off(w[1], where));
  } else if (name == "orbit") {
    viewer.set_orbit(number(w[1], where), number(w[2], where), w.size() > 3 ? number(w[3], where) : 0.0);
  } else if (name == "walk") {
    viewer.start_walk(number(w[1], where), number(w[2], where), number(w[3], where));
  } else if (name == "forward") {
    viewer.walk_by(number(w[1], where), 0.0);
  } else if (name == "strafe") {
    viewer.walk_by(0.0, number(w[1], where));
  } else if (name == "turn") {
    viewer.turn(number(w[1], where), w.size() > 2 ? number(w[2], where) : 0.0);
  } else if (name == "walkpath") {
    const int steps = static_cast<int>(number(w[5], where));
    if (steps < 1) fail("{}: walkpath needs at least 1 step", where);
    const double length = viewer.start_walk_toward(number(w[1], where), number(w[2], where), number(w[3], where), number(w[4], where));
    path_step_m_ = length / steps;
    path_steps_left_ = steps;
  } else if (name == "stopwalk") {
    viewer.stop_walk();
  } else if (name == "wait") {
    waiting_idle_ = true;
    idle_wait_started_ = now_s();
  } else if (name == "frames") {
    frames_to_wait_ = std::max(1, static_cast<int>(number(w[1], where)));
  } else if (name == "sleep") {
    sleep_until_s_ = now_s() + std::max(0.0, number(w[1], where));
  } else if (name == "waitfor") {
    wait_for_file_ = w[1];
    idle_wait_started_ = now_s();
  } else if (name == "measure") {
    viewer.start_frame_series();
    viewer.set_recording_frames(true);
    viewer.set_always_redraw(true);  // full resolution, every frame, until the measurement ends
    frames_to_wait_ = std::max(1, static_cast<int>(number(w[1], where)));
  } else if (name == "measure-orbit") {
    viewer.start_frame_series();
    viewer.set_recording_frames(true);
    orbit_frames_left_ = std::max(1, static_cast<int>(number(w[1], where)));
  } else if (name == "screenshot") {
    viewer.request_screenshot(w[1]);
    frames_to_wait_ = 1;
  } else if (name == "quit") {
    next_ = steps_.size();
  }
}

}  // namespace sansui::viewer
