// A framebuffer object to draw a picture into without a window: a multisampled colour + depth
// target that is resolved and read back as an Image (row 0 = top).
#pragma once

#include "core/color.hpp"
#include "render/gl_util.hpp"

namespace sansui::render {

class OffscreenTarget {
 public:
  /// Needs a current GL 3.3 context. `samples` per pixel for antialiasing is clamped to the
  /// driver's GL_MAX_SAMPLES (1: no multisampling). Leaves the target bound for drawing.
  /// [Range: width, height 1..GL_MAX_RENDERBUFFER_SIZE]
  OffscreenTarget(int width, int height, int samples = 4);

  /// Binds the target as the draw framebuffer, with the viewport covering it.
  void bind() const;
  /// Resolves the samples and reads the picture back (RGBA8, row 0 = top, alpha 255).
  Image read_pixels() const;

  /// Copies the picture (resolving its samples) into the default framebuffer (a window's) with
  /// its lower-left corner at (x, y) there, stretched (bilinear) to width x height. Leaves
  /// framebuffer 0 bound.
  void blit_to_window(int x, int y, int width, int height) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  int width_, height_, samples_;
  GlName colour_, depth_, framebuffer_;            // what is drawn into (multisampled)
  GlName resolved_colour_, resolved_framebuffer_;  // single-sample copy for reading back
};

}  // namespace sansui::render
