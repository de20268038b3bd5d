// GLSL 3.30 core sources of the terrain, water and sky passes. Each stage is compiled from two
// parts: `common` (the #version line, shared uniforms and helpers), then the pass's own.
#pragma once

namespace sansui::render::shaders {

extern const char* const common;
/// What the sky shows toward a point of the screen (after `common`, for the sky and the stars).
extern const char* const backdrop;
/// Full-screen sky gradient (perspective) or plain background (top view).
extern const char* const sky_vertex;
extern const char* const sky_fragment;
/// The stars, a point of a pixel each, added over the sky where its clouds let them through.
extern const char* const star_vertex;
extern const char* const star_fragment;
/// The terrain surface and the earth-coloured sides of the terrain block.
extern const char* const terrain_vertex;
extern const char* const terrain_fragment;
/// The sea: a plane at sea level, tinted and made opaque by the depth of the ground under it.
extern const char* const water_vertex;
extern const char* const water_fragment;

}  // namespace sansui::render::shaders
