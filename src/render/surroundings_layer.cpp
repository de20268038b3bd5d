#include "render/surroundings_layer.hpp"

#include <cstdint>
#include <vector>

namespace sansui::render {
namespace {

glm::vec4 axis_uniform(const look::SurroundingsAxis& axis) {
  const double middle = 0.5 * (axis.samples - 1);
  return {static_cast<float>(axis.centre_m), static_cast<float>(axis.half_m), static_cast<float>(axis.inner / middle),
          static_cast<float>(axis.growth)};
}

void set_linear_clamped() {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

void SurroundingsLayer::upload(const look::Surroundings& s, double terrain_size_m) {
  if (!vertex_array_) {
    vertex_array_ = make_vertex_array();
    vertices_ = make_buffer();
    indices_ = make_buffer();
    surface_texture_ = make_texture();
    shading_texture_ = make_texture();
  }
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(s.vertices.size() * sizeof(float)), s.vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(s.indices.size() * sizeof(std::uint32_t)), s.indices.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);

  const int columns = s.x_axis.samples, rows = s.z_axis.samples;
  glBindTexture(GL_TEXTURE_2D, surface_texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, columns, rows, 0, GL_RGBA, GL_FLOAT, s.surface_texels.data());
  set_linear_clamped();
  const std::vector<std::uint8_t> shading = look::surroundings_shading_texels(s, terrain_size_m);
  glBindTexture(GL_TEXTURE_2D, shading_texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, columns, rows, 0, GL_RGBA, GL_UNSIGNED_BYTE, shading.data());
  set_linear_clamped();
  check_gl("uploading the surroundings");

  index_count_ = static_cast<int>(s.indices.size());
  x_axis_ = axis_uniform(s.x_axis);
  z_axis_ = axis_uniform(s.z_axis);
  reach_m_ = s.reach_m;
  mirror_reach_m_ = s.mirror_reach_m;
}

void SurroundingsLayer::draw() const {
  if (empty()) return;
  glBindVertexArray(vertex_array_.id());
  glDrawElements(GL_TRIANGLE_STRIP, index_count_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace sansui::render
