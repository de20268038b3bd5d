// The sources, registered once: name, checks, run and example (sources.hpp). Choices, names,
// the pipeline's dispatch and `--print-defaults` come from this list.
#include <algorithm>
#include <array>

#include "core/error.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {

const std::vector<SourceEntry>& source_entries() {
  using O = OutputKind;
  auto add_output = [](Recipe& recipe, std::string file, OutputKind kind) { recipe.outputs.push_back({std::move(file), kind, {}, {}}); };
  static const std::vector<SourceEntry> entries{
      {SourceKind::none, "none", [](const Recipe&) {}, [](Recipe&, const Needs&, const RunOptions&, const Context&) { return Produced{}; },
       [=](Recipe& r) {
         add_output(r, "sphere.png", O::sphere);
         add_output(r, "slice.png", O::slice);
       },
       "outputs are examples"},
      {SourceKind::midpoint, "midpoint", check_midpoint_source,
       [](Recipe& r, const Needs&, const RunOptions& options, const Context& context) { return run_midpoint_source(r, options, context); },
       [=](Recipe& r) {
         r.shape.emplace_back();
         add_output(r, "heightmap.png", O::heightmap);
         add_output(r, "render.png", O::render);
       },
       "outputs are examples"},
      {SourceKind::file, "file",
       [](const Recipe& r) {
         if (r.file.path.empty()) fail("file.path is missing: the heightmap to read");
       },
       [](Recipe& r, const Needs&, const RunOptions&, const Context& context) { return run_file_source(r, context); },
       [=](Recipe& r) {
         r.file.path = "heightmap.png";
         add_output(r, "render.png", O::render);
       },
       "file.path names an example input: replace it"},
      {SourceKind::contour, "contour", check_contour_source, run_contour_source,
       [=](Recipe& r) {
         r.contour_seed.file = "seed.geojson";
         add_output(r, "contours.geojson", O::contours);
         add_output(r, "map.svg", O::map);
         add_output(r, "dem.png", O::heightmap);
         add_output(r, "render.png", O::render);
       },
       "contour_seed.file names an example input: replace it"},
      {SourceKind::mesh, "mesh", check_mesh_source,
       [](Recipe& r, const Needs& needs, const RunOptions&, const Context& context) { return run_mesh_source(r, needs, context); },
       [=](Recipe& r) {
         r.mesh.pyramid_m = std::array<double, 2>{1000.0, 600.0};
         add_output(r, "mesh.glb", O::mesh);
         add_output(r, "dem.png", O::heightmap);
         add_output(r, "render.png", O::render);
       },
       "mesh.pyramid is an example input"},
      {SourceKind::contour_map, "contour_map", check_contour_map_source,
       [](Recipe& r, const Needs&, const RunOptions&, const Context& context) { return run_contour_map_source(r, context); },
       [=](Recipe& r) {
         r.contour_map.file = "contours.geojson";
         add_output(r, "dem.tif", O::heightmap);
       },
       "contour_map.file names an example input: replace it"},
  };
  return entries;
}

const SourceEntry& source_entry(SourceKind kind) {
  const auto& entries = source_entries();
  return *std::find_if(entries.begin(), entries.end(), [kind](const SourceEntry& entry) { return entry.kind == kind; });
}

}  // namespace sansui::scene::detail
