// The shaders. Colours arrive linear (the C++ side converts the sRGB palette) and leave as
// sRGB; lighting is a sun (Lambert diffuse times the CPU-traced sun visibility) plus sky light
// (times the ambient occlusion), then distance fog toward the sky's colour near the horizon.
// Colour bands follow Oka et al. 1997 (seeds/003, Sec. 4.1.2; SPEC 3.2).
#include "render/shaders.hpp"

namespace sansui::render::shaders {

// Declarations and helpers every pass shares. Drawing coordinates: x east, z south (metres
// from the north-west sample), y = (height - sea level) * exaggeration.
const char* const common = R"(#version 330 core
uniform sampler2D u_surface;   // per sample: true height (m), dh/dx east, dh/dz south
uniform sampler2D u_shading;   // r: sun visibility, g: open sky (ambient occlusion), b, a: band noises
uniform sampler2D u_noise;     // tileable fractal noise, two channels, repeats
uniform vec2 u_extent;         // metres east and south between the outer samples
uniform float u_terrain_size;  // the longer of the two, metres
uniform float u_sea_level;     // metres
uniform float u_exaggeration;
uniform mat4 u_view_proj;
uniform vec3 u_camera_pos;
uniform vec3 u_camera_forward;
uniform int u_orthographic;
uniform vec3 u_sun_dir;        // unit vector toward the sun
uniform vec3 u_sun_light;      // linear colour times strength
uniform vec3 u_sky_light;      // linear ambient light from the sky
uniform sampler2D u_sky;       // the sky dome (look/sky_dome.hpp): linear rgb, cloud cover in a
uniform float u_time;          // seconds, for the ripples' motion
uniform float u_fog_density;   // per terrain size of distance beyond the nearest terrain point
uniform float u_fog_start;     // distance from the camera to the nearest terrain point, metres

// Texture coordinate of a point given as fractions (0..1) of the terrain: sample i of n sits
// at the centre of texel i.
vec2 texcoord(sampler2D tex, vec2 uv) {
  vec2 size = vec2(textureSize(tex, 0));
  return (uv * (size - 1.0) + 0.5) / size;
}
float height_at(vec2 uv) { return textureLod(u_surface, texcoord(u_surface, uv), 0.0).r; }

// Value noise along one axis from an arithmetic hash (Hoskins' "hash without sine"): no
// texture read, and no sin, whose precision differs between drivers.
float hash11(float p) {
  p = fract(p * 0.1031);
  p *= p + 33.33;
  p *= p + p;
  return fract(p);
}
float noise1(float x) {
  float i = floor(x), f = fract(x);
  return mix(hash11(i), hash11(i + 1.0), f * f * (3.0 - 2.0 * f));
}

// The sky dome's texel toward an azimuth (radians, clockwise from north) and an elevation
// (degrees): the dome spans the elevations 90 (top row) down to -10 (look/sky_dome.hpp).
vec4 sky_texel(float azimuth, float elevation_deg) {
  float u = fract(azimuth / 6.28318530718);
  float v = clamp((90.0 - elevation_deg) / 100.0, 0.0, 1.0);
  return texture(u_sky, vec2(u, v));
}
float azimuth_of(vec3 dir) { return atan(dir.x, -dir.z); }
float elevation_of(vec3 dir) { return degrees(asin(clamp(dir.y, -1.0, 1.0))); }

// The sky in a direction (for reflections on the water and the haze).
vec3 sky_colour(vec3 dir) { return sky_texel(azimuth_of(dir), elevation_of(dir)).rgb; }

// Aerial perspective: the farther behind the terrain's nearest point, the more the colour turns
// to the sky's near the horizon (counted from the nearest point, so that the near edge stays
// clear however far the camera stands).
vec3 apply_fog(vec3 colour, vec3 world) {
  if (u_orthographic != 0 || u_fog_density <= 0.0) return colour;
  vec3 offset = world - u_camera_pos;
  float distance = length(offset);
  float fog = 1.0 - exp(-u_fog_density * max(distance - u_fog_start, 0.0) / u_terrain_size);
  // The haze is the sky just above the horizon in that direction.
  vec2 level = normalize(offset.xz + vec2(1e-6, 0.0));
  vec3 haze = sky_texel(atan(level.x, -level.y), 2.0).rgb;
  return mix(colour, haze, fog);
}

// Linear light to sRGB for an RGBA8 target.
vec3 to_srgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c));
}
)";

