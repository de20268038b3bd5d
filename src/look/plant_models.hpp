// Plant meshes made ready for the GPU: a tree mesh (vegetation/tree_mesh.hpp) becomes packed
// vertices with the light they will need baked in. Pure CPU work; plant_renderer.cpp uploads it.
//
// What is baked, and why: a crown drawn with its leaf cards' own normals looks like a cloud of
// confetti, and one lit as a solid looks like a blob. Like SpeedTree's "crown normals", each leaf's
// normal is bent toward the outward normal of an ellipsoid around the crown, so the crown shades
// as one volume on the sun's side and the far side, while cards keep a little of their own
// scatter; and leaves and wood deep inside the crown are darkened (a cheap ambient occlusion), so
// the crown has depth. Meshes, impostors and every level of detail share these vertices' light.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/placed_plant.hpp"
#include "core/triangle_mesh.hpp"
#include "vegetation/placement.hpp"
#include "vegetation/species.hpp"
#include "vegetation/tree_mesh.hpp"

namespace sansui::look {

/// One vertex as the plant shaders read it (24 bytes).
struct PlantVertex {
  float x = 0.0f, y = 0.0f, z = 0.0f;  ///< metres, the plant's base at the origin, y up
  /// The lit normal (bent for leaves), signed-normalised; `leaf` 127 for leaves (lit through
  /// as well as on their face), 0 for wood.
  std::int8_t normal_x = 0, normal_y = 127, normal_z = 0, leaf = 0;
  /// Linear albedo times the crown's occlusion, 0..65535 per channel; alpha unused.
  std::uint16_t red = 0, green = 0, blue = 0, alpha = 65535;
};
static_assert(sizeof(PlantVertex) == 24);

/// The space a plant takes around its base, at scale 1, with a margin of a few per cent. [Units: m]
struct PlantBounds {
  float radius = 0.0f;  ///< largest horizontal distance from the vertical axis through the base
  float bottom = 0.0f;  ///< lowest point (<= 0)
  float top = 0.0f;     ///< highest point
};

struct PlantModel {
  std::vector<PlantVertex> vertices;
  std::vector<std::uint32_t> indices;  ///< three per triangle
  PlantBounds bounds;
};

/// Packs `mesh` (positions, normals and sRGB colours, as build_tree makes them). A vertex is a
/// leaf when every triangle it belongs to is flat-shaded (its three normals equal): leaf cards
/// are, the tubes of the wood and the moss cushion are not.
PlantModel prepare_plant_model(const TriangleMesh& mesh);

/// The kinds of plant a placement uses, each with its two models (below), made once for a
/// season, snow and species library and shared by every draw of them.
struct PlantKinds {
  std::vector<std::uint32_t> keys;  ///< species * variants + variant, ascending
  std::vector<PlantModel> models;   ///< two per key: 2k the full mesh, 2k + 1 the simplified one
  std::uint32_t variants = static_cast<std::uint32_t>(vegetation::variants_per_species);
};

/// The plants a renderer draws, as plain data: the instances (world coordinates) and the kinds
/// they use. A renderer that takes this needs nothing of vegetation/.
struct PlantsToDraw {
  const std::vector<PlacedPlant>* trees = nullptr;   ///< null: no plants
  const std::vector<PlacedPlant>* ground = nullptr;  ///< the ground layer, may be null
  std::shared_ptr<const PlantKinds> kinds;
  bool empty() const { return (trees == nullptr || trees->empty()) && (ground == nullptr || ground->empty()); }
};

/// Makes the kinds of each placement, and keeps the last ones: a placement with the same kinds,
/// season, snow and library (the viewer's next edit) gets them again without building.
class PlantKindCache {
 public:
  /// `placement` must outlive the result. Throws InputError for a plant whose species or
  /// variant the library does not have.
  PlantsToDraw plants_to_draw(const vegetation::Placement& placement, const vegetation::TreeOptions& look);

 private:
  std::shared_ptr<const PlantKinds> last_;
  vegetation::TreeOptions last_look_{};
  const std::vector<vegetation::Species>* last_library_ = nullptr;
};

/// Two models per plant kind (key = species * variants_per_species + variant): the full mesh at
/// 2k and the simplified one at 2k + 1, each variant a seeded shape of its own, the same in every
/// scene. Built in parallel (build_tree is a pure function). The renderer only uploads them.
std::vector<PlantModel> build_plant_models(const std::vector<std::uint32_t>& keys, const vegetation::TreeOptions& options,
                                           const std::vector<vegetation::Species>& library);

}  // namespace sansui::look
