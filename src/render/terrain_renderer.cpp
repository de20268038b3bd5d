#include "render/terrain_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>

#include "core/error.hpp"
#include "look/camera.hpp"
#include "look/colour_space.hpp"
#include "look/downsample.hpp"
#include "look/ground_maps.hpp"
#include "look/horizon_shading.hpp"
#include "look/sky_model.hpp"
#include "look/surface_maps.hpp"
#include "look/surroundings.hpp"
#include "look/terrain_mesh.hpp"
#include "render/impostor_atlas.hpp"
#include "render/shaders.hpp"

namespace sansui::render {

// The look's helpers, by their short names.
using look::degrees;
using look::direction_of;
using look::downsample;
using look::linear;
using look::strip_restart;
namespace {

// Shadows and ambient occlusion are traced on at most this many samples per side (about
// 80 ms for 1025^2 on two cores), and sampled with linear filtering above that.
constexpr int max_shading_samples = 1025;

// Light strengths (linear): full sun on a face turned to it plus sky light adds up to about
// 1.5, so a sunlit slope shows its palette colour a little brighter and a shadowed one about a
// third as bright, as in a clear-day photograph.
constexpr float sun_strength = 1.2f;
constexpr float sky_strength = 0.9f;
// Starlight and airglow: a moonless night is not pitch black to dark-adapted eyes.
constexpr glm::vec3 night_light{0.012f, 0.016f, 0.03f};
// A walker's share of the plants' triangle budgets (see draw()).
constexpr double walker_budget_share = 0.35;
// The sun's disc is drawn larger than the true 0.27 degrees, so that it reads in a picture.
constexpr double sun_disc_radius_deg = 1.2;

void check_finite(const Heightfield& heights) {
  for (int y = 0; y < heights.height(); ++y) {
    const auto row = heights.row(y);
    for (int x = 0; x < heights.width(); ++x)
      if (!std::isfinite(row[x])) fail("height {} at sample ({}, {}) is not allowed: heights must be finite", row[x], x, y);
  }
}

/// A linear-filtered, edge-clamped texture.
void set_sampling(GLenum filter) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void upload_surface(GLuint texture, const Heightfield& heights) {
  const std::vector<float> texels = look::height_and_gradient_texels(heights);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, heights.width(), heights.height(), 0, GL_RGBA, GL_FLOAT, texels.data());
  set_sampling(GL_LINEAR);
  check_gl("uploading the height texture");
}

void upload_noise(GLuint texture) {
  constexpr int size = 256;
  const std::vector<std::uint8_t> texels = look::tileable_noise_texels(size);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG8, size, size, 0, GL_RG, GL_UNSIGNED_BYTE, texels.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  check_gl("uploading the noise texture");
}

/// Hurst exponent of the near-view detail: a little smoother than most terrains, so that the
/// finest octaves roughen the light without turning into grain.
constexpr double detail_hurst = 0.85;

void upload_detail(GLuint texture, double& gradient_scale) {
  constexpr int size = 256;
  // The same for every renderer: made once per process.
  static const look::DetailNoise noise = look::detail_noise_texels(size, detail_hurst);
  gradient_scale = noise.gradient_scale;
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, noise.texels.data());
  // Mipmaps fade each octave out as the pixels grow past it: the overview does not alias.
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  check_gl("uploading the detail texture");
}

/// The landform maps of the ground's colour (look/ground_maps.hpp) on the shading grid.
void upload_ground(GLuint texture, const Heightfield& shading_heights, const look::RenderParams& params,
                   const look::TerrainLayers& layers) {
  // Landforms for colour need no more than about 513 samples a side (the height texture's own
  // curvature adds the finest): routing and blurs then cost a quarter.
  const Heightfield heights =
      look::downsample(shading_heights, look::downsample_step(shading_heights.width(), shading_heights.height(), 513));
  const look::GroundMapParams ground{params.sea_level_m, params.land.cliff_slope_deg, params.land.cliff_blend_deg};
  const std::vector<std::uint8_t> texels =
      look::ground_map_texels(heights, ground, layers.water_depth != nullptr ? layers.wetness : nullptr);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, heights.width(), heights.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  set_sampling(GL_LINEAR);
  check_gl("uploading the ground maps");
}

/// Signed water depth (r, look::signed_water_depth()) and wetness (g) as a float texture, each texel the
/// largest of its block: a river one sample wide must not vanish when the grid is thinned.
void upload_surface_water(GLuint texture, const Grid<float>& water_depth, const Heightfield& surface, const Grid<float>& wetness,
                          int max_samples) {
  const Grid<float> depth = look::signed_water_depth(water_depth, surface);
  const int step = look::downsample_step(depth.width(), depth.height(), max_samples);
  const int width = (depth.width() - 1) / step + 1, height = (depth.height() - 1) / step + 1;
  std::vector<float> texels(2 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float deepest = look::dry_water_depth_m, wettest = 0.0f;
      for (int dy = 0; dy < step && y * step + dy < depth.height(); ++dy)
        for (int dx = 0; dx < step && x * step + dx < depth.width(); ++dx) {
          deepest = std::max(deepest, depth(x * step + dx, y * step + dy));
          wettest = std::max(wettest, wetness(x * step + dx, y * step + dy));
        }
      const std::size_t i = 2 * (static_cast<std::size_t>(y) * width + x);
      texels[i] = deepest;
      texels[i + 1] = std::clamp(wettest, 0.0f, 1.0f);
    }
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, width, height, 0, GL_RG, GL_FLOAT, texels.data());
  set_sampling(GL_LINEAR);
  check_gl("uploading the rivers and lakes texture");
}

