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
uniform sampler2D u_sky_clear; // the same dome without clouds: the clouds are drawn per pixel over it
uniform sampler2D u_haze;      // one row round the horizon: the haze toward each azimuth (look::horizon_haze)
uniform sampler2D u_clouds;    // the cloud layer (look/sky_dome.hpp): r density, g optical depth; mirrored repeat
uniform int u_has_clouds;
uniform float u_cloud_height;  // drawing units: the cloud layer's height above the sea
uniform float u_cloud_span;    // drawing units that one cloud image spans
uniform vec3 u_cloud_sun;      // linear sunlight on the clouds
uniform float u_cloud_cover;   // 0..1

// The land around the terrain out to the horizon (look/surroundings.hpp): a grid whose spacing
// grows past the terrain's border. Per axis: centre and half extent (m), the border's fraction
// s0 of the half grid, and the growth rate past it.
uniform int u_ring;            // 1: the surroundings are drawn
uniform vec4 u_ring_x, u_ring_z;
uniform sampler2D u_ring_surface;  // the surroundings' heights and slopes, as u_surface

// Texture coordinate of a point given as fractions (0..1) of the terrain: sample i of n sits
// at the centre of texel i.
vec2 texcoord(sampler2D tex, vec2 uv) {
  vec2 size = vec2(textureSize(tex, 0));
  return (uv * (size - 1.0) + 0.5) / size;
}
float height_at(vec2 uv) { return textureLod(u_surface, texcoord(u_surface, uv), 0.0).r; }

// Metres of a grid fraction t (0..1) of the surroundings along one axis, and back.
float ring_position(float t, vec4 axis) {
  float s = 2.0 * t - 1.0, a = abs(s);
  float d = a <= axis.z ? a / axis.z : exp(axis.w * (a - axis.z) / axis.z);
  return axis.x + sign(s) * axis.y * d;
}
float ring_fraction(float position, vec4 axis) {
  float d = (position - axis.x) / axis.y, a = abs(d);
  float s = a <= 1.0 ? a * axis.z : axis.z * (1.0 + log(a) / axis.w);
  return 0.5 + 0.5 * sign(d) * s;
}

// True height of the ground under a point (x, z metres) of the sea: the terrain's, the
// surroundings' (`ring` 1: drawn in the world), or far out a deep sea floor.
float sea_floor_at(vec2 xz, int ring) {
  vec2 uv = xz / u_extent;
  if (all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)))) return height_at(uv);
  if (ring == 0) return -1e9;
  vec2 t = vec2(ring_fraction(xz.x, u_ring_x), ring_fraction(xz.y, u_ring_z));
  if (any(lessThan(t, vec2(0.0))) || any(greaterThan(t, vec2(1.0)))) return -1e9;
  return textureLod(u_ring_surface, texcoord(u_ring_surface, t), 0.0).r;
}

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
// The share of the haze the sea keeps far out (apply_fog_toward).
const float sea_horizon_shade = 0.86;
// The haze toward an azimuth: what the fog turns the far land and sea to, and the sky below 2 degrees.
vec3 haze_at(float azimuth) { return texture(u_haze, vec2(fract(azimuth / 6.28318530718), 0.5)).rgb; }
float elevation_of(vec3 dir) { return degrees(asin(clamp(dir.y, -1.0, 1.0))); }

// The sky in a direction (for reflections on the water and the haze).
vec3 sky_colour(vec3 dir) { return sky_texel(azimuth_of(dir), elevation_of(dir)).rgb; }

// The clouds are one field on a flat layer, sampled per pixel where a ray meets it: the sky, the
// sea's reflections and the shadows on the land all read the same field, so they agree, and no
// baked texture's texels show as steps near the horizon. Its mip levels filter the far layer
// (toward the horizon it averages into a haze band instead of aliasing).
vec2 cloud_uv(vec2 xz) { return (xz - 0.5 * u_extent) / u_cloud_span + 0.5; }

// Where a ray from `origin` along `dir` (dir.y > 0) meets the layer; from above the layer it is
// seen as from half its height below. (The sky of an overview, drawn as seen from below anyway,
// looks from sea level: the camera high above the land would see a few clouds magnified.)
float cloud_distance_up(vec3 origin) { return max(u_cloud_height - origin.y, 0.5 * u_cloud_height); }
vec2 cloud_point(vec3 origin, vec3 dir) {
  float above = cloud_distance_up(origin);
  return origin.xz + dir.xz * (above / max(dir.y, 0.005));
}

