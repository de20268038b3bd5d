#include "scene/output_kinds.hpp"

#include <algorithm>

#include "io/file_formats.hpp"

namespace sansui::scene {

const std::vector<OutputKindInfo>& output_kinds() {
  using O = OutputKind;
  using In = OutputInput;
  static const std::vector<OutputKindInfo> kinds = [] {
    const auto heights = io::format_extensions(io::FormatData::heights, io::Access::write);
    const auto meshes = io::format_extensions(io::FormatData::mesh, io::Access::write);
    const auto png = io::extensions_of({"png8"}), geojson = io::extensions_of({"geojson"}), map = io::extensions_of({"svg", "png8"});
    const auto grid = io::extensions_of({"png8", "r32", "geotiff"});  // a splat map, or float values
    return std::vector<OutputKindInfo>{
        {O::heightmap, "heightmap", "the heightfield (16-bit PNG, raw, float or GeoTIFF)", heights, heights},
        {O::mesh, "mesh", "the heightfield as a mesh, or the mesh source's subdivided mesh", meshes, meshes, In::mesh},
        {O::render, "render", "a picture drawn with OpenGL", png, {}},
        {O::contours, "contours", "the contour lines of a contour source", geojson, {geojson.front()}, In::contour_tree},  // .json names no
                                                                                                                           // kind
        {O::map, "map", "a contour map of a contour source", map, io::extensions_of({"svg"}), In::contour_tree},
        {O::preview, "preview", "shaded relief, top down", png, {}},
        {O::volume, "volume", "a solid-texture field", io::extensions_of({"volume_r32"}), {}, In::nothing},
        {O::sphere, "sphere", "a solid texture on a sphere", png, {}, In::nothing},
        {O::cube, "cube", "a solid texture on a cube", png, {}, In::nothing},
        {O::slice, "slice", "a slice of a solid texture", png, {}, In::nothing},
        {O::comparison,
         "comparison",
         "measures of a comparison with a real DEM, printed as a table too",
         io::extensions_of({"json"}),
         {},
         In::heights,
         false,
         false,
         true},
        {O::map_real, "map_real", "a contour map of the real DEM at the compared levels", map, {}},
        {O::map_generated, "map_generated", "a contour map of the heightfield at the compared levels", map, {}},
        {O::plants, "plants", "the plant instances (position, species, scale, turn) for game engines", io::extensions_of({"csv", "json"}),
         io::extensions_of({"csv"})},
        {O::tree, "tree", "a picture or mesh of one plant ([tree])", io::extensions_of({"png8", "glb", "obj"}), {}, In::nothing},
        {O::rivers,
         "rivers",
         "river reaches with Strahler order and discharge ([flow])",
         geojson,
         {},
         In::heights,
         true,
         false,
         false,
         true},
        {O::lakes, "lakes", "lakes with their water level", geojson, {}, In::heights, true, false, false, true},
        {O::flow_map, "flow_map", "log10 of the drainage area, a splat map", grid, {}, In::heights, true},
        {O::erosion_map, "erosion_map", "metres eroded by the erode steps", grid, {}, In::heights, true, true},
        {O::deposition_map, "deposition_map", "metres deposited by the erode steps", grid, {}, In::heights, true, true},
        {O::wetness_map, "wetness_map", "topographic wetness 0..1", grid, {}, In::heights, true, false, false, true},
        {O::water_depth_map, "water_depth_map", "metres of river and lake water", grid, {}, In::heights, true, false, false, true},
        {O::splat_map, "splat_map", "RGBA weights of sand, grass, rock and snow (the land's bands), 0..255 each, summing to 255", png, {}},
    };
  }();
  return kinds;
}

const OutputKindInfo& output_kind_info(OutputKind kind) {
  const auto& kinds = output_kinds();
  return *std::find_if(kinds.begin(), kinds.end(), [kind](const OutputKindInfo& info) { return info.kind == kind; });
}

std::string inferred_kinds_text() {
  std::string text = "from the extension:";
  for (const OutputKindInfo& info : output_kinds()) {
    if (info.inferred_from.empty()) continue;
    text += text.back() == ':' ? " " : ", ";
    for (const std::string& extension : info.inferred_from) text += extension + " ";
    text += info.name;
  }
  return text;
}

}  // namespace sansui::scene
