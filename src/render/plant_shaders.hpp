// GLSL 3.30 core sources of the plant passes (render/plant_renderer.hpp). Each stage is compiled
// from shaders::common (render/shaders.hpp), then plant_common, then the pass's own part.
#pragma once

namespace sansui::render::shaders {

/// The turn about the vertical and the light on a plant's surface, shared by meshes and impostors.
extern const char* const plant_common;
/// Instanced plant meshes (full and simplified), lit per vertex.
extern const char* const plant_mesh_vertex;
extern const char* const plant_mesh_fragment;
/// Impostors: one upright card per plant facing the camera, textured from the atlas; the
/// fragment shaders of cards and sprites start with plant_impostor_shading.
extern const char* const plant_impostor_shading;
extern const char* const plant_impostor_vertex;
extern const char* const plant_impostor_fragment;
/// The smallest impostors: one point sprite each, showing the same card.
extern const char* const plant_sprite_vertex;
extern const char* const plant_sprite_fragment;
/// Trees' shadows on the ground (look::ShadowVertex): a quad per tree multiplying the terrain's colour.
extern const char* const plant_shadow_vertex;
extern const char* const plant_shadow_fragment;
/// Filling the impostor atlas: a plant mesh's albedo and normal, seen from one side or from above.
extern const char* const plant_capture_vertex;
extern const char* const plant_capture_fragment;

}  // namespace sansui::render::shaders
