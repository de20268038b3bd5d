#include "render/headless_context.hpp"

#include <string_view>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <fmt/format.h>

#include "render/gl_util.hpp"

namespace sansui::render {
namespace {

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const auto space = rest.find(' ');
    if (rest.substr(0, space) == name) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

[[noreturn]] void fail_egl(std::string_view what) {
  throw GlError(
      fmt::format("cannot create a headless OpenGL context: {} (EGL error 0x{:04x}); "
                  "Mesa's EGL (libegl-mesa0, libgl1-mesa-dri) is needed",
                  what, eglGetError()));
}

}  // namespace

HeadlessContext::HeadlessContext() {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_extensions, "EGL_EXT_platform_base") || !has_extension(client_extensions, "EGL_MESA_platform_surfaceless"))
    fail_egl("EGL has no surfaceless platform (EGL_MESA_platform_surfaceless)");

  EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) fail_egl("no surfaceless EGL display");
  EGLint major = 0, minor = 0;  // initialising an initialised display is a no-op
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) fail_egl("eglInitialize failed");
  display_ = display;

  auto give_up = [&](std::string_view what) {
    const EGLint error = eglGetError();
    eglReleaseThread();
    throw GlError(fmt::format("cannot create a headless OpenGL context: {} (EGL error 0x{:04x})", what, error));
  };
  const char* display_extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!has_extension(display_extensions, "EGL_KHR_surfaceless_context")) give_up("no EGL_KHR_surfaceless_context");
  if (!has_extension(display_extensions, "EGL_KHR_no_config_context") && !has_extension(display_extensions, "EGL_MESA_configless_context"))
    give_up("no EGL_KHR_no_config_context");
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) give_up("no desktop OpenGL API");

  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT) give_up("no OpenGL 3.3 core context");
  context_ = context;
  if (eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    eglDestroyContext(display, context);
    give_up("eglMakeCurrent failed");
  }
}

HeadlessContext::~HeadlessContext() {
  auto* display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  // The display is left initialised, never eglTerminate'd: EGL hands out one display per
  // platform and process, shared by every context on it (eglTerminate would end it for other
  // users too), and Mesa unloads its driver there, leaking a few bytes that LeakSanitizer
  // then reports from an unknown (unloaded) module, where no suppression can name them.
  eglReleaseThread();
}

void HeadlessContext::make_current() const {
  if (eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_)) != EGL_TRUE)
    fail_egl("eglMakeCurrent failed");
}

std::string HeadlessContext::description() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return fmt::format("{}, {}", renderer != nullptr ? renderer : "?", version != nullptr ? version : "?");
}

}  // namespace sansui::render