// The clouds (density and optical depth from the field `field`) seen along `dir` in front of the
// clear sky `sky`: rgb, and the cover in a.
// Sunlight through a cloud falls off with its optical depth (Beer-Lambert), so thick clouds are
// dark underneath; thin edges toward the sun glow (forward scattering: the silver lining).
vec4 cloud_over(vec3 sky, vec2 field, vec3 dir) {
  if (u_has_clouds == 0 || dir.y <= 0.0) return vec4(sky, 0.0);
  // Toward the horizon the layer is seen edge-on and many clouds fall in a pixel: they blend
  // into their average (the cover), a band of haze, instead of streaking.
  float far = 1.0 - smoothstep(0.01, 0.12, dir.y);
  // Seen edge-on, gaps between the clouds hide behind them: the band is denser than the cover.
  field = mix(field, vec2(min(1.3 * u_cloud_cover, 1.0), 0.6 * u_cloud_cover), far);
  // Under a nearly closed cover the gaps are veiled by thinner cloud, so an overcast sky does
  // not open wide blue holes overhead (a gap of a twentieth of the layer fills much of the sky).
  float density = max(clamp(field.r, 0.0, 1.0), 0.8 * smoothstep(0.6, 1.0, u_cloud_cover));
  float depth = min(field.g * (0.7 + 0.6 * density), 1.0);
  float toward_sun = max(dot(dir, u_sun_dir), 0.0);
  float sky_luminance = dot(sky, vec3(0.2126, 0.7152, 0.0722));
  vec3 ambient = (vec3(0.8 * sky_luminance + 0.03) + sky * 0.15) * (1.0 - 0.3 * depth);
  float through = 0.3 + 0.7 * exp(-2.0 * depth);  // what the many scatterings still bring through
  float silver = pow(toward_sun, 16.0) * (1.0 - density) * 2.0;
  vec3 lit = u_cloud_sun * ((0.4 + 0.5 * toward_sun * toward_sun) * through + silver);
  vec3 cloud = (ambient + lit) * (1.0 - 0.3 * u_cloud_cover);
  // Far clouds thin out into the haze over the horizon.
  float alpha = density * mix(0.75, 1.0, smoothstep(0.0, 0.1, dir.y));
  return vec4(mix(sky, cloud, alpha), alpha);
}

// The clear sky and the clouds seen along `dir` from `origin` (for the sea's reflections), the
// clouds blurred over `spread` radians, the spread of the reflected rays over a pixel: read at a
// fixed level of detail, since the ripples' normals would make the derivatives noisy.
vec3 sky_with_clouds(vec3 dir, vec3 origin, float spread) {
  vec3 sky = textureLod(u_sky_clear, vec2(fract(azimuth_of(dir) / 6.28318530718), clamp((90.0 - elevation_of(dir)) / 100.0, 0.0, 1.0)), 0.0).rgb;
  if (u_has_clouds == 0 || dir.y <= 0.0) return sky;
  float above = cloud_distance_up(origin);
  float blur = spread * above / max(dir.y * dir.y, 0.005) / u_cloud_span * float(textureSize(u_clouds, 0).x);
  return cloud_over(sky, textureLod(u_clouds, cloud_uv(cloud_point(origin, dir)), log2(max(blur, 1.0))).rg, dir).rgb;
}

// How much of the sun reaches a point (drawing coordinates) past the clouds: the field where the
// ray toward the sun crosses the layer (its soft edges are the penumbra). An overcast
// sky's diffuse light is already in the sun's strength, so its shadows fade out.
float cloud_shadow(vec3 world) {
  if (u_has_clouds == 0 || u_sun_dir.y <= 0.01) return 1.0;
  vec2 xz = world.xz + u_sun_dir.xz / u_sun_dir.y * max(u_cloud_height - world.y, 0.0);
  // One bilinear read of the finest level: a cloud sample is larger than the land's pixels.
  vec2 field = textureLod(u_clouds, cloud_uv(xz), 0.0).rg;
  float strength = 0.8 * (1.0 - smoothstep(0.8, 1.0, u_cloud_cover));
  return 1.0 - strength * clamp(field.r * (0.6 + 0.6 * field.g), 0.0, 1.0);
}

// Aerial perspective: the farther behind the terrain's nearest point, the more the colour turns
// to the sky's near the horizon (counted from the nearest point, so that the near edge stays
// clear however far the camera stands).
// `shade`: the haze's share the far surface keeps (the sea's is darker than the sky above it).
vec3 apply_fog_toward(vec3 colour, vec3 world, float shade) {
  if (u_orthographic != 0 || u_fog_density <= 0.0) return colour;
  vec3 offset = world - u_camera_pos;
  float distance = length(offset);
  float fog = 1.0 - exp(-u_fog_density * max(distance - u_fog_start, 0.0) / u_terrain_size);
  // The haze is the sky just above the horizon in that direction.
  vec2 level = normalize(offset.xz + vec2(1e-6, 0.0));
  return mix(colour, shade * haze_at(atan(level.x, -level.y)), fog);
}
vec3 apply_fog(vec3 colour, vec3 world) { return apply_fog_toward(colour, world, 1.0); }

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

