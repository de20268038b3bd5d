// The plant shaders. Plants are lit like the terrain (shaders.cpp: a sun times its visibility plus
// sky light), with two differences: the sun and sky visibility and the fog are worked out once per
// plant on the CPU (look/plant_lod.cpp) and arrive as instance attributes, because llvmpipe runs
// vertex shaders on one thread and a texture read per vertex would cost more than the whole
// plant; and leaves are thin, so light that reaches their back shows through (a wrapped diffuse
// term) instead of leaving the shaded side of a crown black.
#include "render/plant_shaders.hpp"

namespace sansui::render::shaders {

const char* const plant_common = R"(
// A plant's turn about the vertical (cos, sin): local x goes to world (cos, 0, -sin).
vec3 turn(vec3 p, vec2 cs) { return vec3(cs.x * p.x + cs.y * p.z, p.y, -cs.y * p.x + cs.x * p.z); }

// Sunlight times its visibility, and sky light from above, as on the terrain (shaders.cpp).
// Leaves (leaf = 1) let light through: half the light falling on their back reaches the eye.
vec3 plant_light(vec3 normal, float leaf, float sun, float sky) {
  float facing = dot(normal, u_sun_dir);
  float diffuse = mix(max(facing, 0.0), max(facing + 0.5, 0.0) / 1.5, leaf);
  return u_sun_light * diffuse * sun + u_sky_light * sky * (0.6 + 0.4 * normal.y);
}
)";

// Per vertex: attributes 0-2 (look/plant_models.hpp); per instance: 3-6 (look::PlantInstance in
// look/plant_lod.hpp).
const char* const plant_mesh_vertex = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_normal;  // xyz: normal, w: 1 leaf, 0 wood
layout(location = 2) in vec4 a_albedo;  // linear
layout(location = 3) in vec4 a_place;   // x, ground y, z, scale
layout(location = 4) in vec4 a_turn;    // cos, sin, sun visibility, sky visibility
layout(location = 5) in vec4 a_haze;    // haze colour, fog fraction
out vec3 v_colour;
void main() {
  vec3 world = a_place.xyz + turn(a_position * a_place.w, a_turn.xy);
  vec3 normal = turn(normalize(a_normal.xyz), a_turn.xy);
  vec3 lit = a_albedo.rgb * plant_light(normal, a_normal.w, a_turn.z, a_turn.w);
  // Lit per vertex and turned to sRGB here: a plant's triangles are a few pixels at most, and
  // per-fragment work is what a software rasteriser pays most for.
  v_colour = to_srgb(mix(lit, a_haze.rgb, a_haze.a));
  gl_Position = u_view_proj * vec4(world, 1.0);
}
)";

const char* const plant_mesh_fragment = R"(
in vec3 v_colour;
out vec4 o_colour;
void main() { o_colour = vec4(v_colour, 1.0); }
)";

const char* const plant_impostor_vertex = R"(
layout(location = 3) in vec4 a_place;
layout(location = 4) in vec4 a_turn;
layout(location = 5) in vec4 a_haze;
layout(location = 6) in vec4 a_box;     // radius, bottom, top at scale 1; kind * 16 + view (look/plant_lod.hpp)
layout(location = 7) in vec2 a_corner;  // the card's corner, 0..1 across and up
uniform int u_side_views;  // views around the plant in the atlas, then the view from above
uniform vec3 u_card_right, u_card_up;
out vec3 v_texcoord;
flat out vec4 v_turn;
flat out vec4 v_haze;
void main() {
  float scale = a_place.w;
  float radius = a_box.x * scale, bottom = a_box.y * scale, top = a_box.z * scale;
  float layer = floor(a_box.w / 16.0), view = a_box.w - 16.0 * layer;
  // A layer of the atlas: the side views one cell wide each, the view from above two.
  float cells = float(u_side_views + 2);
  vec3 world;
  if (view >= float(u_side_views)) {
    // Seen from high above: the view from above, lying flat in the crown, north up in the atlas.
    vec2 local = (a_corner * 2.0 - 1.0) * radius;
    world = a_place.xyz + vec3(0.0, mix(bottom, top, 0.75), 0.0) + turn(vec3(local.x, 0.0, -local.y), a_turn.xy);
    v_texcoord = vec3((view + 2.0 * a_corner.x) / cells, a_corner.y, layer);
  } else {
    // A card across the view, upright but leaning back by half the camera's pitch (so that
    // a plant seen from above is not squashed to a sliver), showing the side view the CPU chose.
    world = a_place.xyz + u_card_right * ((a_corner.x * 2.0 - 1.0) * radius) + u_card_up * mix(bottom, top, a_corner.y);
    v_texcoord = vec3((view + a_corner.x) / cells, a_corner.y, layer);
  }
  v_turn = a_turn;
  v_haze = a_haze;
  gl_Position = u_view_proj * vec4(world, 1.0);
}
)";