void upload_albedo(GLuint texture, const Grid<Rgba8>& albedo, int max_samples) {
  // Thinned by whole steps: colours are not averaged, which is fine for a rock pattern.
  const int step = look::downsample_step(albedo.width(), albedo.height(), max_samples);
  const int width = (albedo.width() - 1) / step + 1, height = (albedo.height() - 1) / step + 1;
  std::vector<Rgba8> texels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) texels[static_cast<std::size_t>(y) * width + x] = albedo(x * step, y * step);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  set_sampling(GL_LINEAR);
  // Mipmapped: far rock strata average into their colour instead of aliasing into specks.
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  check_gl("uploading the cliff albedo texture");
}

/// Samples per side of the mesh: a vertex every 4 pixels or so of the picture's longer side is
/// enough, since per-pixel normals come from the finer height texture; software rasterisers
/// shade whole 4x4 pixel blocks per triangle, so triangles smaller than that cost dearly.
int mesh_samples_for(const look::RenderParams& params) {
  // A walker's ground is close: its silhouettes (the next ridge, the bank at his feet) need
  // every sample the cap allows.
  if (params.camera.eye_height_m && params.view == look::View::perspective) return params.max_mesh_samples;
  return std::min(params.max_mesh_samples, std::max(129, std::max(params.width, params.height.value_or(720)) / 4 + 1));
}

void draw_strips(const look::IndexRange& range) {
  // GL takes a byte offset into the bound index buffer as a pointer.
  const auto offset = static_cast<std::uintptr_t>(range.first) * sizeof(std::uint32_t);
  const void* indices = reinterpret_cast<const void*>(offset);  // NOLINT(performance-no-int-to-ptr)
  glDrawElements(GL_TRIANGLE_STRIP, range.count, GL_UNSIGNED_INT, indices);
}

}  // namespace

TerrainRenderer::TerrainRenderer() {
  terrain_program_ =
      make_program(link_program("terrain", {shaders::common, shaders::terrain_vertex}, {shaders::common, shaders::terrain_fragment}));
  water_program_ =
      make_program(link_program("water", {shaders::common, shaders::water_vertex}, {shaders::common, shaders::water_fragment}));
  sky_program_ = make_program(
      link_program("sky", {shaders::common, shaders::sky_vertex}, {shaders::common, shaders::backdrop, shaders::sky_fragment}));
  star_program_ = make_program(link_program("stars", {shaders::common, shaders::backdrop, shaders::star_vertex},
                                            {shaders::common, shaders::backdrop, shaders::star_fragment}));
  vertex_array_ = make_vertex_array();
  vertices_ = make_buffer();
  indices_ = make_buffer();
  water_array_ = make_vertex_array();
  water_vertices_ = make_buffer();
  sky_array_ = make_vertex_array();
  star_array_ = make_vertex_array();
  star_vertices_ = make_buffer();
  surface_texture_ = make_texture();
  shading_texture_ = make_texture();
  cliff_texture_ = make_texture();
  noise_texture_ = make_texture();
  upload_noise(noise_texture_.id());
  ground_texture_ = make_texture();
  detail_texture_ = make_texture();
  upload_detail(detail_texture_.id(), detail_gradient_scale_);
  sky_texture_ = make_texture();
  sky_clear_texture_ = make_texture();
  haze_texture_ = make_texture();
  cloud_texture_ = make_texture();
  sun_disc_texture_ = make_texture();

  // The sea: one quad over the terrain at sea level.
  const float quad[] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 0, 0};
  glBindVertexArray(water_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, water_vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof(quad), quad, GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glBindVertexArray(0);
  check_gl("creating the renderer");
}

TerrainRenderer::~TerrainRenderer() = default;

void TerrainRenderer::upload_mesh(const Heightfield& heights) {
  const look::TerrainMesh mesh = look::build_terrain_mesh(heights);
  surface_orders_ = mesh.surface_orders;
  sides_ = mesh.sides;
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)), mesh.vertices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)), mesh.indices.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  check_gl("uploading the terrain mesh");
}