// The backdrop: what the sky shows toward a point of the screen, shared by the sky and the stars
// drawn over it, so that a star is hidden exactly by the cloud the sky shows there.
const char* const backdrop = R"(
uniform mat4 u_inverse_view_proj;
uniform int u_true_sky;  // 1: a walker looks around, the sky is where it is

// The direction the backdrop shows at `ndc` (normalised device coordinates), its elevation in
// degrees and azimuth in radians. A bird's-eye camera looks down, and its picture's top may still
// be below the true horizon: the backdrop then spreads the sky from the horizon (bottom) to 60
// degrees up (top), in the true azimuth; a camera that looks up sees the true directions.
vec3 backdrop_direction(vec2 ndc, out float elevation, out float azimuth) {
  vec4 near = u_inverse_view_proj * vec4(ndc, -1.0, 1.0);
  vec4 far = u_inverse_view_proj * vec4(ndc, 1.0, 1.0);
  vec3 dir = normalize(far.xyz / far.w - near.xyz / near.w);
  float up = clamp(0.5 + 0.5 * ndc.y, 0.0, 1.0);
  elevation = u_true_sky != 0 ? elevation_of(dir) : max(elevation_of(dir), 60.0 * pow(up, 1.2));
  azimuth = azimuth_of(dir);
  return vec3(cos(radians(elevation)) * sin(azimuth), sin(radians(elevation)), -cos(radians(elevation)) * cos(azimuth));
}

// The sky the backdrop shows along `seen` (backdrop_direction()): linear rgb, the clouds' cover
// in a. Below 2 degrees in the world: land or sea too far to draw, lost in the haze (the colour
// apply_fog() turns the farthest ground to).
vec4 backdrop_sky(vec3 seen, float elevation, float azimuth) {
  if (u_ring != 0 && elevation < 2.0) return vec4(haze_at(azimuth), 0.0);
  vec3 clear = texture(u_sky_clear, vec2(fract(azimuth / 6.28318530718), clamp((90.0 - elevation) / 100.0, 0.0, 1.0))).rgb;
  vec4 sky = vec4(clear, 0.0);
  if (u_has_clouds != 0 && seen.y > 0.0) {
    // The cloud image is fine enough (look/sky_dome.hpp) that no detail noise is needed, whose
    // tile would show as a regular pattern of puffs.
    vec3 eye = u_true_sky != 0 ? u_camera_pos : vec3(u_camera_pos.x, 0.0, u_camera_pos.z);
    sky = cloud_over(clear, texture(u_clouds, cloud_uv(cloud_point(eye, seen))).rg, seen);
  }
  // In the world the sky comes out of the haze the far land and sea fade into: no line where
  // they meet (the haze is the sky at 2 degrees, averaged round the horizon).
  if (u_ring != 0) sky.rgb = mix(haze_at(azimuth), sky.rgb, smoothstep(2.0, 6.0, elevation));
  return sky;
}
)";

const char* const sky_fragment = R"(
uniform vec3 u_background;     // linear, for the top view
uniform sampler2D u_sun_disc;  // along x the distance from the disc's centre (act, Table 3): rgb colour, a opacity
uniform float u_sun_radius;    // the disc's angular radius, radians
in vec2 v_ndc;
out vec4 o_colour;
void main() {
  if (u_orthographic != 0) {
    o_colour = vec4(to_srgb(u_background), 1.0);
    return;
  }
  float elevation, azimuth;
  vec3 seen = backdrop_direction(v_ndc, elevation, azimuth);
  float act = acos(clamp(dot(seen, u_sun_dir), -1.0, 1.0)) / u_sun_radius;
  // The sun sets behind the land and sea beyond the horizon.
  if (u_ring != 0 && elevation < 0.0) act = 2.0;
  vec4 sky = backdrop_sky(seen, elevation, azimuth);
  vec3 colour = sky.rgb;
  if (act < 1.0) {
    vec4 disc = texture(u_sun_disc, vec2(act, 0.5));
    colour = mix(colour, disc.rgb, disc.a * (1.0 - sky.a));
  }
  o_colour = vec4(to_srgb(colour), 1.0);
}
)";

