// The kinds of output, registered once: each kind's name, what its file holds, the extensions
// it may have, the extensions that name it when an output gives no kind, and what it needs of
// the recipe. Names and choices, extension checks and messages, kind inference, what the
// source must make, and the docs all come from this list.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/recipe.hpp"

namespace sansui::scene {

/// What an output is made from.
enum class OutputInput {
  heights,       ///< the heightfield (the source's, after its shaping steps, or a graph node's)
  mesh,          ///< the mesh source's own mesh, else the heightfield as a mesh
  contour_tree,  ///< the contour source's tree of contour lines
  nothing,       ///< its own sections only (solid textures, one plant)
};

struct OutputKindInfo {
  OutputKind kind;
  std::string_view name;                   ///< "heightmap": `kind = "heightmap"` in a scene file
  std::string_view holds;                  ///< what the file holds, for docs and help
  std::vector<std::string> extensions;     ///< the extensions its file may have (".png")
  std::vector<std::string> inferred_from;  ///< extensions that name this kind when an output gives none
  OutputInput input = OutputInput::heights;
  bool water = false;       ///< made from flow routing over the heights: the whole world's, not a tile's
  bool erode_step = false;  ///< a map of what the erode steps did: needs one
  bool printed = false;     ///< may have no file: printed only
  /// Made from the surface water (rivers, lakes, their depth, wetness), not from the routing
  /// alone: a world that writes one works the surface water out once for all of them.
  bool surface_water = false;
};

/// Every kind, in the order docs list them.
const std::vector<OutputKindInfo>& output_kinds();

/// The entry of `kind`.
const OutputKindInfo& output_kind_info(OutputKind kind);

/// "from the extension: .png .r32 ... heightmap, .obj .glb mesh, ...": what an output without a
/// kind is taken to be, for docs and messages.
std::string inferred_kinds_text();

}  // namespace sansui::scene