const char* const sky_vertex = R"(
out vec2 v_ndc;
void main() {
  // One triangle that covers the screen.
  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
  v_ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
)";

const char* const sky_fragment = R"(
uniform mat4 u_inverse_view_proj;
uniform vec3 u_background;     // linear, for the top view
uniform int u_true_sky;        // 1: a walker looks around, the sky is where it is
uniform sampler2D u_sun_disc;  // along x the distance from the disc's centre (act, Table 3): rgb colour, a opacity
uniform float u_sun_radius;    // the disc's angular radius, radians
in vec2 v_ndc;
out vec4 o_colour;
void main() {
  if (u_orthographic != 0) {
    o_colour = vec4(to_srgb(u_background), 1.0);
    return;
  }
  vec4 near = u_inverse_view_proj * vec4(v_ndc, -1.0, 1.0);
  vec4 far = u_inverse_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  // A bird's-eye camera looks down, and its picture's top may still be below the true horizon:
  // the backdrop then spreads the sky from the horizon (bottom) to 60 degrees up (top), in the
  // true azimuth; a camera that looks up sees the true directions.
  float up = clamp(0.5 + 0.5 * v_ndc.y, 0.0, 1.0);
  float elevation = u_true_sky != 0 ? elevation_of(dir) : max(elevation_of(dir), 60.0 * pow(up, 1.2));
  float azimuth = azimuth_of(dir);
  vec4 sky = sky_texel(azimuth, elevation);
  vec3 seen = vec3(cos(radians(elevation)) * sin(azimuth), sin(radians(elevation)), -cos(radians(elevation)) * cos(azimuth));
  float act = acos(clamp(dot(seen, u_sun_dir), -1.0, 1.0)) / u_sun_radius;
  vec3 colour = sky.rgb;
  if (act < 1.0) {
    vec4 disc = texture(u_sun_disc, vec2(act, 0.5));
    colour = mix(colour, disc.rgb, disc.a * (1.0 - sky.a));
  }
  o_colour = vec4(to_srgb(colour), 1.0);
}
)";

