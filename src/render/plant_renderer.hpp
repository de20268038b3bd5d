// Plants on the terrain (issue 11, item 5: rendering that scales): instanced meshes at two levels
// of detail, impostor cards and, for the smallest, impostor point sprites, chosen per plant and
// per draw (look/plant_lod.hpp), lit like the terrain. Owned by TerrainRenderer, which calls it
// between the terrain and the sky.
//
// Plants keep their true size: the vertical exaggeration raises the ground they stand on, not
// them (a 20 m oak is 20 m tall on any relief), so an exaggerated mountain shows its forest as
// the texture it is rather than a bristle of needles.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "look/plant_lod.hpp"
#include "look/plant_models.hpp"
#include "render/gl_util.hpp"

namespace sansui::render {

/// Counts and times of the last set_plants() and draw(), for benchmarks and the curious.
struct PlantStats {
  int kinds = 0;            ///< (species, variant) pairs with meshes and impostors
  std::int64_t plants = 0;  ///< plants on the drawn terrain
  std::int64_t full = 0;    ///< drawn with the full mesh, last draw
  std::int64_t simplified = 0;
  std::int64_t impostors = 0;  ///< as cards
  std::int64_t sprites = 0;    ///< as point sprites (the smallest impostors)
  std::int64_t culled = 0;     ///< outside the view
  std::int64_t thinned = 0;    ///< smaller than a pixel or two, and not drawn (plant_lod.hpp)
  std::int64_t triangles = 0;  ///< triangles drawn: meshes', and two per card (sprites are points)
  std::int64_t shadows = 0;    ///< trees' shadows drawn on the ground, last draw
  double build_s = 0.0;        ///< building the meshes (look::PlantKindCache: 0 when they were built before)
  double atlas_s = 0.0;        ///< drawing the impostor atlas, set_plants
  double upload_s = 0.0;       ///< the plants on the terrain, vertex buffers, set_plants
  double select_s = 0.0;       ///< culling, levels of detail and sorting, last draw
  double draw_s = 0.0;         ///< drawing, last draw; only with set_timing(true), else 0
};

/// What draw() needs besides the selection's view: the terrain's light (linear colours).
struct PlantLight {
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};
  glm::vec3 sun_light{1.0f};
  glm::vec3 sky_light{0.5f};
};

class PlantRenderer {
 public:
  /// Compiles the shaders. Needs a current GL 3.3 core context; throws GlError.
  PlantRenderer();
  ~PlantRenderer();
  PlantRenderer(const PlantRenderer&) = delete;
  PlantRenderer& operator=(const PlantRenderer&) = delete;

  /// Takes the plants of `placement` that stand on the drawn terrain: `mesh_heights` is the mesh
  /// TerrainRenderer draws (its origin in world metres), stretched over width_m x depth_m.
  /// Builds a full and a simplified mesh and an impostor for every (species, variant) used,
  /// unless the kinds and the look are those of the last call. Throws InputError for a species
  /// or variant out of range. Reports "render: plants".
  void set_plants(const look::PlantsToDraw& plants, const Heightfield& mesh_heights, double width_m, double depth_m,
                  const Context& context = quiet_context());
  /// Forgets the plants (meshes are kept for the next set_plants).
  void clear();

  std::int64_t count() const { return static_cast<std::int64_t>(spots_.size()); }
  /// The highest drawn point of any plant. [Units: drawing y]
  double highest_y(double sea_level_m, double exaggeration) const;
  /// Appends each plant's top and the two sides of its crown seen across the view: points a
  /// fitted camera keeps in the picture (TerrainRenderer adds them when there are few plants).
  void add_fit_points(std::vector<glm::dvec3>& points, double sea_level_m, double exaggeration) const;

  /// Draws the plants into the bound framebuffer with depth test (after the terrain), using
  /// texture units 6 and 7. A multisampled target gets alpha-to-coverage for the impostors.
  void draw(const look::PlantView& plant_view, const PlantLight& light);

  void set_limits(const look::PlantLodLimits& limits) { limits_ = limits; }
  const look::PlantLodLimits& limits() const { return limits_; }
  /// Waits for the GPU around the draw to time it (PlantStats::draw_s).
  void set_timing(bool on) { timing_ = on; }
  const PlantStats& stats() const { return stats_; }

 private:
  struct Kind {
    std::uint16_t species = 0, variant = 0;
    std::int64_t full_first = 0, full_count = 0;  // index ranges in the element buffer
    std::int64_t simplified_first = 0, simplified_count = 0;
  };
  void upload_kinds(const look::PlantKinds& kinds);
  /// Points attributes 3-6 of `vertex_array` at the instances from `first` on, one per instance
  /// (divisor 1) or one per vertex (0, the sprites).
  void bind_instances(GLuint vertex_array, std::int64_t first, GLuint divisor) const;
  /// Darkens the ground under the trees' shadows (look::ShadowVertex), multiplying its colour.
  void draw_shadows(const std::vector<look::ShadowVertex>& shadows, const glm::mat4& view_proj);
  // draw(), stage by stage.
  void count_drawn(const look::PlantDrawList& list);
  /// All instances in one buffer: full meshes, simplified meshes, impostor cards, sprites.
  void upload_instances(const look::PlantDrawList& list, std::size_t total);
  /// The full and simplified meshes, one instanced draw per kind and level.
  void draw_meshes(const look::PlantDrawList& list, const glm::mat4& view_proj, const PlantLight& light);
  /// The impostor cards and the sprites, which face the camera.
  void draw_cards(const look::PlantDrawList& list, const look::PlantView& view, const PlantLight& light);

  GlName mesh_program_, impostor_program_, sprite_program_, capture_program_;
  GlName shadow_program_, shadow_array_, shadow_vertices_;
  GlName mesh_array_, capture_array_, impostor_array_, sprite_array_;
  GlName vertices_, indices_, corners_, instances_;
  GlName impostor_albedo_, impostor_normal_;
  std::vector<Kind> kinds_;
  std::vector<look::PlantKindInfo> kind_info_;
  std::shared_ptr<const look::PlantKinds> kinds_upload_;  // the kinds on the GPU
  std::vector<look::PlantSpot> spots_;
  look::TreeGrid tree_grid_;  // the trees of spots_, for their shadows on each other
  look::PlantLodLimits limits_;
  PlantStats stats_;
  bool timing_ = false;
};

}  // namespace sansui::render
