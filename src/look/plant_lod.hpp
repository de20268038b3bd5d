// Which plants are drawn, and how finely, for one camera: culling to the view frustum, a level of
// detail per plant by its size on the picture in pixels (its height seen from the side, its
// crown's width seen from above: full mesh near, simplified mesh in the middle, an impostor card
// beyond, the same impostor as a point sprite when a few pixels small), triangle budgets for the
// two meshes, and thinning of plants a pixel or two small. Pure CPU work, redone every draw; the
// result is instance data ready for the GPU (plant_renderer.cpp draws it). Per-plant light (the
// terrain's shadow and open sky under it) and fog are worked out here too, once per plant rather
// than once per vertex.
//
// Thinning keeps a forest's look from afar at a bounded cost: a tree h < t pixels in size is kept
// with probability (h / t)^2 and drawn t / h times larger, so the area it covers on the picture
// stays the same on average (a distant forest still darkens and textures the ground as much),
// while the number drawn per pixel of picture stays below about 1 / t^2. Ground plants (grass)
// below a few pixels are simply dropped: the terrain's own colour bands stand for them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "look/plant_models.hpp"

namespace sansui::look {

/// One plant as the renderer keeps it between draws, in drawing coordinates (x east, z south,
/// metres from the terrain's north-west sample).
struct PlantSpot {
  float x_m = 0.0f, z_m = 0.0f;
  /// True height (metres) of the drawn terrain mesh under the plant, for its two triangulations:
  /// strips of rows and strips of columns cut each cell along different diagonals
  /// (look/terrain_mesh.hpp), so the ground a plant stands on depends on which one is drawn.
  float ground_rows_m = 0.0f, ground_columns_m = 0.0f;
  float slope = 0.0f;  ///< steepness of the drawn mesh there, |dh/dx| + |dh/dz| (true heights)
  float scale = 1.0f;
  float cos_turn = 1.0f, sin_turn = 0.0f;  ///< turn about the vertical (PlantInstance::turn)
  std::uint16_t kind = 0;                  ///< index into the renderer's (species, variant) kinds
  bool ground_layer = false;               ///< grass and small plants (Placement::ground)
  std::uint32_t noise = 0;                 ///< random bits: thinning and a little tint
  /// The drawn mesh's gradient under the plant, dh/dx and dh/dz (true heights): the plane its
  /// shadow lies in.
  float gradient_x = 0.0f, gradient_z = 0.0f;
};

/// What select_plants needs to know of each kind.
struct PlantKindInfo {
  PlantBounds bounds;
  std::int64_t full_triangles = 0, simplified_triangles = 0;
};

/// One drawn plant as the shaders read it: four vec4 attributes per instance (64 bytes).
struct PlantInstance {
  float place[4];  ///< x, y (drawn ground), z, scale
  float turn[4];   ///< cos and sin of the turn (local x -> world (cos, 0, -sin)), sun visibility, sky visibility
  float haze[4];   ///< linear haze colour, fog fraction
  /// Bounds radius, bottom, top (at scale 1); kind * 16 + the impostor's view: the atlas's side
  /// view nearest to the direction the plant is seen from, in its own frame, or side_views for
  /// the view from above (render/impostor_atlas.hpp). Chosen here, per plant, and not per vertex
  /// on the GPU: llvmpipe transforms vertices on one thread.
  float box[4];
};
static_assert(sizeof(PlantInstance) == 64);

/// One corner of a tree's shadow on the ground: a quad (two triangles, six corners) from the
/// trunk's foot away from the sun, in the ground's plane under the tree. The shader
/// (render/plant_shaders.cpp) darkens the terrain under it by `strength` inside the crown's
/// shadow, an ellipse stretched by the sun's elevation, and along the trunk's thin shadow.
struct ShadowVertex {
  float x = 0.0f, y = 0.0f, z = 0.0f;  ///< drawing coordinates
  float along = 0.0f, across = 0.0f;   ///< the corner in crown radii: away from the sun, and across
  float reach = 0.0f;                  ///< the crown shadow's centre, crown radii from the trunk
  float stretch = 1.0f;                ///< the crown shadow's half-length along, crown radii
  float strength = 0.0f;               ///< darkening at the shadow's core, 0..1 (linear light)
  float trunk = 0.1f;                  ///< the trunk shadow's half-width, crown radii
};
static_assert(sizeof(ShadowVertex) == 36);

/// The camera and the terrain's light, as select_plants needs them.
struct PlantView {
  glm::mat4 view_proj{1.0f};
  glm::vec3 camera_pos{0.0f};
  glm::vec3 camera_forward{0.0f, -1.0f, 0.0f};
  bool orthographic = false;
  /// Pixels per metre at a view depth of 1 m (perspective) or per metre (orthographic): the
  /// projection's [1][1] times half the picture's height.
  float pixels_per_unit = 1.0f;
  float sea_level_m = 0.0f, exaggeration = 1.0f;
  bool rows_triangulation = true;  ///< the terrain is drawn as strips of rows (orders 0 and 1)
  /// Distance fog as the terrain shader has it (apply_fog): 0 density or orthographic: none.
  float fog_density = 0.0f, fog_start_m = 0.0f, terrain_size_m = 1.0f;
  /// The haze colour (linear) toward azimuths (i + 0.5) / n * 360 degrees: the sky dome 2 degrees
  /// above the horizon. Empty: no fog.
  std::span<const glm::vec3> haze;
  /// The terrain's shading texels (RGBA8: sun visibility, open sky, ...), over the extent below.
  std::span<const std::uint8_t> shading;
  int shading_width = 0, shading_height = 0;
  float width_m = 1.0f, depth_m = 1.0f;
  bool shadows = true;
  float ambient_occlusion = 1.0f;
  /// Side views of each plant in the impostor atlas (render/impostor_atlas.hpp). [Range: 1..15]
  int side_views = 8;
  /// Toward the sun (unit), and how much a tree's shadow darkens the ground it falls on: the
  /// sun's share of the ground's light. 0: no tree shadows.
  glm::vec3 sun_dir{0.0f, 1.0f, 0.0f};
  float shadow_strength = 0.0f;
};

/// Thresholds and budgets of the levels of detail.
struct PlantLodLimits {
  /// Plants at least this big on the picture get the full mesh. [Units: pixels]
  float full_min_px = 150.0f;
  /// ... at least this big, the simplified mesh; smaller ones an impostor. [Units: pixels]
  float simplified_min_px = 48.0f;
  /// Impostors smaller than this are point sprites: one vertex and one primitive each, where a
  /// card takes four vertices and two triangles, and a software rasteriser pays per primitive
  /// more than per pixel at this size. [Units: pixels] [Range: <= 64]
  float sprite_below_px = 12.0f;
  /// Trees smaller than this are thinned (see the file's comment). [Units: pixels]
  float thin_below_px = 2.0f;
  /// Ground plants smaller than this are not drawn. [Units: pixels]
  float ground_min_px = 3.0f;
  /// Trees at least this big on the picture cast a shadow on the ground. [Units: pixels]
  float shadow_min_px = 16.0f;
  /// At most this many triangles of full meshes; the biggest on the picture win, the rest go
  /// down a level. llvmpipe draws about a million plant triangles a second on two cores (it
  /// transforms vertices on one), so this is about a second: a hundred or two full trees.
  std::int64_t full_triangle_budget = 1'000'000;
  /// ... and of simplified meshes (a thousand trees or two).
  std::int64_t simplified_triangle_budget = 1'500'000;
};

struct PlantDrawList {
  /// Mesh instances grouped by kind (kind k: [first[k], first[k + 1])), front to back within a kind.
  std::vector<PlantInstance> full, simplified;
  std::vector<int> full_first, simplified_first;  ///< kinds + 1 entries
  std::vector<PlantInstance> impostors;           ///< cards, front to back
  std::vector<PlantInstance> sprites;             ///< impostors drawn as point sprites, front to back
  std::vector<ShadowVertex> shadows;              ///< six corners a shadow: the trees' shadows on the ground
  std::int64_t culled = 0;                        ///< outside the view frustum
  std::int64_t thinned = 0;                       ///< too small: dropped by thinning
  std::int64_t full_triangles = 0, simplified_triangles = 0;
};

/// The trees (not ground plants) bucketed on a square grid over the drawn terrain: the
/// neighbours a near tree looks among for crowns between it and the sun (select_plants).
struct TreeGrid {
  float cell_m = 16.0f;
  int columns = 0, rows = 0;
  std::vector<std::uint32_t> first;  ///< columns * rows + 1 entries: bucket b is index[first[b], first[b + 1])
  std::vector<std::uint32_t> index;  ///< indices into the spots, bucket by bucket, ascending within one
};
TreeGrid tree_grid(std::span<const PlantSpot> spots, float width_m, float depth_m, float cell_m = 16.0f);

/// The plants to draw for `view`. Deterministic: the same input gives the same lists, with any
/// number of threads.
/// With `trees` (tree_grid of the same spots), trees drawn as meshes are shaded by the crowns of
/// their neighbours between them and the sun: trees cast shadows on each other.
PlantDrawList select_plants(std::span<const PlantSpot> spots, std::span<const PlantKindInfo> kinds, const PlantView& view,
                            const PlantLodLimits& limits = {}, const TreeGrid* trees = nullptr);

}  // namespace sansui::look