const char* const plant_impostor_shading = R"(
uniform sampler2DArray u_impostor_albedo;  // sRGB albedo, alpha: coverage
uniform sampler2DArray u_impostor_normal;  // the plant's own normal * 0.5 + 0.5, a: leaf
uniform int u_alpha_to_coverage;

// Hoskins' "hash without sine" of a pixel position, in [0, 1).
float hash12(vec2 p) {
  vec3 p3 = fract(vec3(p.xyx) * 0.1031);
  p3 += dot(p3, p3.yzx + 33.33);
  return fract((p3.x + p3.y) * p3.z);
}

// Whether a texel of this coverage covers the pixel. Partly covered texels (edges, far mip
// levels) cover their share of the picture: through the multisampled target's
// alpha-to-coverage, or else a hashed alpha test (Wyman and McGuire 2017). No blending, so
// impostors need no sorting; and no discard with alpha-to-coverage, which would keep llvmpipe
// from testing depth before shading.
bool covers(float coverage) { return u_alpha_to_coverage != 0 || coverage >= max(hash12(gl_FragCoord.xy), 0.02); }

// An impostor's texel (albedo and stored normal) lit as the meshes are.
vec4 shade_impostor(vec4 albedo, vec4 stored, vec4 turn_light, vec4 haze) {
  vec3 normal = turn(normalize(stored.xyz * 2.0 - 1.0), turn_light.xy);
  vec3 lit = albedo.rgb * plant_light(normal, stored.a, turn_light.z, turn_light.w);
  return vec4(to_srgb(mix(lit, haze.rgb, haze.a)), albedo.a);
}
)";

const char* const plant_impostor_fragment = R"(
in vec3 v_texcoord;
flat in vec4 v_turn;
flat in vec4 v_haze;
out vec4 o_colour;
void main() {
  // One level sharper than the card's size asks for: the mesh it replaces is sharp, and the
  // multisampled coverage hides the aliasing.
  vec4 albedo = texture(u_impostor_albedo, v_texcoord, -1.0);
  if (!covers(albedo.a)) discard;
  o_colour = shade_impostor(albedo, texture(u_impostor_normal, v_texcoord, -1.0), v_turn, v_haze);
}
)";

const char* const plant_sprite_vertex = R"(
layout(location = 3) in vec4 a_place;
layout(location = 4) in vec4 a_turn;
layout(location = 5) in vec4 a_haze;
layout(location = 6) in vec4 a_box;  // as the cards'
uniform int u_side_views;
uniform vec3 u_card_up;
uniform float u_pixels_per_unit;  // pixels per metre at a view depth of 1 m (perspective) or per metre
uniform vec2 u_cell_texels;       // a side view's cell in the atlas, texels wide and high
flat out vec4 v_cell;    // the view's first u, its width in u, the atlas layer, 1 for the view from above
flat out vec2 v_extent;  // the card's width and height as fractions of the sprite's side
flat out float v_lod;    // the atlas level to read
flat out vec4 v_turn;
flat out vec4 v_haze;
void main() {
  float scale = a_place.w;
  float radius = a_box.x * scale, bottom = a_box.y * scale, top = a_box.z * scale;
  float layer = floor(a_box.w / 16.0), view = a_box.w - 16.0 * layer;
  float cells = float(u_side_views + 2);
  bool above = view >= float(u_side_views);
  // The card the sprite stands for (see plant_impostor_vertex), at its centre, in pixels.
  vec3 centre = above ? a_place.xyz + vec3(0.0, mix(bottom, top, 0.75), 0.0) : a_place.xyz + u_card_up * (0.5 * (bottom + top));
  gl_Position = u_view_proj * vec4(centre, 1.0);
  float pixels = u_pixels_per_unit / (u_orthographic != 0 ? 1.0 : max(gl_Position.w, 1e-3));
  vec2 card = (above ? vec2(2.0 * radius) : vec2(2.0 * radius, top - bottom)) * pixels;
  float side = max(max(card.x, card.y), 1.0);
  gl_PointSize = side;
  v_extent = card / side;
  // The level is worked out here: texture derivatives across a point sprite are not to be
  // relied on (llvmpipe's pick a level far too sharp). One level sharper, as the cards'.
  vec2 texels = above ? vec2(2.0 * u_cell_texels.x, u_cell_texels.y) : u_cell_texels;
  v_lod = max(log2(max(texels.x / max(card.x, 1e-3), texels.y / max(card.y, 1e-3))) - 1.0, 0.0);
  v_cell = vec4(view / cells, (above ? 2.0 : 1.0) / cells, layer, above ? 1.0 : 0.0);
  v_turn = a_turn;
  v_haze = a_haze;
}
)";