const char* const terrain_vertex = R"(
// x, y: the point as fractions of the terrain (east, south); z: its true height in metres;
// w: 0 on the surface, 1 at the top of a side of the block (the ground, or the sea surface
// where that is higher), 2 at its base.
layout(location = 0) in vec4 a_vertex;
uniform float u_base_y;
out vec2 v_uv;
out vec3 v_world;
out float v_side;
void main() {
  vec2 uv = a_vertex.xy;
  float ground = (a_vertex.z - u_sea_level) * u_exaggeration;
  // The sea floor is cut off at the block's base (deeper water is opaque anyway).
  ground = max(ground, u_base_y);
  float y = a_vertex.w > 1.5 ? u_base_y : (a_vertex.w > 0.5 ? max(ground, 0.0) : ground);
  v_uv = uv;
  v_side = a_vertex.w > 0.5 ? 1.0 : 0.0;
  v_world = vec3(uv.x * u_extent.x, y, uv.y * u_extent.y);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

const char* const terrain_fragment = R"(
uniform sampler2D u_cliff_albedo;  // sRGB texture: rock colour per sample, if present
uniform int u_has_cliff_albedo;
uniform float u_max_above_sea;     // metres: the highest sample's height above sea level
uniform float u_band_scale;        // metres: the same, at least look/render_params.hpp: min_band_relief_m
uniform float u_beach_top, u_tree_line, u_snow_line, u_blend, u_border_noise;  // fractions of u_band_scale
uniform float u_cliff_slope, u_cliff_blend, u_snow_max_slope;                  // degrees
uniform float u_ambient_occlusion;  // 0..1
uniform int u_shadows;
uniform vec3 u_seabed, u_beach, u_forest_low, u_forest_high, u_cliff, u_snow, u_earth;  // linear
uniform vec3 u_water_shallow, u_water_deep;                                            // linear
uniform sampler2D u_surface_water;  // rivers and lakes: r metres of water on the ground, g wetness 0..1
uniform int u_has_surface_water;
uniform sampler2D u_ground;         // landforms (look/ground_maps.hpp): r wetness, g curvature ~40 m, b scree, a curvature ~250 m
uniform sampler2D u_detail;         // near-view detail, tiled: rg slope, b height, a colour noise
uniform float u_detail_gradient_scale;  // the detail texture's slope per tile width where rg is 1
uniform float u_texel_m;            // metres between the height texture's samples
uniform vec2 u_sunny_dir;           // horizontal unit vector (x east, z south) toward the sunny side (the equator)
in vec2 v_uv;
in vec3 v_world;
in float v_side;
out vec4 o_colour;

// 0 below edge - width/2, 1 above edge + width/2, linear between: the paper's linear blend.
float ramp(float edge, float width, float x) { return clamp((x - edge) / max(width, 1e-4) + 0.5, 0.0, 1.0); }
float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec3 rock_colour(float height_m, float patches) {
  if (u_has_cliff_albedo != 0) return texture(u_cliff_albedo, texcoord(u_cliff_albedo, v_uv)).rgb;
  // Faint horizontal strata and blotches, so bare rock is not one flat colour.
  float strata = noise1(height_m / (0.012 * u_max_above_sea));
  return u_cliff * (0.75 + 0.3 * strata + 0.3 * (patches - 0.5));
}

// What the ground is made of at a point, and how rough it is (for the detail normals).
struct Ground {
  vec3 albedo;
  float roughness;  // 0 smooth (sand, snow) .. 1 bare rock
};

// The ground's colour (seeds/003, Sec. 4.1.2, grown into landform rules): elevation bands whose
// borders wander with a world-space noise; vegetation that dries out on convex ridges and sunny
// faces and greens up in hollows and wet valley floors; bare soil on slopes too steep to hold a
// sward; rock on steep faces and exposed crests; scree where debris from cliffs comes to rest;
// sand only at beach height; snow above the snow line, lower on shady faces. `noise`: the band
// noises baked with the shadows; `land`: the landform maps; `fine_curvature`: at the height
// texture's own scale; `normal`: the true (unexaggerated) surface normal.
Ground ground_albedo(float height_m, float slope_deg, vec3 normal, vec2 noise, vec4 land, float fine_curvature) {
  float above_sea = height_m - u_sea_level;
  float e = above_sea / u_band_scale;
  // Band borders wander with a smooth noise over the ground, so they do not trace contours.
  float wander = (noise.x - 0.5) * 2.0 * u_border_noise;
  float eb = e + wander;
  float patches = noise.y;
  float wet = land.r;
  float scree = land.b;
  // Concave (valley floors, hollows) > 0 > convex (ridges, crests), from three scales.
  float concave = clamp(0.7 * (land.g * 2.0 - 1.0) + 0.6 * (land.a * 2.0 - 1.0) + 2.0 * fine_curvature, -1.0, 1.0);
  // +1 on a 25-degree face turned to the sunny side, -1 turned away, 0 on flat ground.
  float sunny = clamp(dot(normal.xz, u_sunny_dir) * 2.4, -1.0, 1.0);

  // Vegetation by altitude, then by dryness.
  float forest_position = clamp((eb - u_beach_top) / max(u_tree_line - u_beach_top, 1e-4), 0.0, 1.0);
  vec3 plants = mix(u_forest_low, u_forest_high, forest_position);
  float dry = clamp(0.45 - 0.7 * concave + 0.3 * sunny - 1.2 * wet + (patches - 0.5) * 0.9, 0.0, 1.0);
  // Only a green palette turns greener where it is wet and yellower where it is dry: a desert's
  // "vegetation" (sand and gravel) only darkens and lightens.
  float green_palette = clamp(3.0 * (plants.g - max(plants.r, plants.b)) / max(plants.g, 1e-3), 0.0, 1.0);
  vec3 lush = plants * mix(vec3(0.85), vec3(0.7, 1.15, 0.65), green_palette);
  // Dry grass and scrub: yellower and lighter, still the climate's own vegetation.
  vec3 parched = plants * mix(vec3(1.15), vec3(1.5, 1.2, 0.7), green_palette);
  vec3 colour = mix(lush, parched, dry) * (0.8 + 0.4 * patches);
  float roughness = 0.45;

  // Bare soil on slopes too steep for a sward (not where water gathers).
  vec3 soil = mix(u_earth, u_cliff, 0.45) * 0.8;
  float soil_weight = ramp(u_cliff_slope - 4.0 + 12.0 * min(concave, 0.0), 8.0, slope_deg + (patches - 0.5) * 14.0) *
                      clamp(0.6 - concave, 0.0, 1.0) * (1.0 - wet);
  colour = mix(colour, soil, soil_weight);
  roughness = mix(roughness, 0.6, soil_weight);

  // Above the tree line: alpine turf in gentle hollows, rock on crests and higher up.
  vec3 rock = rock_colour(height_m, patches);
  vec3 turf = mix(u_forest_high, u_beach, 0.35) * 1.1;
  float rocky = clamp(0.2 + (eb - u_tree_line) / max(u_snow_line - u_tree_line, 1e-3) - 0.6 * concave + (slope_deg - 22.0) / 25.0, 0.0, 1.0);
  float alpine = ramp(u_tree_line, u_blend, eb);
  colour = mix(colour, mix(turf, rock, rocky), alpine);
  roughness = mix(roughness, mix(0.5, 1.0, rocky), alpine);

  // Scree: grey-brown debris below cliffs, paler than the rock it fell from.
  vec3 debris = mix(rock, vec3(luma(rock)), 0.35) * 1.2;
  float scree_weight = clamp(scree * 1.3 - 0.4 * wet, 0.0, 1.0) * step(0.0, above_sea);
  colour = mix(colour, debris, scree_weight);
  roughness = mix(roughness, 0.8, scree_weight);

  // Steep faces and exposed crests: bare rock (the ragged edge from the patch noise).
  float steep = ramp(u_cliff_slope + 16.0 * min(concave, 0.0), u_cliff_blend, slope_deg + (patches - 0.5) * 12.0) * step(0.0, above_sea);
  colour = mix(colour, rock, steep);
  roughness = mix(roughness, 1.0, steep);

  // Sand at beach height only: within u_beach_top of the sea, on gentle shores.
  float beach_m = u_beach_top * u_band_scale;
  float sand = (1.0 - ramp(beach_m, max(1.0, 0.6 * beach_m), above_sea + (patches - 0.5) * 0.8 * beach_m)) *
               (1.0 - ramp(22.0, 10.0, slope_deg)) * (1.0 - 0.8 * wet);
  colour = mix(colour, u_beach, sand);
  roughness = mix(roughness, 0.2, sand);
  // Under the sea, the seabed.
  colour = mix(u_seabed, colour, smoothstep(-1.0, 0.3, above_sea));

  // Wet ground is darker.
  colour *= 1.0 - 0.22 * wet;

  // Snow above the snow line (lower on shady faces and in hollows), not on slopes too steep to hold it.
  float snow = ramp(u_snow_line, u_blend, eb - 0.025 * sunny + 0.015 * concave) *
               (1.0 - ramp(u_snow_max_slope, 8.0, slope_deg + (patches - 0.5) * 10.0));
  colour = mix(colour, u_snow, snow);
  roughness = mix(roughness, 0.25, snow);
  return Ground(colour, roughness);
}

// Detail below the height texture's grid for near views: up to three reads of the tiled detail
// noise, each eight times finer than the last (four octaves each), turned against each other so
// the tile does not show, continuing the terrain's spectrum from two texels down to centimetres.
// An octave group is skipped once its coarsest features are smaller than a few pixels
// (`footprint`: metres per pixel on the ground); the mipmaps fade the finer octaves within it.
// Returns the extra slope (dh/dx, dh/dz) and, in `micro`, a colour noise (0.5 when far).
vec2 detail_slope(vec2 xz, float footprint, float sharp, float roughness, out float micro) {
  const mat2 turns[3] = mat2[3](mat2(1.0, 0.0, 0.0, 1.0), mat2(0.4536, 0.8912, -0.8912, 0.4536), mat2(-0.6669, 0.7451, -0.7451, -0.6669));
  const vec2 shifts[3] = vec2[3](vec2(0.0), vec2(0.37, 0.71), vec2(0.13, 0.59));
  const float texels = 256.0;             // the detail texture's size (terrain_renderer.cpp)
  float tile = 16.0 * u_texel_m;          // coarsest octave: two texels of the height texture
  float slope_scale = 0.16 * roughness;   // typical slope of the coarsest octave
  vec2 slope = vec2(0.0);
  micro = 0.5;
  for (int k = 0; k < 3; ++k) {
    float fade = clamp(tile / 8.0 / footprint / 3.0 - 1.0, 0.0, 1.0);
    if (fade <= 0.0) break;
    mat2 turn = turns[k];
    vec4 t = textureLod(u_detail, turn * xz / tile + shifts[k], log2(max(sharp * texels / tile, 1.0)));
    // Slope per tile width -> per metre, turned back into the world's axes.
    vec2 g = (t.rg * 2.0 - 1.0) * u_detail_gradient_scale * slope_scale / 8.0;
    slope += fade * (transpose(turn) * g);
    micro = mix(micro, t.a, fade);
    tile /= 8.0;
    slope_scale *= 1.366;  // 8^(1 - H) with the detail's H = 0.85: finer octaves are a little steeper
  }
  return slope;
}

vec3 light(vec3 normal, vec2 shade) {
  float sun = u_shadows != 0 ? shade.r : 1.0;
  float open_sky = mix(1.0, shade.g, u_ambient_occlusion);
  float diffuse = max(dot(normal, u_sun_dir), 0.0) * sun;
  // Sky light comes mostly from above: faces turned down get less of it.
  return u_sun_light * diffuse + u_sky_light * open_sky * (0.6 + 0.4 * normal.y);
}

// The cut sides of the terrain block: earth below the ground, sea above it.
vec3 side_colour() {
  vec3 normal = v_uv.x < 1e-5 ? vec3(-1.0, 0.0, 0.0)
              : v_uv.x > 1.0 - 1e-5 ? vec3(1.0, 0.0, 0.0)
              : v_uv.y < 1e-5 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 0.0, 1.0);
  float ground = (height_at(v_uv) - u_sea_level) * u_exaggeration;
  float layers = texture(u_noise, vec2(v_world.y / (0.15 * u_max_above_sea * u_exaggeration), 0.37)).r;
  // Sea seen from the side: lighter near its surface.
  float below_surface = -v_world.y / (0.1 * u_max_above_sea * u_exaggeration);
  vec3 sea = mix(u_water_shallow, u_water_deep, clamp(0.4 + below_surface, 0.0, 1.0));
  vec3 albedo = v_world.y > ground + 0.01 ? sea : u_earth * (0.8 + 0.3 * layers);
  // Sides in shade get some warm light bounced off the ground in front, so they read as earth.
  vec3 lit = albedo * (u_sun_light * (max(dot(normal, u_sun_dir), 0.0) + 0.15) + u_sky_light);
  return lit;
}

