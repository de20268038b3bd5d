// The terrain renderer: draws a heightfield as a bird's-eye or top view into whatever
// framebuffer is bound (an OffscreenTarget headless, or a window's default framebuffer in the
// viewer). It needs a current OpenGL 3.3 core context, and owns only GL objects and the small
// CPU copies it needs to re-shade when the sun moves. render/ consumes terrain, never makes it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/color.hpp"
#include "core/grid.hpp"
#include "look/render_params.hpp"
#include "look/sky_dome.hpp"
#include "look/terrain_layers.hpp"
#include "look/terrain_mesh.hpp"
#include "render/gl_util.hpp"
#include "render/plant_renderer.hpp"
#include "render/surroundings_layer.hpp"

namespace sansui::render {

class TerrainRenderer {
 public:
  /// Compiles the shaders. Needs a current GL 3.3 core context; throws GlError.
  TerrainRenderer();
  ~TerrainRenderer();
  TerrainRenderer(const TerrainRenderer&) = delete;
  TerrainRenderer& operator=(const TerrainRenderer&) = delete;

  /// Uploads a terrain (metres; cell size from the grid; at least 2x2 samples). Heightfields
  /// wider than params.max_mesh_samples / max_texture_samples are averaged down first.
  /// Throws InputError on a NaN or infinite height, naming the sample. Draws layers.plants if
  /// set (see set_plants), else no plants.
  void set_terrain(const Heightfield& heights, const look::RenderParams& params, const look::TerrainLayers& layers = {});

  /// Plants on the terrain set last (world coordinates, as vegetation::place_plants gives them on
  /// the same heights): builds their meshes and impostors (kept while the species, variants and
  /// look stay the same) and places them on the drawn ground. Reports "render: plants".
  void set_plants(const look::PlantsToDraw& plants, const Context& context = quiet_context());
  /// Counts and times of the plants' last upload and draw (all zero without plants).
  PlantStats plant_stats() const { return plants_ ? plants_->stats() : PlantStats{}; }
  /// Levels of detail of the plants (look/plant_lod.hpp), for benchmarks and tests.
  void set_plant_limits(const look::PlantLodLimits& limits);
  /// Waits for the GPU around the plants' draw to time it (PlantStats::draw_s).
  void set_plant_timing(bool on);

  /// Uploads the sky around the viewer (look/sky_dome.hpp) and the sun's disc for `params`
  /// (resolved, see look::with_fallbacks()). Call it when the sun or the sky changes.
  void set_sky(const look::SkyDome& dome, const look::RenderParams& params);

  /// Draws the terrain into the bound framebuffer over the viewport (0, 0, width, height).
  /// `params` must be resolved (look::with_fallbacks()).
  /// Shadows and ambient occlusion are traced again only when the sun, the exaggeration or the
  /// sea level changed since the last draw. Call set_terrain() first.
  void draw(const look::RenderParams& params, int width, int height);

  /// The height of the drawn ground at (x east, z south) metres from the north-west corner
  /// (clamped to the terrain), never below the surface the mesh draws there. [Units: m]
  double ground_height_m(double x_m, double z_m) const;
  double width_m() const { return width_m_; }
  double depth_m() const { return depth_m_; }

 private:
  struct ShadingKey {
    double sun_azimuth_deg, sun_elevation_deg, exaggeration, sea_level_m;
    friend bool operator==(const ShadingKey&, const ShadingKey&) = default;
  };
  void update_shading(const look::RenderParams& params);
  void update_surroundings(const look::RenderParams& params);
  // draw(), stage by stage (terrain_renderer.cpp).
  struct DrawPass;
  DrawPass prepare_pass(const look::RenderParams& params, int width, int height) const;
  void fit_camera(const look::RenderParams& params, DrawPass& pass, int width, int height) const;
  void set_common_uniforms(const Uniforms& u, const DrawPass& pass, const look::RenderParams& params) const;
  void set_ground_uniforms(const Uniforms& u, const DrawPass& pass, const look::RenderParams& params) const;
  void bind_textures(bool in_world) const;
  void draw_ground(const DrawPass& pass, const look::RenderParams& params);
  look::PlantView plant_view(const DrawPass& pass, const look::RenderParams& params, int height) const;
  void draw_plants(const DrawPass& pass, const look::RenderParams& params, int height);
  void draw_sky(const DrawPass& pass, const look::RenderParams& params);
  void draw_sea(const DrawPass& pass, const look::RenderParams& params);
  void upload_mesh(const Heightfield& heights);
  PlantRenderer& plants();

  GlName terrain_program_, water_program_, sky_program_;
  GlName vertex_array_, vertices_, indices_;
  GlName water_array_, water_vertices_;
  GlName sky_array_;
  GlName star_program_, star_array_, star_vertices_;  // the stars as points (set_sky)
  GLsizei star_count_ = 0;
  GlName surface_texture_, shading_texture_, cliff_texture_, noise_texture_, sky_texture_, sun_disc_texture_;
  GlName sky_clear_texture_, cloud_texture_;  // the sky without clouds; the cloud field (set_sky)
  GlName haze_texture_;                       // look::horizon_haze(), one row round the horizon
  bool has_clouds_ = false;
  float cloud_cover_ = 0.0f;
  glm::vec3 cloud_sunlight_{0.0f};
  GlName ground_texture_;                             // wetness, curvature, scree (look/ground_maps.hpp) on the shading grid
  GlName detail_texture_;                             // near-view detail noise: slope and colour, tiled, mipmapped
  double detail_gradient_scale_ = 1.0;                // the detail texture's slope per tile width at 1.0
  double texture_cell_m_ = 1.0;                       // metres between the height texture's samples
  GlName water_texture_;                              // rivers and lakes: depth (r), wetness (g); none without them
  glm::vec3 sky_light_{0.0f};                         // linear light of the sky's upper hemisphere (look::SkyDome::sky_light)
  std::array<look::IndexRange, 4> surface_orders_{};  // see look::TerrainMesh
  look::IndexRange sides_{};
  SurroundingsLayer surroundings_;  // the land around the terrain (perspective view)
  struct SurroundingsKey {
    look::Beyond beyond;
    double sea_level_m;
    bool sea;
    friend bool operator==(const SurroundingsKey&, const SurroundingsKey&) = default;
  };
  std::optional<SurroundingsKey> surroundings_key_;  // what surroundings_ was built for, if anything
  Heightfield area_heights_;                         // the heights the surroundings continue

  Heightfield shading_heights_;               // heights at the resolution shadows and occlusion are traced at
  Heightfield mesh_heights_;                  // the heights the mesh is drawn from (plants stand on it)
  std::vector<std::uint8_t> shading_texels_;  // the shading texture's texels, for the plants' light
  std::vector<glm::vec3> horizon_haze_;       // look::horizon_haze(), for the plants' fog
  std::unique_ptr<PlantRenderer> plants_;     // made on first use
  look::PlantLodLimits plant_limits_;
  bool plant_timing_ = false;
  std::vector<std::uint8_t> band_noise_;  // two noise channels per shading sample (surface_maps.hpp)
  std::vector<glm::dvec3> outline_;       // (x m, height m, z m): coarse high points, to fit the camera
  std::optional<ShadingKey> shading_key_;
  double width_m_ = 1.0, depth_m_ = 1.0;
  double min_height_m_ = 0.0, max_height_m_ = 0.0, mean_height_m_ = 0.0;
  bool has_terrain_ = false, has_sky_ = false;
};

}  // namespace sansui::render