// The stars (look/sky_dome.hpp: Star), one point of a pixel each, added over the sky where its
// clouds let them through.
const char* const star_vertex = R"(
layout(location = 0) in vec4 a_star;  // direction (drawing coordinates), linear brightness
flat out vec2 v_ndc;
flat out float v_brightness;
void main() {
  v_brightness = a_star.w;
  vec4 p;
  if (u_true_sky != 0) {
    p = u_view_proj * vec4(a_star.xyz, 0.0);  // a direction: a point at infinity
  } else {
    // Where the bird's-eye backdrop shows the star's elevation (backdrop_direction()), in its azimuth.
    vec4 h = u_view_proj * vec4(normalize(vec3(a_star.x, 0.0, a_star.z)), 0.0);
    float up = pow(clamp(elevation_of(a_star.xyz) / 60.0, 0.0, 2.0), 1.0 / 1.2);
    p = vec4(h.x, (2.0 * up - 1.0) * h.w, 0.0, h.w);
  }
  v_ndc = p.xy / p.w;
  gl_Position = p.xyww;  // on the far plane, behind everything drawn; clipped behind the camera
}
)";

const char* const star_fragment = R"(
flat in vec2 v_ndc;
flat in float v_brightness;
out vec4 o_colour;
void main() {
  float elevation, azimuth;
  vec3 seen = backdrop_direction(v_ndc, elevation, azimuth);
  if (u_orthographic != 0 || (u_ring != 0 && elevation < 2.0)) discard;
  vec4 sky = backdrop_sky(seen, elevation, azimuth);
  // A faint blue-white; added over the sky already drawn (sRGB): the difference its light makes.
  // The dome's texel-sized stars spread their light over several pixels; a point gathers more
  // of it into one, so that the faint ones still show (mean magnitude 4.5: about 0.8 in sRGB).
  const float point_gain = 8.0;
  vec3 star = point_gain * v_brightness * (1.0 - sky.a) * vec3(0.95, 0.97, 1.0);
  o_colour = vec4(to_srgb(sky.rgb + star) - to_srgb(sky.rgb), 0.0);
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
  // The surroundings' grid is uneven: its fractions map to metres through the axes.
  v_world = u_ring != 0 ? vec3(ring_position(uv.x, u_ring_x), y, ring_position(uv.y, u_ring_z))
                        : vec3(uv.x * u_extent.x, y, uv.y * u_extent.y);
  gl_Position = u_view_proj * vec4(v_world, 1.0);
}
)";

const char* const terrain_fragment = R"(
uniform sampler2D u_cliff_albedo;  // sRGB texture: rock colour per sample, if present
uniform int u_has_cliff_albedo;
uniform float u_max_above_sea;     // metres: the highest sample's height above sea level
uniform float u_band_scale;        // metres: the same, at least look/render_params.hpp: min_band_relief_m
uniform float u_beach_top, u_tree_line, u_snow_line, u_blend, u_border_noise;  // fractions of u_band_scale
uniform float u_cliff_slope, u_cliff_blend, u_snow_max_slope, u_cover_slope;   // degrees
uniform float u_ambient_occlusion;  // 0..1
uniform int u_shadows;
uniform vec3 u_seabed, u_beach, u_forest_low, u_forest_high, u_cliff, u_snow, u_earth;  // linear
uniform vec3 u_water_shallow, u_water_deep;                                            // linear
uniform sampler2D u_surface_water;  // rivers and lakes: r metres of water on the ground, g wetness 0..1
uniform int u_has_surface_water;
uniform int u_block;                // 1: the terrain is a block, its cut sides earth-coloured
uniform sampler2D u_ground;         // landforms (look/ground_maps.hpp): r wetness, g curvature ~40 m, b scree, a curvature ~250 m
uniform sampler2D u_detail;         // near-view detail, tiled: rg slope, b height, a colour noise
uniform float u_detail_gradient_scale;  // the detail texture's slope per tile width where rg is 1
uniform float u_texel_m;            // metres between the height texture's samples
uniform vec2 u_sunny_dir;           // horizontal unit vector (x east, z south) toward the sunny side (the equator)
uniform int u_sea_over;             // 1: the world's sea (water_fragment) is drawn over the ground afterwards
uniform vec4 u_sea_rect;            // its west, north, east and south edges, metres
uniform float u_sea_depth_scale;    // water_fragment's u_depth_scale
in vec2 v_uv;
in vec3 v_world;
in float v_side;
out vec4 o_colour;

