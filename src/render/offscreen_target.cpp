#include "render/offscreen_target.hpp"

#include <algorithm>
#include <cstring>
#include <vector>

#include <fmt/format.h>

namespace sansui::render {
namespace {

void check_complete(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw GlError(fmt::format("{} framebuffer is incomplete (0x{:04x})", what, status));
}

}  // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples) : width_(width), height_(height) {
  GLint max_size = 0, max_samples = 1;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  if (width < 1 || height < 1 || width > max_size || height > max_size)
    throw GlError(fmt::format("a {}x{} picture is larger than this OpenGL allows ({} pixels per side)", width, height, max_size));
  samples_ = std::clamp(samples, 1, std::max(1, static_cast<int>(max_samples)));

  // The multisampled target: colour and depth renderbuffers.
  colour_ = make_renderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, colour_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_RGBA8, width, height);
  depth_ = make_renderbuffer();
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_ > 1 ? samples_ : 0, GL_DEPTH_COMPONENT24, width, height);
  framebuffer_ = make_framebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  check_complete("drawing");

  // The single-sample copy that the samples resolve into.
  if (samples_ > 1) {
    resolved_colour_ = make_renderbuffer();
    glBindRenderbuffer(GL_RENDERBUFFER, resolved_colour_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    resolved_framebuffer_ = make_framebuffer();
    glBindFramebuffer(GL_FRAMEBUFFER, resolved_framebuffer_.id());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, resolved_colour_.id());
    check_complete("resolve");
  }
  check_gl("creating the offscreen target");
  bind();
}

void OffscreenTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

void OffscreenTarget::blit_to_window(int x, int y, int width, int height) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  if (samples_ > 1) {
    // A multisampled source resolves only into a rectangle of its own size and place: resolve
    // first, then copy.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_.id());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved_framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  }
  const bool same_size = width == width_ && height == height_;
  glBlitFramebuffer(0, 0, width_, height_, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, same_size ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Image OffscreenTarget::read_pixels() const {
  GLuint source = framebuffer_.id();
  if (samples_ > 1) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolved_framebuffer_.id());
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    source = resolved_framebuffer_.id();
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<Rgba8> pixels(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  check_gl("reading the picture back");
  bind();

  // GL's row 0 is the bottom; an Image's is the top.
  auto image = Image::uninitialized(width_, height_);
  const auto row_bytes = static_cast<std::size_t>(width_) * sizeof(Rgba8);
  for (int y = 0; y < height_; ++y)
    std::memcpy(image.row(y).data(), pixels.data() + static_cast<std::size_t>(height_ - 1 - y) * width_, row_bytes);
  for (Rgba8& pixel : image.values()) pixel.a = 255;
  return image;
}

}  // namespace sansui::render
