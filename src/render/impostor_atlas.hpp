// Impostors of plants: each plant kind (species and variant) drawn once, from several sides and
// from above, into one layer of a 2-D array texture of albedo and another of normals, with mip
// levels made on the CPU. Far plants are then cards showing the view nearest to the camera's
// direction (render/plant_shaders.cpp), lit by the same light as the meshes, so a plant that
// changes from mesh to impostor keeps its colour.
//
// A layer: side views one cell wide each (a cell is 64 x 128 texels, the plant's full height
// over its bounding diameter), the camera going round the plant counter-clockwise seen from
// above starting from the south (view k from local direction (sin, 0, cos)(2 pi k / side_views)),
// then the view from above in a 128 x 128 cell, north up. Row 0 is the bottom (GL's order).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/color.hpp"
#include "look/plant_models.hpp"
#include "render/gl_util.hpp"

namespace sansui::render {

struct ImpostorLayout {
  static constexpr int side_views = 8;
  static constexpr int cell_width = 64, cell_height = 128;
  static constexpr int layer_width = (side_views + 2) * cell_width, layer_height = cell_height;
  /// Mip levels 0..levels-1: at the last, a side cell is 2 x 4 texels.
  static constexpr int levels = 6;
  /// The views are drawn this many times larger per side and averaged down (antialiasing).
  static constexpr int supersample = 2;
};

/// One layer's texels at every level, from its supersampled capture: albedo as sRGB with
/// coverage in alpha, and normals as n * 0.5 + 0.5 with the leaf flag in alpha. Colours are
/// averaged weighted by coverage, so edges do not darken; uncovered texels take their cell's
/// mean, so that filtering across an edge does not pull in black.
struct ImpostorLevels {
  std::vector<std::vector<Rgba8>> albedo, normal;  ///< [level][row * width + column]
};
/// `albedo` and `normal`: the layer drawn at ImpostorLayout::supersample times its size, row 0 at
/// the bottom; albedo's alpha is 255 where the plant covers the texel, 0 elsewhere.
ImpostorLevels impostor_levels(std::span<const Rgba8> albedo, std::span<const Rgba8> normal);

/// A plant to capture: its triangles in the bound element buffer and its bounds.
struct ImpostorSource {
  std::int64_t first_index = 0, index_count = 0;
  look::PlantBounds bounds;
};

/// Draws every source into its layer of the two array textures (which it (re)allocates:
/// GL_SRGB8_ALPHA8 and GL_RGBA8, ImpostorLayout's size, sources.size() layers, mipmapped).
/// `program`: the capture shaders; `vertex_array`: attributes 0-2 of the plant vertices and the
/// element buffer. Restores the framebuffer binding and viewport. Needs a current GL context.
void build_impostor_atlas(GLuint program, GLuint vertex_array, std::span<const ImpostorSource> sources, GLuint albedo_texture,
                          GLuint normal_texture);

}  // namespace sansui::render