// The surroundings near the terrain show its own surface mirrored across the border (as their
// heights are, look/surroundings.hpp), at full detail, fading out over u_mirror_reach metres.
uniform sampler2D u_ring_shading;  // the surroundings' shading texels, as u_shading
uniform float u_mirror_reach;
vec2 mirrored_uv(vec2 xz) {
  vec2 t = mod(abs(xz), 2.0 * u_extent);
  return min(t, 2.0 * u_extent - t) / u_extent;
}
// The sign the mirror gives a slope along each axis.
vec2 mirror_sign(vec2 xz) {
  vec2 t = mod(abs(xz), 2.0 * u_extent);
  return mix(vec2(1.0), vec2(-1.0), step(u_extent, t)) * mix(vec2(1.0), vec2(-1.0), lessThan(xz, vec2(0.0)));
}
float mirror_keep(vec2 xz) {
  float t = min(length(xz - clamp(xz, vec2(0.0), u_extent)) / max(u_mirror_reach, 1.0), 1.0);
  return 1.0 - t * t * (3.0 - 2.0 * t);
}
// Height (m), slopes east and south, and curvature at this fragment (see u_surface).
vec4 ground_surface() {
  if (u_ring == 0) return texture(u_surface, texcoord(u_surface, v_uv));
  vec4 own = texture(u_ring_surface, texcoord(u_ring_surface, v_uv));
  float keep = mirror_keep(v_world.xz);
  if (keep <= 0.0) return own;
  vec4 mirrored = texture(u_surface, texcoord(u_surface, mirrored_uv(v_world.xz)));
  mirrored.gb *= mirror_sign(v_world.xz);
  return mix(own, mirrored, keep);
}
// The landform maps at this fragment (see u_ground); the surroundings past the mirror have
// none of their own: middling wetness, flat, no scree.
vec4 ground_landforms() {
  if (u_ring == 0) return texture(u_ground, texcoord(u_ground, v_uv));
  float keep = mirror_keep(v_world.xz);
  vec4 plain = vec4(0.3, 0.5, 0.0, 0.5);
  if (keep <= 0.0) return plain;
  return mix(plain, texture(u_ground, texcoord(u_ground, mirrored_uv(v_world.xz))), keep);
}
// Sun visibility, open sky and the band noises at this fragment (see u_shading).
vec4 ground_shading() {
  if (u_ring == 0) return texture(u_shading, texcoord(u_shading, v_uv));
  vec4 own = texture(u_ring_shading, texcoord(u_ring_shading, v_uv));
  float keep = mirror_keep(v_world.xz);
  if (keep <= 0.0) return own;
  return mix(own, texture(u_shading, texcoord(u_shading, mirrored_uv(v_world.xz))), keep);
}
// Where the rock texture is read: the terrain's own point, or its mirror image around it.
vec2 rock_uv() { return u_ring == 0 ? v_uv : mirrored_uv(v_world.xz); }

// 0 below edge - width/2, 1 above edge + width/2, linear between: the paper's linear blend.
float ramp(float edge, float width, float x) { return clamp((x - edge) / max(width, 1e-4) + 0.5, 0.0, 1.0); }
float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec3 rock_colour(float height_m, float patches) {
  if (u_has_cliff_albedo != 0) return texture(u_cliff_albedo, texcoord(u_cliff_albedo, rock_uv())).rgb;
  // Faint horizontal strata and blotches, so bare rock is not one flat colour.
  float strata = noise1(height_m / (0.012 * u_max_above_sea));
  return u_cliff * (0.75 + 0.3 * strata + 0.3 * (patches - 0.5));
}

// What the ground is made of at a point, and how rough it is (for the detail normals).
struct Ground {
  vec3 albedo;
  float roughness;  // 0 smooth (sand, snow) .. 1 bare rock
};

// The range of true heights (m) one pixel spans, set at the top of main().
float height_footprint = 0.0;

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

  // Bare soil on slopes too steep for the climate's plant cover (not where water gathers).
  vec3 soil = mix(u_earth, u_cliff, 0.45) * 0.8;
  float soil_weight = ramp(u_cover_slope + 12.0 * min(concave, 0.0), 8.0, slope_deg + (patches - 0.5) * 14.0) *
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
  float rock_slope = max(u_cliff_slope, u_cover_slope + 4.0);
  float steep = ramp(rock_slope + 16.0 * min(concave, 0.0), u_cliff_blend, slope_deg + (patches - 0.5) * 12.0) * step(0.0, above_sea);
  colour = mix(colour, rock, steep);
  roughness = mix(roughness, 1.0, steep);

  // Sand at beach height only: within u_beach_top of the sea, on gentle shores. Seen from afar
  // the band is thinner than a pixel, and would break into single bright pixels along the
  // shore: it fades with the share of the pixel's height range it covers.
  float beach_m = u_beach_top * u_band_scale;
  float sand = (1.0 - ramp(beach_m, max(1.0, 0.6 * beach_m), above_sea + (patches - 0.5) * 0.8 * beach_m)) *
               (1.0 - ramp(22.0, 10.0, slope_deg)) * (1.0 - 0.8 * wet) * clamp(beach_m / max(height_footprint, 1e-3), 0.0, 1.0);
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
  float sun = (u_shadows != 0 ? shade.r : 1.0) * cloud_shadow(v_world);  // sky helper: clouds' shadows
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