void TerrainRenderer::set_terrain(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers) {
  if (heights.width() < 2 || heights.height() < 2)
    fail("a {}x{} heightfield cannot be drawn: it needs at least 2x2 samples", heights.width(), heights.height());
  if (!(heights.cell_size_m > 0.0) || !std::isfinite(heights.cell_size_m))
    fail("cell size {} m is not allowed: it must be > 0", heights.cell_size_m);
  check_finite(heights);

  // Statistics of the full-resolution heights: band thresholds hang on the highest peak.
  double sum = 0.0;
  float low = heights.data()[0], high = low;
  for (float value : heights.values()) {
    low = std::min(low, value);
    high = std::max(high, value);
    sum += value;
  }
  min_height_m_ = low;
  max_height_m_ = high;
  mean_height_m_ = sum / static_cast<double>(heights.size());

  // GPU copies, averaged down when the heightfield is bigger than the caps.
  const int texture_step = look::downsample_step(heights.width(), heights.height(), params.max_texture_samples);
  const int mesh_step = look::downsample_step(heights.width(), heights.height(), mesh_samples_for(params));
  const int shading_step = look::downsample_step(heights.width(), heights.height(), max_shading_samples);
  // A heightfield too long and thin to be averaged down to the caps keeps its two rows (or
  // columns) and must still fit a texture: GL 4.5 guarantees 16384 texels a side.
  constexpr int longest_texture = 16384;
  const int texture_side = (std::max(heights.width(), heights.height()) - 1) / texture_step + 1;
  if (texture_side > longest_texture)
    fail(
        "a {}x{} heightfield is too long and thin to draw: averaged down it keeps {} samples along its length, more than the {} a GPU "
        "texture may hold; crop it or resample it nearer to square (gdal_translate -outsize)",
        heights.width(), heights.height(), texture_side, longest_texture);
  const Heightfield texture_heights = downsample(heights, texture_step);
  const Heightfield mesh_heights = mesh_step == texture_step ? texture_heights : downsample(heights, mesh_step);
  shading_heights_ = shading_step == texture_step ? texture_heights
                     : shading_step == mesh_step  ? mesh_heights
                                                  : downsample(heights, shading_step);
  // Extent between the outer samples that are drawn (a downsample may drop a few edge samples).
  width_m_ = (texture_heights.width() - 1) * texture_heights.cell_size_m;
  depth_m_ = (texture_heights.height() - 1) * texture_heights.cell_size_m;

  // A coarse outline for fitting the camera: the highest sample around each of 33 x 33 points.
  outline_.clear();
  constexpr int outline_points = 33;
  for (int j = 0; j < outline_points; ++j)
    for (int i = 0; i < outline_points; ++i) {
      const int cx = i * (mesh_heights.width() - 1) / (outline_points - 1);
      const int cy = j * (mesh_heights.height() - 1) / (outline_points - 1);
      const int reach = std::max(mesh_heights.width(), mesh_heights.height()) / (2 * (outline_points - 1)) + 1;
      float highest = mesh_heights(cx, cy);
      for (int y = std::max(0, cy - reach); y <= std::min(mesh_heights.height() - 1, cy + reach); ++y)
        for (int x = std::max(0, cx - reach); x <= std::min(mesh_heights.width() - 1, cx + reach); ++x)
          highest = std::max(highest, mesh_heights(x, y));
      outline_.push_back({static_cast<double>(cx) / (mesh_heights.width() - 1) * width_m_, highest,
                          static_cast<double>(cy) / (mesh_heights.height() - 1) * depth_m_});
    }

  upload_surface(surface_texture_.id(), texture_heights);
  texture_cell_m_ = texture_heights.cell_size_m;
  upload_mesh(mesh_heights);
  // The surroundings continue the mesh's heights (made when a perspective picture first needs them).
  area_heights_ = mesh_heights;
  surroundings_.clear();
  surroundings_key_.reset();
  mesh_heights_ = mesh_heights;
  if (layers.cliff_albedo != nullptr && !layers.cliff_albedo->empty()) {
    if (!cliff_texture_) cliff_texture_ = make_texture();
    upload_albedo(cliff_texture_.id(), *layers.cliff_albedo, params.max_texture_samples);
  } else {
    cliff_texture_.reset();
  }
  if (layers.water_depth != nullptr && layers.wetness != nullptr && !layers.water_depth->empty()) {
    if (layers.wetness->width() != layers.water_depth->width() || layers.wetness->height() != layers.water_depth->height())
      fail("the wetness layer is {}x{} and the water depth {}x{}: they must be the same size", layers.wetness->width(),
           layers.wetness->height(), layers.water_depth->width(), layers.water_depth->height());
    if (!water_texture_) water_texture_ = make_texture();
    upload_surface_water(water_texture_.id(), *layers.water_depth, heights, *layers.wetness, params.max_texture_samples);
  } else {
    water_texture_.reset();
  }
  band_noise_ = look::world_noise_texels(shading_heights_.width(), shading_heights_.height(), shading_heights_.cell_size_m,
                                         heights.origin_x_m, heights.origin_y_m);
  upload_ground(ground_texture_.id(), shading_heights_, params, layers);
  shading_key_.reset();
  has_terrain_ = true;
  if (!layers.plants.empty()) {
    set_plants(layers.plants);
  } else if (plants_) {
    plants_->clear();
  }
}

PlantRenderer& TerrainRenderer::plants() {
  if (!plants_) {
    plants_ = std::make_unique<PlantRenderer>();
    plants_->set_limits(plant_limits_);
    plants_->set_timing(plant_timing_);
  }
  return *plants_;
}

void TerrainRenderer::set_plants(const look::PlantsToDraw& plants, const Context& context) {
  if (!has_terrain_) throw GlError("TerrainRenderer::set_plants called before set_terrain");
  if (plants.empty() && !plants_) return;
  this->plants().set_plants(plants, mesh_heights_, width_m_, depth_m_, context);
}

