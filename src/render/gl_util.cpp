#include "render/gl_util.hpp"

#include <fmt/format.h>

namespace sansui::render {
namespace {

std::string shader_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, length, nullptr, log.data());
  return log;
}

std::string program_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(program, length, nullptr, log.data());
  return log;
}

GLuint compile(const char* name, GLenum kind, std::initializer_list<const char*> parts) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, static_cast<GLsizei>(parts.size()), parts.begin(), nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = shader_log(shader);
    glDeleteShader(shader);
    throw GlError(fmt::format("{} {} shader does not compile: {}", name, kind == GL_VERTEX_SHADER ? "vertex" : "fragment", log));
  }
  return shader;
}

}  // namespace

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    if (error == GL_OUT_OF_MEMORY)
      throw GlError(fmt::format("OpenGL ran out of memory in {}: try a smaller picture or heightfield", where));
    throw GlError(fmt::format("OpenGL error 0x{:04x} in {}", error, where));
  }
}

GLuint link_program(const char* name, std::initializer_list<const char*> vertex_parts, std::initializer_list<const char*> fragment_parts) {
  const GLuint vertex = compile(name, GL_VERTEX_SHADER, vertex_parts);
  GLuint fragment = 0;
  try {
    fragment = compile(name, GL_FRAGMENT_SHADER, fragment_parts);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    const std::string log = program_log(program);
    glDeleteProgram(program);
    throw GlError(fmt::format("{} shader program does not link: {}", name, log));
  }
  return program;
}

GlName make_texture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return {id, [](GLuint name) { glDeleteTextures(1, &name); }};
}
GlName make_buffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return {id, [](GLuint name) { glDeleteBuffers(1, &name); }};
}
GlName make_vertex_array() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return {id, [](GLuint name) { glDeleteVertexArrays(1, &name); }};
}
GlName make_framebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return {id, [](GLuint name) { glDeleteFramebuffers(1, &name); }};
}
GlName make_renderbuffer() {
  GLuint id = 0;
  glGenRenderbuffers(1, &id);
  return {id, [](GLuint name) { glDeleteRenderbuffers(1, &name); }};
}
GlName make_program(GLuint id) {
  return {id, [](GLuint name) { glDeleteProgram(name); }};
}

}  // namespace sansui::render