// A river or lake over lit ground (`depth`: signed, below zero on the banks, see
// terrain_renderer.cpp: signed_depth): fresh water, darker and less turquoise than the sea's
// shallows, over a bed that shows through the shallows and fades with depth (Beer-Lambert over
// about 1.5 m); the sky reflected by Fresnel's term off a flat surface. The shore is where the
// signed depth crosses zero, blended over a pixel (`depth_change`: the depth's change across it)
// so it is neither stair-stepped nor jagged.
vec3 with_surface_water(vec3 ground, float depth, float depth_change, vec2 shade) {
  float edge = max(depth_change, 0.02);
  if (depth <= -edge) return ground;
  float sun = u_shadows != 0 ? shade.r : 1.0;
  vec3 body = mix(u_water_deep, u_water_shallow, 0.25) * 0.6;
  vec3 lit = body * (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun);
  vec3 below = mix(lit, ground * vec3(0.7, 0.8, 0.8), exp(-max(depth, 0.0) / 1.5));
  vec3 to_eye = u_orthographic != 0 ? -u_camera_forward : normalize(u_camera_pos - v_world);
  float fresnel = 0.02 + 0.98 * pow(1.0 - max(to_eye.y, 0.0), 5.0);
  vec3 reflected_dir = reflect(-to_eye, vec3(0.0, 1.0, 0.0));
  vec3 surface = mix(below, sky_colour(vec3(reflected_dir.x, abs(reflected_dir.y), reflected_dir.z)), fresnel);
  return mix(ground, surface, smoothstep(-edge, edge, depth));
}

// Whether the sea drawn over this pixel afterwards hides the ground whole: water_fragment at the
// point where the ray through the pixel meets the sea gives alpha 1 (deep water, see there), with
// margins for rounding and for the pixel's samples. The ground's colour would be lost, so it is
// not worked out: in a world view the sea can fill half the picture.
bool under_opaque_sea() {
  if (u_sea_over == 0) return false;
  float above = u_camera_pos.y - v_world.y;
  vec2 xz = u_camera_pos.xz + (v_world.xz - u_camera_pos.xz) * (u_camera_pos.y / max(above, 1e-6));
  float depth = u_sea_level - sea_floor_at(xz, 1);
  float change = fwidth(depth);  // in uniform control flow: every fragment reads its floor
  bool inside = all(greaterThan(xz, u_sea_rect.xy)) && all(lessThan(xz, u_sea_rect.zw));
  // alpha = 1 needs deep >= 0.7 (depth >= 1.204 depth scales), depth >= 0.3 m, and in the
  // surroundings depth >= 2 fwidth(depth). The ground itself lies as deep, so that the sea's
  // depth test passes in every sample (the block's sides reach up to the sea's surface: a
  // sample there could tie with it and stay unshaded).
  float deep = max(1.3 * u_sea_depth_scale, 0.5);
  return v_side < 0.5 && -v_world.y > deep * u_exaggeration && u_camera_pos.y > 0.0 && inside && u_orthographic == 0 &&
         depth - 2.0 * change > deep && depth > 4.0 * change;
}