void TerrainRenderer::set_plant_limits(const look::PlantLodLimits& limits) {
  plant_limits_ = limits;
  if (plants_) plants_->set_limits(limits);
}

void TerrainRenderer::set_plant_timing(bool on) {
  plant_timing_ = on;
  if (plants_) plants_->set_timing(on);
}

void TerrainRenderer::set_sky(const look::SkyDome& dome, const look::RenderParams& params) {
  glBindTexture(GL_TEXTURE_2D, sky_texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, dome.width, dome.height, 0, GL_RGBA, GL_FLOAT, dome.rgba.data());
  set_sampling(GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // azimuth goes round
  glBindTexture(GL_TEXTURE_2D, sky_clear_texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, dome.width, dome.height, 0, GL_RGBA, GL_FLOAT,
               dome.clear.size() == dome.rgba.size() ? dome.clear.data() : dome.rgba.data());
  set_sampling(GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  // The stars, one vertex each: direction and brightness.
  std::vector<float> stars;
  stars.reserve(4 * dome.stars.size());
  for (const look::Star& star : dome.stars)
    stars.insert(stars.end(), {star.direction.x, star.direction.y, star.direction.z, star.brightness});
  star_count_ = static_cast<GLsizei>(dome.stars.size());
  glBindVertexArray(star_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, star_vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(stars.size() * sizeof(float)), stars.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glBindVertexArray(0);
  // The cloud field, mip-mapped so that the far layer averages out, mirrored beyond its edges
  // (a midpoint-displacement image does not tile).
  has_clouds_ = dome.clouds_size > 1 && dome.clouds.size() == 2 * static_cast<std::size_t>(dome.clouds_size) * dome.clouds_size;
  cloud_cover_ = dome.cloud_cover;
  cloud_sunlight_ = dome.cloud_sunlight;
  glBindTexture(GL_TEXTURE_2D, cloud_texture_.id());
  const std::vector<float> no_clouds(2, 0.0f);
  const int cloud_size = has_clouds_ ? dome.clouds_size : 1;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, cloud_size, cloud_size, 0, GL_RG, GL_FLOAT, has_clouds_ ? dome.clouds.data() : no_clouds.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  sky_light_ = dome.sky_light;
  // The haze toward each azimuth: the fog and the far sky read it (u_haze), and the plants,
  // whose fog is worked out per plant on the CPU (look/plant_lod.hpp).
  horizon_haze_ = look::horizon_haze(dome);
  glBindTexture(GL_TEXTURE_2D, haze_texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F, dome.width, 1, 0, GL_RGB, GL_FLOAT, horizon_haze_.data());
  set_sampling(GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);

  // The sun's disc along its radius (Table 3: act from 0 at the centre to 1 at the edge).
  constexpr int steps = 64;
  std::vector<float> disc(4 * steps);
  const double elevation = *params.sun_elevation_deg;
  const float strength = static_cast<float>(*params.sky.sun_strength);
  for (int k = 0; k < steps; ++k) {
    const double act = (k + 0.5) / steps;
    const glm::vec3 colour = linear(look::sun_disc_colour(elevation, act)) * (1.5f + 2.0f * strength);
    disc[4 * k] = colour.r, disc[4 * k + 1] = colour.g, disc[4 * k + 2] = colour.b;
    disc[4 * k + 3] = look::sun_disc_alpha(act) * (0.35f + 0.65f * strength);
  }
  glBindTexture(GL_TEXTURE_2D, sun_disc_texture_.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, steps, 1, 0, GL_RGBA, GL_FLOAT, disc.data());
  set_sampling(GL_LINEAR);
  check_gl("uploading the sky");
  has_sky_ = true;
}

void TerrainRenderer::update_surroundings(const look::RenderParams& params) {
  const SurroundingsKey key{params.beyond, params.sea_level_m, params.sea};
  if (surroundings_key_ == key) return;
  // Without a sea the lowest valley is the base level: the land around stays above it.
  const std::optional<double> floor_m = params.sea ? std::nullopt : std::optional<double>(min_height_m_);
  const look::Surroundings s = look::build_surroundings(area_heights_, params.sea_level_m, params.beyond, floor_m);
  surroundings_.upload(s, std::max(width_m_, depth_m_));
  surroundings_key_ = key;
}

void TerrainRenderer::update_shading(const look::RenderParams& params) {
  const ShadingKey key{*params.sun_azimuth_deg, *params.sun_elevation_deg, params.exaggeration, params.sea_level_m};
  if (shading_key_ == key) return;
  // The sea is flat: shadows fall on its surface, and hollows under it are not occluded.
  Heightfield surface = shading_heights_;
  for (float& value : surface.values()) value = std::max(value, static_cast<float>(params.sea_level_m));
  const Grid<float> sun = look::sun_visibility(surface, {*params.sun_azimuth_deg, *params.sun_elevation_deg, params.exaggeration, 1.2});
  const int radius = std::max(8, std::max(surface.width(), surface.height()) / 16);
  const Grid<float> sky = look::ambient_occlusion(surface, {params.exaggeration, radius});

  // One RGBA texel per sample: sun, open sky, and the two band noises, so that the fragment
  // shader gets all four with one texture read (a software rasteriser pays for each).
  std::vector<std::uint8_t> texels(surface.size() * 4);
  for (std::size_t i = 0; i < surface.size(); ++i) {
    texels[4 * i] = static_cast<std::uint8_t>(std::lround(std::clamp(sun.data()[i], 0.0f, 1.0f) * 255.0f));
    texels[4 * i + 1] = static_cast<std::uint8_t>(std::lround(std::clamp(sky.data()[i], 0.0f, 1.0f) * 255.0f));
    texels[4 * i + 2] = band_noise_[2 * i];
    texels[4 * i + 3] = band_noise_[2 * i + 1];
  }
  glBindTexture(GL_TEXTURE_2D, shading_texture_.id());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, surface.width(), surface.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  set_sampling(GL_LINEAR);
  check_gl("uploading shadows and ambient occlusion");
  shading_texels_ = std::move(texels);
  shading_key_ = key;
}

double TerrainRenderer::ground_height_m(double x_m, double z_m) const {
  if (mesh_heights_.empty()) return 0.0;
  const int w = mesh_heights_.width(), h = mesh_heights_.height();
  const double fx = std::clamp(x_m / width_m_, 0.0, 1.0) * (w - 1), fz = std::clamp(z_m / depth_m_, 0.0, 1.0) * (h - 1);
  const int x0 = std::min(static_cast<int>(fx), w - 2), z0 = std::min(static_cast<int>(fz), h - 2);
  const double u = fx - x0, v = fz - z0;
  const double h00 = mesh_heights_(x0, z0), h10 = mesh_heights_(x0 + 1, z0), h01 = mesh_heights_(x0, z0 + 1),
               h11 = mesh_heights_(x0 + 1, z0 + 1);
  // The cell is drawn as two triangles split along one diagonal or the other (the strip order
  // decides): the higher of the two surfaces is never below the drawn ground.
  const double split_main = u >= v ? h00 + u * (h10 - h00) + v * (h11 - h10) : h00 + v * (h01 - h00) + u * (h11 - h01);
  const double split_other =
      u + v <= 1.0 ? h00 + u * (h10 - h00) + v * (h01 - h00) : h11 + (1.0 - u) * (h01 - h11) + (1.0 - v) * (h10 - h11);
  return std::max(split_main, split_other);
}

/// What one draw() works out before it draws: the drawn box, the camera, the light and the sea.
/// Heights are drawn relative to sea level, times the exaggeration.
struct TerrainRenderer::DrawPass {
  bool in_world = false;  // the perspective view: the world goes on around the terrain
  double sea = 0.0;       // sea level [Units: m]
  double scale = 1.0;     // the exaggeration
  double highest = 0.0;   // drawn height of the highest land above the sea
  double base_y = 0.0;    // drawn height of the block's base
  bool has_plants = false;
  double terrain_size_m = 1.0;  // the terrain's longer side (look::TerrainFrame::size_m)
  look::CameraMatrices camera;
  glm::mat4 view_proj{1.0f};
  glm::vec3 sun_dir{0.0f}, sun_light{0.0f}, sky_light{0.0f};
  bool draws_sea = false;
  double sea_depth_scale = 1.0;  // the water depth that turns the sea deep-coloured [Units: m]
  glm::vec4 sea_rect{0.0f};      // where the sea is drawn: x and z from, x and z to [Units: m]
  int surface_order = 0;         // the mesh's strip order, front to back for this camera
};

void TerrainRenderer::fit_camera(const look::RenderParams& params, DrawPass& pass, int width, int height) const {
  const double sea = pass.sea, scale = pass.scale;
  std::vector<glm::dvec3> fit_points;
  fit_points.reserve(outline_.size() + 4);
  for (const glm::dvec3& point : outline_) fit_points.emplace_back(point.x, std::max(point.y - sea, 0.0) * scale, point.z);
  for (double x : {0.0, width_m_})
    for (double z : {0.0, depth_m_}) fit_points.emplace_back(x, pass.base_y, z);
  // Plants reach above the ground: the box (near and far planes, the top view's height) takes
  // in the tallest, and a picture of a few plants (a single tree) frames them whole.
  const double top_y = pass.has_plants ? std::max(pass.highest, plants_->highest_y(sea, scale)) : pass.highest;
  constexpr std::int64_t few_plants = 64;
  if (pass.has_plants && plants_->count() < few_plants) plants_->add_fit_points(fit_points, sea, scale);
  look::TerrainFrame frame{width_m_, depth_m_, pass.base_y, top_y, std::max(mean_height_m_ - sea, 0.0) * scale, fit_points};
  if (pass.in_world) frame.surroundings_reach_m = surroundings_.reach_m();
  if (params.camera.eye_height_m)
    frame.eye_ground_y =
        (std::max(ground_height_m(params.camera.target_x * width_m_, params.camera.target_y * depth_m_), sea) - sea) * scale;
  pass.camera = look::camera_matrices(params, frame, width, height);
  pass.terrain_size_m = frame.size_m();
}

TerrainRenderer::DrawPass TerrainRenderer::prepare_pass(const look::RenderParams& params, int width, int height) const {
  DrawPass pass;
  pass.in_world = params.view == look::View::perspective;
  // The drawn box: the block's base a little below the lowest point (or sea floor).
  const double sea = params.sea_level_m, scale = params.exaggeration;
  pass.sea = sea;
  pass.scale = scale;
  // A deep sea floor is hidden by opaque water anyway: the block is cut off at a depth of a
  // third of the land's height, so that its sides do not dwarf the land.
  pass.highest = std::max(max_height_m_ - sea, 0.0) * scale;
  const double lowest = std::max((std::min(min_height_m_, sea) - sea) * scale, -std::max(pass.highest / 3.0, 1.0));
  pass.base_y = lowest - 0.04 * std::max(pass.highest - lowest, 1.0);
  pass.has_plants = plants_ && plants_->count() > 0;
  fit_camera(params, pass, width, height);
  pass.view_proj = pass.camera.projection * pass.camera.view;

  pass.sun_dir = direction_of(*params.sun_azimuth_deg, *params.sun_elevation_deg);
  // Sky light: what the sky's upper hemisphere sends down; sunlight fades out as the sun sets.
  pass.sky_light = glm::max(sky_strength * sky_light_, night_light);
  const float sun_up = static_cast<float>(std::clamp((*params.sun_elevation_deg + 1.0) / 4.0, 0.0, 1.0));
  pass.sun_light = sun_strength * linear(*params.sky.sunlight) * static_cast<float>(*params.sky.sun_strength) * sun_up;

  // The sea: where it is drawn, and the depth that turns it deep-coloured (a fiftieth of the
  // relief, at least a metre).
  pass.draws_sea = min_height_m_ < sea || (pass.in_world && params.sea);
  pass.sea_depth_scale = std::max(0.02 * (max_height_m_ - min_height_m_), 1.0);
  const double reach = pass.in_world ? surroundings_.reach_m() : 0.0;
  pass.sea_rect = glm::vec4(static_cast<float>(0.5 * width_m_ - std::max(reach, 0.5 * width_m_)),
                            static_cast<float>(0.5 * depth_m_ - std::max(reach, 0.5 * depth_m_)),
                            static_cast<float>(0.5 * width_m_ + std::max(reach, 0.5 * width_m_)),
                            static_cast<float>(0.5 * depth_m_ + std::max(reach, 0.5 * depth_m_)));
  pass.surface_order = look::surface_order_for(pass.camera.forward.x, pass.camera.forward.z);
  return pass;
}

void TerrainRenderer::set_common_uniforms(const Uniforms& u, const DrawPass& pass, const look::RenderParams& params) const {
  u.set("u_surface", 0);
  u.set("u_shading", 1);
  u.set("u_noise", 3);
  u.set("u_extent", glm::vec2(static_cast<float>(width_m_), static_cast<float>(depth_m_)));
  u.set("u_terrain_size", pass.terrain_size_m);
  u.set("u_sea_level", pass.sea);
  u.set("u_exaggeration", pass.scale);
  u.set("u_view_proj", pass.view_proj);
  u.set("u_camera_pos", pass.camera.position);
  u.set("u_camera_forward", pass.camera.forward);
  u.set("u_orthographic", pass.camera.orthographic ? 1 : 0);
  u.set("u_sun_dir", pass.sun_dir);
  u.set("u_sun_light", pass.sun_light);
  u.set("u_sky_light", pass.sky_light);
  u.set("u_sky", 4);
  u.set("u_time", params.time_s);
  u.set("u_fog_density", *params.atmosphere.fog);
  u.set("u_fog_start", pass.camera.nearest_m);
  u.set("u_shadows", params.shadows ? 1 : 0);
  u.set("u_ring", 0);
  u.set("u_ring_x", surroundings_.x_axis());
  u.set("u_ring_z", surroundings_.z_axis());
  u.set("u_ring_surface", 9);
  // The cloud layer above the highest land, at least 2 km up; one cloud image spans eight times
  // its height (overhead a cloud sample covers about half a degree).
  const double cloud_height = std::max(2000.0, 1.25 * pass.highest);
  u.set("u_sky_clear", 7);
  u.set("u_haze", 13);
  u.set("u_clouds", 8);
  u.set("u_has_clouds", has_clouds_ ? 1 : 0);
  u.set("u_cloud_height", cloud_height);
  u.set("u_cloud_span", 8.0 * cloud_height);
  u.set("u_cloud_sun", cloud_sunlight_);
  u.set("u_cloud_cover", cloud_cover_);
}

/// The texture units the shaders read (their u_* sampler uniforms name the same units).
void TerrainRenderer::bind_textures(bool in_world) const {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, surface_texture_.id());
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, shading_texture_.id());
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, cliff_texture_ ? cliff_texture_.id() : 0);
  glActiveTexture(GL_TEXTURE3);
  glBindTexture(GL_TEXTURE_2D, noise_texture_.id());
  glActiveTexture(GL_TEXTURE4);
  glBindTexture(GL_TEXTURE_2D, sky_texture_.id());
  glActiveTexture(GL_TEXTURE5);
  glBindTexture(GL_TEXTURE_2D, sun_disc_texture_.id());
  glActiveTexture(GL_TEXTURE6);
  glBindTexture(GL_TEXTURE_2D, water_texture_ ? water_texture_.id() : 0);
  glActiveTexture(GL_TEXTURE7);
  glBindTexture(GL_TEXTURE_2D, sky_clear_texture_.id());
  glActiveTexture(GL_TEXTURE8);
  glBindTexture(GL_TEXTURE_2D, cloud_texture_.id());
  glActiveTexture(GL_TEXTURE9);
  glBindTexture(GL_TEXTURE_2D, in_world ? surroundings_.surface_texture() : 0);
  glActiveTexture(GL_TEXTURE11);
  glBindTexture(GL_TEXTURE_2D, ground_texture_.id());
  glActiveTexture(GL_TEXTURE12);
  glBindTexture(GL_TEXTURE_2D, detail_texture_.id());
  glActiveTexture(GL_TEXTURE13);
  glBindTexture(GL_TEXTURE_2D, haze_texture_.id());
  glActiveTexture(GL_TEXTURE0);
}

