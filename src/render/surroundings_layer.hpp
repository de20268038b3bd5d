// The land around the terrain on the GPU (look/surroundings.hpp): its mesh, its height and
// shading textures, and the axes the shaders need to place its uneven grid. Needs a current
// GL 3.3 core context.
#pragma once

#include <glm/glm.hpp>

#include "look/surroundings.hpp"
#include "render/gl_util.hpp"

namespace sansui::render {

class SurroundingsLayer {
 public:
  /// Uploads `s`; `terrain_size_m` is the terrain's longer side (the band noises' scale).
  void upload(const look::Surroundings& s, double terrain_size_m);
  void clear() { index_count_ = 0; }
  bool empty() const { return index_count_ == 0; }

  /// Per axis: centre, half extent (m), border fraction, growth (the shaders' u_ring_x, u_ring_z).
  glm::vec4 x_axis() const { return x_axis_; }
  glm::vec4 z_axis() const { return z_axis_; }
  double reach_m() const { return reach_m_; }
  double mirror_reach_m() const { return mirror_reach_m_; }
  GLuint surface_texture() const { return surface_texture_.id(); }
  GLuint shading_texture() const { return shading_texture_.id(); }
  /// Draws the mesh (the terrain program bound, its textures set). Primitive restart on.
  void draw() const;

 private:
  GlName vertex_array_, vertices_, indices_, surface_texture_, shading_texture_;
  int index_count_ = 0;
  glm::vec4 x_axis_{0.0f}, z_axis_{0.0f};
  double reach_m_ = 0.0, mirror_reach_m_ = 0.0;
};

}  // namespace sansui::render