void main() {
  if (under_opaque_sea()) {
    o_colour = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  // Pixel footprint on the ground, before any branch (derivatives need the whole quad).
  // The geometric mean of the two axes: a grazing pixel keeps detail across the view.
  float across = length(dFdx(v_world)), along = length(dFdy(v_world));
  float footprint = max(sqrt(across * along), 1e-4);
  // The detail's mip level follows the shorter axis of a grazing pixel: the longer one would
  // smear the noise into streaks toward the horizon.
  float sharp = max(min(across, along), 1e-4);
  height_footprint = fwidth(v_world.y) / max(u_exaggeration, 1e-3);
  // Rivers and lakes (signed depth, wetness), and how much the depth changes across the pixel.
  vec2 water = u_has_surface_water != 0 ? texture(u_surface_water, texcoord(u_surface_water, v_uv)).rg : vec2(-10.0, 0.0);
  float water_edge = fwidth(water.r);
  vec3 colour;
  // In the world the sides only fill the seam with the coarser surroundings: ground-coloured.
  if (v_side > 0.5 && u_block != 0) {
    colour = side_colour();
  } else {
    // Per-pixel normal from the interpolated height gradient.
    vec4 surface = ground_surface();
    float height_m = surface.r;
    vec2 gradient = surface.gb;
    vec3 true_normal = normalize(vec3(-gradient.x, 1.0, -gradient.y));
    float slope_deg = degrees(acos(clamp(true_normal.y, -1.0, 1.0)));
    vec4 shading = ground_shading();
    vec4 land = ground_landforms();
    // The heights a pixel spans: the mesh's change across it, or the surface's slope times
    // the ground it covers, whichever is more.
    height_footprint = max(height_footprint, length(gradient) * footprint);
    Ground ground = ground_albedo(height_m, slope_deg, true_normal, shading.ba, land, surface.a);
    float micro;
    vec2 detail = detail_slope(v_world.xz, footprint, sharp, ground.roughness, micro);
    // Colour varies at the detail's scale too, more on rough ground.
    vec3 albedo = ground.albedo * (1.0 + (micro - 0.5) * (0.3 + 0.3 * ground.roughness));
    gradient += detail;
    vec3 drawn_normal = normalize(vec3(-gradient.x * u_exaggeration, 1.0, -gradient.y * u_exaggeration));
    albedo *= 1.0 - 0.4 * water.g;  // wet ground is darker
    colour = with_surface_water(albedo * light(drawn_normal, shading.rg), water.r, water_edge, shading.rg);
  }
  o_colour = vec4(to_srgb(apply_fog(colour, v_world)), 1.0);
}
)";

const char* const water_vertex = R"(
layout(location = 0) in vec4 a_vertex;  // x, y: fractions of the sea's rectangle; z, w unused
uniform vec4 u_sea_rect;                // the sea's west, north, east and south edges, metres
out vec2 v_uv;
out vec3 v_world;
void main() {
  v_world = vec3(mix(u_sea_rect.x, u_sea_rect.z, a_vertex.x), 0.0, mix(u_sea_rect.y, u_sea_rect.w, a_vertex.y));
  v_uv = v_world.xz / u_extent;
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

// Value noise over the plane from an arithmetic hash (Hoskins' "hash without sine"): no texture
// read and no period, for the sea's wind patches.
float hash12(vec2 p) {
  vec3 p3 = fract(vec3(p.xyx) * 0.1031);
  p3 += dot(p3, p3.yzx + 33.33);
  return fract((p3.x + p3.y) * p3.z);
}
float noise2(vec2 x) {
  vec2 i = floor(x), f = fract(x);
  vec2 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(hash12(i), hash12(i + vec2(1.0, 0.0)), u.x), mix(hash12(i + vec2(0.0, 1.0)), hash12(i + vec2(1.0)), u.x), u.y);
}

// Ripples (seeds/003, Sec. 4.1.5: noise on the water surface): the slope of the surface from
// three reads of the noise tile at scales 1 : 2.7 : 7.2 of each other (no common period short of
// hundreds of tiles), each turned by its own angle and drifting its own way. `p` is in
// kilometres: the largest tile spans 400 m, whatever the terrain's size. An octave whose tile
// spans fewer than about fifty pixels fades out before its period could show as a grid or a
// moire; what it would have added counts as roughness below the pixel (`unresolved`, 0..1),
// which blurs the reflection and widens the glint instead. Wind patches (a smooth noise without
// period) make some water rougher than other.
vec2 ripple_slope(vec2 p, out float unresolved) {
  vec2 drift = vec2(0.0021, 0.0013) * u_time;  // tiles a second
  float footprint = length(fwidth(p));
  float wind = 0.55 + 0.6 * noise2(p * 0.45) + 0.35 * noise2(mat2(0.6, 0.8, -0.8, 0.6) * p * 1.3);
  vec2 slope = vec2(0.0);
  unresolved = 0.0;
  const float scales[3] = float[3](2.5, 6.73, 18.1);
  const vec2 turns[3] = vec2[3](vec2(0.9563, 0.2924), vec2(0.5446, -0.8387), vec2(-0.3256, 0.9455));
  const float weights[3] = float[3](0.45, 0.33, 0.22);
  for (int k = 0; k < 3; ++k) {
    float fade = 1.0 - smoothstep(0.02, 0.08, footprint * scales[k]);
    unresolved += weights[k] * (1.0 - fade);
    if (fade <= 0.0) continue;  // no read for an octave below the pixel
    vec2 t = turns[k];
    vec2 q = mat2(t.x, t.y, -t.y, t.x) * p * scales[k] + drift * (1.0 + 0.7 * float(k));
    slope += (texture(u_noise, q).rg - 0.5) * weights[k] * fade;
  }
  unresolved *= wind;
  return slope * 2.2 * wind;
}