/// The terrain program's own uniforms: its textures, the land's bands and palette, the sea.
void TerrainRenderer::set_ground_uniforms(const Uniforms& u, const DrawPass& pass, const look::RenderParams& params) const {
  const look::Land& land = params.land;
  const look::Sea& water = params.water;
  u.set("u_base_y", pass.base_y);
  u.set("u_cliff_albedo", 2);
  u.set("u_has_cliff_albedo", cliff_texture_ ? 1 : 0);
  u.set("u_surface_water", 6);
  u.set("u_has_surface_water", water_texture_ ? 1 : 0);
  u.set("u_max_above_sea", std::max(max_height_m_ - pass.sea, 1.0));
  u.set("u_band_scale", look::band_scale_m(params.land, pass.sea, max_height_m_));
  u.set("u_beach_top", land.beach_top);
  u.set("u_tree_line", look::tree_line_fraction(land));
  u.set("u_snow_line", look::snow_line_fraction(land));
  u.set("u_blend", land.blend);
  u.set("u_border_noise", land.border_noise);
  u.set("u_cliff_slope", land.cliff_slope_deg);
  u.set("u_cliff_blend", land.cliff_blend_deg);
  u.set("u_snow_max_slope", land.snow_max_slope_deg);
  u.set("u_cover_slope", land.cover_slope_deg.value_or(land.cliff_slope_deg - 4.0));
  u.set("u_ambient_occlusion", params.ambient_occlusion);
  u.set("u_ground", 11);
  u.set("u_detail", 12);
  u.set("u_detail_gradient_scale", detail_gradient_scale_);
  u.set("u_texel_m", texture_cell_m_);
  const glm::vec3 sunny = direction_of(land.sunny_azimuth_deg.value_or(180.0), 0.0);
  u.set("u_sunny_dir", glm::vec2(sunny.x, sunny.z));
  u.set("u_seabed", linear(*water.seabed));
  u.set("u_beach", linear(*land.beach));
  u.set("u_forest_low", linear(*land.forest_low));
  u.set("u_forest_high", linear(*land.forest_high));
  u.set("u_cliff", linear(*land.cliff));
  u.set("u_snow", linear(*land.snow));
  u.set("u_earth", linear(*land.earth));
  u.set("u_water_shallow", linear(*water.shallow));
  u.set("u_water_deep", linear(*water.deep));
  u.set("u_block", pass.in_world ? 0 : 1);
  // The world's sea covers deep water whole: the ground under it is not shaded (the shader's
  // under_opaque_sea()).
  u.set("u_sea_over", pass.in_world && pass.draws_sea ? 1 : 0);
  u.set("u_sea_rect", pass.sea_rect);
  u.set("u_sea_depth_scale", pass.sea_depth_scale);
}

