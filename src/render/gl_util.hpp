// Small OpenGL helpers for render/: errors, shader programs, owned GL names. Functions are
// loaded by libepoxy, so this works in any current GL 3.3 core context (EGL or GLFW).
#pragma once

#include <initializer_list>
#include <utility>

#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "render/gl_error.hpp"

namespace sansui::render {

/// Throws GlError naming `where` if glGetError reports an error.
void check_gl(const char* where);

/// Compiles and links a vertex + fragment shader pair, each stage's source the concatenation
/// of its parts; throws GlError with the compiler's log.
GLuint link_program(const char* name, std::initializer_list<const char*> vertex_parts, std::initializer_list<const char*> fragment_parts);

/// One owned GL name (texture, buffer, program, ...), deleted with `destroy` when dropped.
class GlName {
 public:
  using Destroy = void (*)(GLuint);
  GlName() = default;
  GlName(GLuint id, Destroy destroy) : id_(id), destroy_(destroy) {}
  ~GlName() { reset(); }
  GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)), destroy_(other.destroy_) {}
  GlName& operator=(GlName&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
      destroy_ = other.destroy_;
    }
    return *this;
  }
  GlName(const GlName&) = delete;
  GlName& operator=(const GlName&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0 && destroy_ != nullptr) destroy_(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
  Destroy destroy_ = nullptr;
};

GlName make_texture();
GlName make_buffer();
GlName make_vertex_array();
GlName make_framebuffer();
GlName make_renderbuffer();
GlName make_program(GLuint id);

/// Sets uniforms of a program, which it makes current; names the shaders do not use are ignored.
class Uniforms {
 public:
  explicit Uniforms(GLuint program) : program_(program) { glUseProgram(program); }
  void set(const char* name, float value) const { glUniform1f(at(name), value); }
  void set(const char* name, double value) const { glUniform1f(at(name), static_cast<float>(value)); }
  void set(const char* name, int value) const { glUniform1i(at(name), value); }
  void set(const char* name, glm::vec2 value) const { glUniform2f(at(name), value.x, value.y); }
  void set(const char* name, glm::vec3 value) const { glUniform3f(at(name), value.x, value.y, value.z); }
  void set(const char* name, glm::vec4 value) const { glUniform4f(at(name), value.x, value.y, value.z, value.w); }
  void set(const char* name, const glm::mat4& value) const { glUniformMatrix4fv(at(name), 1, GL_FALSE, glm::value_ptr(value)); }

 private:
  GLint at(const char* name) const { return glGetUniformLocation(program_, name); }
  GLuint program_;
};

}  // namespace sansui::render