const char* const plant_sprite_fragment = R"(
flat in vec4 v_cell;
flat in vec2 v_extent;
flat in float v_lod;
flat in vec4 v_turn;
flat in vec4 v_haze;
out vec4 o_colour;
void main() {
  // gl_PointCoord runs right and down across the sprite; the card fills its middle.
  vec2 uv = vec2(0.5 + (gl_PointCoord.x - 0.5) / v_extent.x, 0.5 - (gl_PointCoord.y - 0.5) / v_extent.y);
  // The view from above is drawn turned as the plant is (exact in the top view, north up).
  if (v_cell.w > 0.5) uv = vec2(0.5) + mat2(v_turn.x, -v_turn.y, v_turn.y, v_turn.x) * (uv - 0.5);
  float inside = step(0.0, uv.x) * step(uv.x, 1.0) * step(0.0, uv.y) * step(uv.y, 1.0);
  vec3 texcoord = vec3(v_cell.x + clamp(uv.x, 0.0, 1.0) * v_cell.y, clamp(uv.y, 0.0, 1.0), v_cell.z);
  vec4 albedo = textureLod(u_impostor_albedo, texcoord, v_lod);
  albedo.a *= inside;
  if (!covers(albedo.a)) discard;
  o_colour = shade_impostor(albedo, textureLod(u_impostor_normal, texcoord, v_lod), v_turn, v_haze);
}
)";

const char* const plant_shadow_vertex = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_local;  // crown radii: away from the sun, across
layout(location = 2) in vec4 a_shape;  // the crown shadow's centre and half-length along, strength, trunk half-width
out vec2 v_local;
flat out vec4 v_shape;
void main() {
  v_local = a_local;
  v_shape = a_shape;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";

// The crown's shadow is a soft ellipse (the crown seen from the sun, stretched along the ground
// by the sun's elevation); the trunk's a thin band from the foot to it. The framebuffer holds
// sRGB, so the linear darkening is turned into an sRGB factor (about its 1 / 2.2 power).
const char* const plant_shadow_fragment = R"(
in vec2 v_local;
flat in vec4 v_shape;
out vec4 o_colour;
void main() {
  float along = v_local.x, across = v_local.y;
  float off = (along - v_shape.x) / v_shape.y;
  float crown = 1.0 - smoothstep(0.35, 1.0, off * off + across * across);
  float trunk = step(0.0, along) * step(along, v_shape.x) * (1.0 - smoothstep(0.5 * v_shape.w, v_shape.w, abs(across))) * 0.8;
  float shade = v_shape.z * max(crown, trunk);
  if (shade < 0.003) discard;
  o_colour = vec4(vec3(pow(1.0 - shade, 1.0 / 2.2)), 1.0);
}
)";

const char* const plant_capture_vertex = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_normal;
layout(location = 2) in vec4 a_albedo;
uniform mat4 u_capture;
out vec3 v_albedo;
out vec4 v_normal;
void main() {
  v_albedo = a_albedo.rgb;
  v_normal = a_normal;
  gl_Position = u_capture * vec4(a_position, 1.0);
}
)";

const char* const plant_capture_fragment = R"(
in vec3 v_albedo;
in vec4 v_normal;
layout(location = 0) out vec4 o_albedo;
layout(location = 1) out vec4 o_normal;
void main() {
  o_albedo = vec4(to_srgb(v_albedo), 1.0);
  o_normal = vec4(normalize(v_normal.xyz) * 0.5 + 0.5, v_normal.w);
}
)";

}  // namespace sansui::render::shaders