void main() {
  float depth = u_sea_level - sea_floor_at(v_world.xz, u_ring);
  bool on_terrain = all(greaterThanEqual(v_uv, vec2(0.0))) && all(lessThanEqual(v_uv, vec2(1.0)));
  if (depth <= 0.0) discard;
  float deep = 1.0 - exp(-depth / u_depth_scale);
  vec3 water = mix(u_water_shallow, u_water_deep, deep);

  // A sky reflection by Schlick's Fresnel term, and the sun's glint. The ripples calm down in
  // the last few decimetres of water, so that the shore does not sparkle in single pixels.
  float unresolved;
  vec2 ripples = ripple_slope(v_world.xz / 1000.0, unresolved);
  vec2 slope = ripples * 0.05 * u_ripple * smoothstep(0.0, 0.5, depth);
  vec3 normal = normalize(vec3(slope.x, 1.0, slope.y));
  vec3 to_eye = u_orthographic != 0 ? -u_camera_forward : normalize(u_camera_pos - v_world);
  // A ripple turned away from a grazing eye would reflect the sea itself: keep the reflected
  // ray above the horizon, and the Fresnel term off the mean surface at grazing angles.
  vec3 reflected_dir = reflect(-to_eye, normal);
  reflected_dir.y = max(abs(reflected_dir.y), 0.01);
  reflected_dir = normalize(reflected_dir);
  float facing = clamp(dot(normal, to_eye), 0.0, 1.0);
  float fresnel = 0.02 + 0.98 * pow(1.0 - mix(max(to_eye.y, 0.0), facing, smoothstep(0.02, 0.2, to_eye.y)), 5.0);
  // The reflected rays of a pixel spread with the ripples' slopes and the pixel's own footprint.
  float spread = (0.1 + 0.25 * unresolved) * u_ripple + 2.0 * length(fwidth(to_eye));
  vec3 reflected = sky_with_clouds(reflected_dir, v_world, spread);
  float sun = (u_shadows != 0 && on_terrain ? texture(u_shading, texcoord(u_shading, v_uv)).r : 1.0) * cloud_shadow(v_world);
  // The glint is broad enough to cover more than a pixel, and bounded: no single-pixel sparks;
  // rough water below the pixel spreads it (Phong's lobe, its peak kept in proportion).
  float shininess = mix(300.0, 40.0, clamp(unresolved * u_ripple, 0.0, 1.0));
  float glint = min(pow(max(dot(reflected_dir, u_sun_dir), 0.0), shininess) * shininess / 300.0, 1.0) * sun;
  vec3 lit = water * (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun);
  vec3 colour = mix(lit, reflected, fresnel) + u_sun_light * glint * 1.2;

  // Foam on the shallows, in patches of the ripples' own noise (no extra read), fading in
  // over the foam depth instead of starting at a line.
  float shallow = u_foam_depth > 0.0 ? clamp(1.0 - depth / u_foam_depth, 0.0, 1.0) : 0.0;
  float foam = shallow * shallow * smoothstep(0.35, 0.75, shallow + 0.4 * ripples.x);
  // Seen from afar the foam band is thinner than a pixel and would break into single white
  // pixels along the shore: it is weighed by the share of the pixel it covers.
  foam *= clamp(u_foam_depth / max(2.0 * fwidth(depth), 1e-6), 0.0, 1.0);
  // The surroundings' coarse grid and their mirrored surface disagree by more than the foam's
  // depth: foam there would be white specks in pits of the land, so their shores have none.
  if (!on_terrain) foam = 0.0;
  colour = mix(colour, (u_sky_light + u_sun_light * max(u_sun_dir.y, 0.0) * sun) * 0.9, foam);

  // Shallow water lets the seabed show through; the shore has no hard line.
  float alpha = clamp(max(mix(0.2, 1.0, smoothstep(0.0, 0.7, deep)), foam) * smoothstep(0.0, 0.3, depth), 0.0, 1.0);
  // Pits of the surroundings' coarse land a pixel wide that dip below the sea would show as
  // single bright pixels of reflected sky: water there fades in over a pixel's change in depth.
  if (!on_terrain) alpha *= clamp(depth / max(2.0 * fwidth(depth), 1e-3), 0.0, 1.0);
  // Far out the sea reflects the sky near the horizon, but the waves' faces turned to the eye show
  // the water itself: the sea's haze is a shade darker than the sky's, so a horizon line shows.
  o_colour = vec4(to_srgb(apply_fog_toward(colour, v_world, sea_horizon_shade)), alpha);
}
)";

}  // namespace sansui::render::shaders