// A river or lake over lit ground: the sea's colours by depth, the sky reflected by Fresnel's
// term off a flat surface, fading in over the first 5 cm so banks have no hard line (a brook a
// few decimetres deep still shows).
vec3 with_surface_water(vec3 ground, float depth, vec2 shade) {
  if (depth <= 0.0) return ground;
  vec3 water = mix(u_water_shallow, u_water_deep, 1.0 - exp(-depth / 3.0));
  float sun = u_shadows != 0 ? shade.r : 1.0;
  vec3 lit = water * (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun);
  vec3 to_eye = u_orthographic != 0 ? -u_camera_forward : normalize(u_camera_pos - v_world);
  float fresnel = 0.02 + 0.98 * pow(1.0 - max(to_eye.y, 0.0), 5.0);
  vec3 reflected_dir = reflect(-to_eye, vec3(0.0, 1.0, 0.0));
  vec3 surface = mix(lit, sky_colour(vec3(reflected_dir.x, abs(reflected_dir.y), reflected_dir.z)), fresnel);
  return mix(ground, surface, smoothstep(0.0, 0.05, depth) * 0.9);
}

void main() {
  // Pixel footprint on the ground, before any branch (derivatives need the whole quad).
  // The geometric mean of the two axes: a grazing pixel keeps detail across the view.
  float across = length(dFdx(v_world)), along = length(dFdy(v_world));
  float footprint = max(sqrt(across * along), 1e-4);
  // The detail's mip level follows the shorter axis of a grazing pixel: the longer one would
  // smear the noise into streaks toward the horizon.
  float sharp = max(min(across, along), 1e-4);
  vec3 colour;
  if (v_side > 0.5) {
    colour = side_colour();
  } else {
    // Per-pixel normal from the interpolated height gradient.
    vec4 surface = texture(u_surface, texcoord(u_surface, v_uv));
    float height_m = surface.r;
    vec2 gradient = surface.gb;
    vec3 true_normal = normalize(vec3(-gradient.x, 1.0, -gradient.y));
    float slope_deg = degrees(acos(clamp(true_normal.y, -1.0, 1.0)));
    vec4 shading = texture(u_shading, texcoord(u_shading, v_uv));
    vec4 land = texture(u_ground, texcoord(u_ground, v_uv));
    Ground ground = ground_albedo(height_m, slope_deg, true_normal, shading.ba, land, surface.a);
    float micro;
    vec2 detail = detail_slope(v_world.xz, footprint, sharp, ground.roughness, micro);
    // Colour varies at the detail's scale too, more on rough ground.
    vec3 albedo = ground.albedo * (1.0 + (micro - 0.5) * (0.3 + 0.3 * ground.roughness));
    gradient += detail;
    vec3 drawn_normal = normalize(vec3(-gradient.x * u_exaggeration, 1.0, -gradient.y * u_exaggeration));
    vec2 water = u_has_surface_water != 0 ? texture(u_surface_water, texcoord(u_surface_water, v_uv)).rg : vec2(0.0);
    albedo *= 1.0 - 0.4 * water.g;  // wet ground is darker
    colour = with_surface_water(albedo * light(drawn_normal, shading.rg), water.r, shading.rg);
  }
  o_colour = vec4(to_srgb(apply_fog(colour, v_world)), 1.0);
}
)";

