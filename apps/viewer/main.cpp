// sansui-viewer: the interactive viewer (viewer/viewer.hpp) in a GLFW window with Dear ImGui.
// With --script or --screenshot it runs unattended and exits: tests and docs drive it so.
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

// epoxy before GLFW, which must not pull in a GL header of its own.
#include <epoxy/gl.h>
// clang-format off
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
// clang-format on
#include <CLI/CLI.hpp>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <imgui.h>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"
#include "io/text_file.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"
#include "viewer/script.hpp"
#include "viewer/viewer.hpp"

namespace {

using namespace sansui;

constexpr int exit_bad_input = 2, exit_no_display = 3;

struct Arguments {
  std::string scene, script, screenshot, report;
  int width = 1600, height = 900, samples = 1;
  bool no_recent = false;
};

std::string script_text(const std::string& script) {
  // A file of steps, or the steps themselves ("set season.season winter; wait").
  std::error_code ignored;
  if (script.find(';') == std::string::npos && std::filesystem::is_regular_file(script, ignored)) {
    std::ifstream file(script);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }
  return script;
}

void glfw_error(int code, const char* description) {
  std::fprintf(stderr, "sansui-viewer: GLFW error 0x%x: %s\n", code, description);
}

GLFWwindow* open_window(const Arguments& args) {
  glfwSetErrorCallback(nullptr);
  if (glfwInit() == GLFW_FALSE) return nullptr;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(args.width, args.height, "Sansui", nullptr, nullptr);
  if (window == nullptr) {
    glfwTerminate();
    return nullptr;
  }
  glfwSetErrorCallback(glfw_error);
  glfwMakeContextCurrent(window);
  // Scripts run as fast as they can draw; a person gets the display's rate.
  glfwSwapInterval(args.script.empty() && args.screenshot.empty() ? 1 : 0);
  return window;
}

int run(const Arguments& args) {
  std::optional<viewer::Script> script;
  if (!args.script.empty())
    script = viewer::Script::parse(script_text(args.script), args.script.find(';') == std::string::npos ? args.script : "script");
  const bool unattended = script.has_value() || !args.screenshot.empty();

  GLFWwindow* window = open_window(args);
  if (window == nullptr) {
    std::fprintf(stderr,
                 "sansui-viewer: no display to open a window on (DISPLAY is %s, or no OpenGL 3.3 core there); "
                 "to draw pictures without a display use `sansui render` or `sansui run SCENE.toml`\n",
                 std::getenv("DISPLAY") != nullptr ? "set" : "not set");
    return exit_no_display;
  }
  // Installed before ImGui's, which calls it on: key presses reach the viewer even when
  // pressed and released between two frames.
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
    auto* app = static_cast<viewer::Viewer*>(glfwGetWindowUserPointer(w));
    if (app != nullptr && action == GLFW_PRESS) app->key_pressed({key, (mods & GLFW_MOD_CONTROL) != 0});
  });
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working directory
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int status = 0;
  {
    viewer::ViewerOptions options;
    options.samples = args.samples;
    options.remember_recent = !args.no_recent && !unattended;
    viewer::Viewer app(options);
    glfwSetWindowUserPointer(window, &app);
    if (!args.scene.empty()) app.open(args.scene);
    bool final_shot_requested = false;
    auto last = std::chrono::steady_clock::now();
    while (glfwWindowShouldClose(window) == GLFW_FALSE) {
      glfwPollEvents();
      const auto now = std::chrono::steady_clock::now();
      const double seconds = std::chrono::duration<double>(now - last).count();
      last = now;
      app.note_frame_seconds(seconds);
      try {
        if (script && !script->finished()) script->advance(app);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "sansui-viewer: %s\n", e.what());
        status = 1;
        break;
      }
      const bool script_done = !script || script->finished();
      if (unattended && script_done) {
        // The last picture once everything is built and drawn, then exit.
        if (args.screenshot.empty() || final_shot_requested) break;
        if (app.idle()) {
          app.request_screenshot(args.screenshot);
          final_shot_requested = true;
        }
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      if (width > 0 && height > 0) app.frame(width, height, seconds);
      ImGui::Render();
      glViewport(0, 0, width, height);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (app.wants_capture() && width > 0 && height > 0) app.capture_window(width, height);
      glfwSwapBuffers(window);
    }
    if (!args.report.empty()) io::write_text_file(args.report, app.report().dump(2) + "\n", "report");
    glfwSetWindowUserPointer(window, nullptr);
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

/// Text for roff: a hyphen as \- (it prints and searches as a minus), a line starting with . protected.
std::string roff(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((i == 0 || text[i - 1] == '\n') && text[i] == '.') out += "\\&";
    out += text[i] == '-' ? std::string("\\-") : text[i] == '\\' ? std::string("\\e") : std::string(1, text[i]);
  }
  return out;
}