/// The terrain, and in perspective the sides of the block and the surroundings.
void TerrainRenderer::draw_ground(const DrawPass& pass, const look::RenderParams& params) {
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_PRIMITIVE_RESTART);
  glPrimitiveRestartIndex(strip_restart);
  {
    const Uniforms u(terrain_program_.id());
    set_common_uniforms(u, pass, params);
    set_ground_uniforms(u, pass, params);
    glBindVertexArray(vertex_array_.id());
    // Front to back: strips ordered from the camera outward (see upload_mesh).
    draw_strips(surface_orders_[pass.surface_order]);
    // The block's cut sides, at every elevation (from high up they are a sliver, but they are
    // there: a block seen at 60 degrees lost them once); in the world they are ground-coloured
    // and fill the seam with the coarser surroundings.
    draw_strips(sides_);
    if (pass.in_world) {
      // The surroundings: the same program over their own grid and textures, without the
      // terrain's rock texture and rivers.
      u.set("u_ring", 1);
      u.set("u_has_surface_water", 0);
      u.set("u_ring_shading", 10);
      u.set("u_mirror_reach", surroundings_.mirror_reach_m());
      glActiveTexture(GL_TEXTURE10);
      glBindTexture(GL_TEXTURE_2D, surroundings_.shading_texture());
      glActiveTexture(GL_TEXTURE0);
      surroundings_.draw();
    }
  }
  glDisable(GL_PRIMITIVE_RESTART);
}