const char* const water_vertex = R"(
layout(location = 0) in vec4 a_vertex;  // x, y: fractions of the terrain; z, w unused
out vec2 v_uv;
out vec3 v_world;
void main() {
  v_uv = a_vertex.xy;
  v_world = vec3(v_uv.x * u_extent.x, 0.0, v_uv.y * u_extent.y);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

const char* const water_fragment = R"(
uniform vec3 u_water_shallow, u_water_deep;  // linear
uniform float u_depth_scale;                 // metres of water that make it 63 % deep-coloured
uniform float u_ripple;                      // strength of the ripples
uniform float u_foam_depth;                  // metres: shallower water foams
uniform int u_shadows;
in vec2 v_uv;
in vec3 v_world;
out vec4 o_colour;
void main() {
  float depth = u_sea_level - height_at(v_uv);
  if (depth <= 0.0) discard;
  float deep = 1.0 - exp(-depth / u_depth_scale);
  vec3 water = mix(u_water_shallow, u_water_deep, deep);

  // A few ripples (seeds/003, Sec. 4.1.5: noise on the water surface), a sky reflection by
  // Schlick's Fresnel term, and the sun's glint.
  // Two scales, turned against each other, so that the noise tile does not show as a grid.
  // The two scales drift in different directions with time, so the ripples move.
  vec2 p = v_uv * u_extent / u_terrain_size;
  vec2 drift = vec2(0.0021, 0.0013) * u_time;
  vec2 ripple = texture(u_noise, p * 23.0 + drift).rg + texture(u_noise, mat2(0.8, 0.6, -0.6, 0.8) * p * 61.0 - drift * 1.7).gr - 1.0;
  vec3 normal = normalize(vec3(ripple.x * 0.05 * u_ripple, 1.0, ripple.y * 0.05 * u_ripple));
  vec3 to_eye = u_orthographic != 0 ? -u_camera_forward : normalize(u_camera_pos - v_world);
  float fresnel = 0.02 + 0.98 * pow(1.0 - max(dot(normal, to_eye), 0.0), 5.0);
  vec3 reflected_dir = reflect(-to_eye, normal);
  vec3 reflected = sky_colour(vec3(reflected_dir.x, abs(reflected_dir.y), reflected_dir.z));
  float sun = u_shadows != 0 ? texture(u_shading, texcoord(u_shading, v_uv)).r : 1.0;
  float glint = pow(max(dot(reflected_dir, u_sun_dir), 0.0), 400.0) * sun;
  vec3 lit = water * (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun);
  vec3 colour = mix(lit, reflected, fresnel) + u_sun_light * glint * 1.5;

  // Foam on the shallows, broken up by the ripples' noise.
  float foam = u_foam_depth > 0.0 ? clamp(1.0 - depth / u_foam_depth, 0.0, 1.0) * smoothstep(0.35, 0.75, texture(u_noise, p * 140.0 + drift * 3.0).r + 0.25) : 0.0;
  colour = mix(colour, (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun) * 0.9, foam);

  // Shallow water lets the seabed show through; the shore has no hard line.
  float alpha = max(mix(0.2, 1.0, smoothstep(0.0, 0.7, deep)), foam);
  o_colour = vec4(to_srgb(apply_fog(colour, v_world)), alpha);
}
)";

}  // namespace sansui::render::shaders
