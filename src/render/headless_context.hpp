// An OpenGL 3.3 core context with no window and no display, through Mesa's EGL surfaceless
// platform (EGL_MESA_platform_surfaceless + EGL_KHR_surfaceless_context): the CLI and CI draw
// pictures on machines without X or Wayland (llvmpipe, Mesa's software rasteriser, gives GL
// 4.5 core). Only context creation lives here; drawing goes through TerrainRenderer into an
// OffscreenTarget, so the viewer can use the same renderer in a GLFW window.
#pragma once

#include <string>

namespace sansui::render {

class HeadlessContext {
 public:
  /// Creates the context and makes it current on this thread. Throws GlError saying what is
  /// missing when EGL, the surfaceless platform or GL 3.3 core is not available.
  HeadlessContext();
  /// Releases and destroys the context (it must not be current on another thread). The EGL
  /// display stays initialised for the next context, until the process ends.
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  /// Makes the context current on the calling thread again.
  void make_current() const;
  /// GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
  std::string description() const;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
};

}  // namespace sansui::render