/// What the plants' renderer needs of the camera, the sea, the fog and the terrain's light.
look::PlantView TerrainRenderer::plant_view(const DrawPass& pass, const look::RenderParams& params, int height) const {
  look::PlantView view;
  view.view_proj = pass.view_proj;
  view.camera_pos = pass.camera.position;
  view.camera_forward = pass.camera.forward;
  view.orthographic = pass.camera.orthographic;
  view.pixels_per_unit = pass.camera.projection[1][1] * 0.5f * static_cast<float>(height);
  view.sea_level_m = static_cast<float>(pass.sea);
  view.exaggeration = static_cast<float>(pass.scale);
  view.rows_triangulation = pass.surface_order < 2;
  view.fog_density = static_cast<float>(*params.atmosphere.fog);
  view.fog_start_m = static_cast<float>(pass.camera.nearest_m);
  view.terrain_size_m = static_cast<float>(pass.terrain_size_m);
  view.haze = horizon_haze_;
  view.shading = shading_texels_;
  view.shading_width = shading_heights_.width();
  view.shading_height = shading_heights_.height();
  view.width_m = static_cast<float>(width_m_);
  view.depth_m = static_cast<float>(depth_m_);
  view.shadows = params.shadows;
  view.ambient_occlusion = static_cast<float>(params.ambient_occlusion);
  view.side_views = ImpostorLayout::side_views;
  return view;
}