/// The manual page (roff) from the options as declared (`sansui-viewer --man`; the build installs
/// it as sansui-viewer.1), so that it lists what --help lists.
std::string man_page(const CLI::App& app) {
  std::string out = fmt::format(
      ".\\\" Generated by `sansui-viewer --man` from its options; do not edit.\n"
      ".TH SANSUI\\-VIEWER 1 \"\" \"sansui-viewer {}\" \"User Commands\"\n"
      ".SH NAME\nsansui\\-viewer \\- front, side, top and perspective views of a scene, with its parameters live\n"
      ".SH SYNOPSIS\n.B sansui\\-viewer\n[\\fIOPTIONS\\fR]\n"
      ".SH DESCRIPTION\n"
      "The interactive viewer of Sansui: a scene file (a .toml recipe, or the .json sidecar of any output of\n"
      "\\fBsansui\\fR(1)) seen from four sides in one window, every parameter of the recipe edited live in panels made from\n"
      "the parameter tables, a walk through the terrain at eye height, and exports of the heightmap, mesh and picture.\n"
      "With \\fB\\-\\-script\\fR or \\fB\\-\\-screenshot\\fR it runs unattended and exits. It needs a display with OpenGL 3.3;\n"
      "pictures without one: \\fBsansui render\\fR, \\fBsansui run\\fR. Its menus, keys and script steps are described in\n"
      "docs/viewer.md (/usr/share/doc/sansui/docs/viewer.md when installed from the Debian packages).\n"
      ".SH OPTIONS\n",
      SANSUI_VERSION);
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_group().empty()) continue;  // CLI11's hidden options
    std::string names;
    for (const auto& name : option->get_snames()) names += (names.empty() ? "" : ", ") + fmt::format("\\fB{}\\fR", roff("-" + name));
    for (const auto& name : option->get_lnames()) names += (names.empty() ? "" : ", ") + fmt::format("\\fB{}\\fR", roff("--" + name));
    if (option->get_expected_max() > 0) names += " \\fIVALUE\\fR";
    out += fmt::format(".TP\n{}\n{}\n", names, roff(option->get_description()));
  }
  out +=
      ".SH EXIT STATUS\n"
      ".TP\n0\nsuccess\n"
      ".TP\n1\na step of the script failed, or an internal error\n"
      ".TP\n2\nbad input (an option, the scene file or the script): one line on standard error says which\n"
      ".TP\n3\nno display to open a window on\n"
      ".SH SEE ALSO\n\\fBsansui\\fR(1)\n";
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::io::remove_temporaries_on_signals();                // SIGINT, SIGTERM: no NAME.tmp-PID-N left behind
  sansui::scene::set_painter(&sansui::render::render_image);  // pictures: scene/painter.hpp
  CLI::App app("sansui-viewer: front, side, top and perspective views of a scene, with its parameters live");
  app.set_version_flag("--version", "sansui-viewer " SANSUI_VERSION);
  Arguments args;
  app.add_option("--scene", args.scene, "Scene file to open (.toml, or an output's .json sidecar)");
  app.add_option("--script", args.script, "Steps to run, from a file or given inline separated by ';' (see docs/viewer.md); exits after");
  app.add_option("--screenshot", args.screenshot, "Write the window's picture here once the scene is built (after the script), then exit");
  app.add_option("--report", args.report, "Write what happened (errors shown, walk log, frame and regeneration times) as JSON");
  app.add_option("--width", args.width, "Window width")->check(CLI::Range(320, 8192));
  app.add_option("--height", args.height, "Window height")->check(CLI::Range(240, 8192));
  app.add_option("--samples", args.samples, "Antialiasing samples of the panes")->check(CLI::Range(1, 16));
  app.add_flag("--no-recent", args.no_recent, "Do not read or keep the recent-files list");
  app.add_flag_callback(
      "--man",
      [&app] {
        std::fputs(man_page(app).c_str(), stdout);
        throw CLI::Success();
      },
      "Print the manual page (roff) and exit");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : exit_bad_input;
  }
  try {
    return run(args);
  } catch (const sansui::InputError& e) {
    std::fprintf(stderr, "sansui-viewer: %s\n", e.what());
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sansui-viewer: %s\n", e.what());
    return 1;
  }
}