void TerrainRenderer::draw_plants(const DrawPass& pass, const look::RenderParams& params, int height) {
  // A walker has hundreds of trees close by, whose meshes would fill budgets an overview
  // never reaches: a ground view draws within the picture's time by giving fewer of them
  // full meshes (the rest go down a level, which at their size shows little).
  look::PlantLodLimits limits = plant_limits_;
  if (pass.camera.walking) {
    limits.full_triangle_budget = static_cast<std::int64_t>(walker_budget_share * static_cast<double>(limits.full_triangle_budget));
    limits.simplified_triangle_budget =
        static_cast<std::int64_t>(walker_budget_share * static_cast<double>(limits.simplified_triangle_budget));
    limits.shadow_min_px *= 4.0f;
  }
  plants_->set_limits(limits);
  plants_->draw(plant_view(pass, params, height), {pass.sun_dir, pass.sun_light, pass.sky_light});
}

/// The sky (or the top view's background) on the far plane, after the terrain, so that only
/// the pixels the terrain left empty are shaded.
void TerrainRenderer::draw_sky(const DrawPass& pass, const look::RenderParams& params) {
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  // The sky and the stars read the same backdrop (shaders::backdrop).
  const auto set_backdrop_uniforms = [&](const Uniforms& u) {
    set_common_uniforms(u, pass, params);
    u.set("u_inverse_view_proj", glm::inverse(pass.view_proj));
    u.set("u_true_sky", pass.camera.walking || pass.in_world ? 1 : 0);
    u.set("u_ring", pass.in_world ? 1 : 0);
  };
  {
    const Uniforms u(sky_program_.id());
    set_backdrop_uniforms(u);
    u.set("u_background", glm::max(sky_light_ * 0.8f, night_light));
    u.set("u_sun_disc", 5);
    u.set("u_sun_radius", sun_disc_radius_deg * degrees);
    glBindVertexArray(sky_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  if (star_count_ > 0) {  // the top, front and side views discard them (u_orthographic)
    // Each star's light added to the sky's pixel, on the far plane where nothing was drawn.
    const Uniforms u(star_program_.id());
    set_backdrop_uniforms(u);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glPointSize(1.0f);
    glBindVertexArray(star_array_.id());
    glDrawArrays(GL_POINTS, 0, star_count_);
    glDisable(GL_BLEND);
  }
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
}

/// The sea, blended over the seabed where it is shallow; in the world out to the horizon.
void TerrainRenderer::draw_sea(const DrawPass& pass, const look::RenderParams& params) {
  const look::Sea& water = params.water;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const Uniforms u(water_program_.id());
  set_common_uniforms(u, pass, params);
  u.set("u_water_shallow", linear(*water.shallow));
  u.set("u_water_deep", linear(*water.deep));
  u.set("u_ripple", water.ripple);
  u.set("u_foam_depth", water.foam_depth_m);
  u.set("u_depth_scale", pass.sea_depth_scale);
  u.set("u_sea_rect", pass.sea_rect);
  u.set("u_ring", pass.in_world ? 1 : 0);
  glBindVertexArray(water_array_.id());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisable(GL_BLEND);
}

void TerrainRenderer::draw(const look::RenderParams& params, int width, int height) {
  if (!has_terrain_ || !has_sky_) throw GlError("TerrainRenderer::draw called before set_terrain and set_sky");
  update_shading(params);
  // The world goes on around the terrain in the perspective view; the block view shows it alone.
  if (params.view == look::View::perspective) update_surroundings(params);
  const DrawPass pass = prepare_pass(params, width, height);

  glViewport(0, 0, width, height);
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  bind_textures(pass.in_world);
  draw_ground(pass, params);
  // Plants stand on the terrain: after it, before the sky fills what is left.
  if (pass.has_plants) draw_plants(pass, params, height);
  draw_sky(pass, params);
  if (pass.draws_sea) draw_sea(pass, params);
  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("drawing the terrain");
}

}  // namespace sansui::render
