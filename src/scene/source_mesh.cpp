// The mesh source: fractal subdivision of a coarse triangle mesh (SPEC 4, seeds/004) from a mesh
// file (with vertex locks), the pyramid of Fig. 3, or a sketch of ridge and valley lines; the
// fine mesh is rasterised into the heightfield when an output needs one.
#include <fmt/format.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/extension.hpp"
#include "io/mesh_io.hpp"
#include "io/sketch_geojson.hpp"
#include "io/vertex_locks.hpp"
#include "mesh/edge_mesh.hpp"
#include "mesh/fractal_stats.hpp"
#include "mesh/pyramid.hpp"
#include "mesh/rasterize.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {
namespace {

nlohmann::json step_table(const mesh::SubdividedMesh& result) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : result.steps)
    steps.push_back({{"step", s.step},
                     {"scale_m", s.scale_m},
                     {"triangles", s.triangles},
                     {"vertices", s.vertices},
                     {"max_edge_m", s.max_edge_m},
                     {"mean_edge_m", s.mean_edge_m}});
  return steps;
}

void report(Produced& produced, const mesh::SubdividedMesh& result, const mesh::SubdivideParams& p, std::size_t locked,
            const std::optional<mesh::FractalMeasurement>& measured, bool measure_wanted) {
  auto& lines = produced.lines;
  lines.push_back("step  S(n) m        triangles   longest edge m   mean edge m");
  for (const auto& s : result.steps)
    lines.push_back(
        fmt::format("{:>4}  {:>10.4g}  {:>12}  {:>15.4g}  {:>12.4g}", s.step, s.scale_m, s.triangles, s.max_edge_m, s.mean_edge_m));
  lines.push_back(fmt::format("stopped by {}{}", result.stopped_by, locked > 0 ? fmt::format("; {} locked vertices", locked) : ""));
  if (!measure_wanted) return;
  if (!measured) {
    lines.push_back("roughness: not measured (needs 7 or more steps for a variogram over 3 octaves)");
    return;
  }
  lines.push_back(
      fmt::format("roughness: asked h {:.3f} (fractal dimension {:.3f}); measured H {:.3f} (dimension {:.3f}, profile "
                  "spectral slope {:.2f}) from the height variogram over {:.3g}-{:.3g} m, r^2 {:.3f}",
                  p.h, 3.0 - p.h, measured->measured_h, measured->measured_dimension(), measured->implied_spectral_slope(),
                  measured->min_lag * measured->cell_size_m, measured->max_lag * measured->cell_size_m, measured->r_squared));
}

}  // namespace

void check_mesh_inputs(const std::string& file, bool pyramid, const std::string& sketch, std::string_view names) {
  const int given = int(!file.empty()) + int(pyramid) + int(!sketch.empty());
  if (given != 1)
    fail("give exactly one input: a mesh file (.obj .glb .gltf), a pyramid WIDTH,HEIGHT or a sketch ({}; {} given)", names, given);
  const std::string extension = io::lower_extension(file);
  if (!file.empty() && extension != ".obj" && extension != ".glb" && extension != ".gltf")
    fail("input mesh {} has an unknown extension '{}': allowed are .obj .glb .gltf", file, extension);
}

CoarseMesh read_coarse_mesh(const std::filesystem::path& file, const std::optional<std::array<double, 2>>& pyramid_m,
                            const std::filesystem::path& sketch, const mesh::SketchParams& sketch_params) {
  if (pyramid_m) return {mesh::make_pyramid((*pyramid_m)[0], (*pyramid_m)[1]), {}};
  if (!sketch.empty()) {
    mesh::SketchMesh made = mesh::triangulate_sketch(io::read_sketch_geojson(sketch), sketch_params);
    return {std::move(made.mesh), std::move(made.locked)};
  }
  CoarseMesh coarse{io::read_mesh(file), {}};
  const std::vector<glm::vec3> locked = io::read_locked_positions(file);
  if (!locked.empty()) coarse.locked = io::lock_flags_for(coarse.mesh, locked);
  return coarse;
}

void check_mesh_source(const Recipe& recipe) {
  const MeshSourceParams& m = recipe.mesh;
  check_mesh_inputs(m.file, m.pyramid_m.has_value(), m.sketch, "mesh.file, mesh.pyramid, mesh.sketch");
  mesh::SubdivideParams params = recipe.subdivide;
  if (!params.steps && !params.min_edge_m) params.steps = 5;
  params.validate();
  params::validate(recipe.sketch);
  if (recipe.dem.size && recipe.dem.cell_m) fail("give dem.size or dem.cell, not both");
  // Before the subdivision, not after it (a 65537 x 65537 DEM, 17 GB, ran out of memory after
  // half a minute). A DEM by cell size has an extent known only then: the grid's own check.
  if (const auto size = recipe.dem.size)
    check_memory(4.0 * double(*size) * double(*size), fmt::format("dem.size {} (a {} x {} DEM)", *size, *size, *size));
}

MeshInput mesh_input(const Recipe& recipe) {
  const MeshSourceParams& m = recipe.mesh;
  return {m.file.empty() ? std::filesystem::path() : resolve(recipe, m.file),
          m.pyramid_m,
          m.sketch.empty() ? std::filesystem::path() : resolve(recipe, m.sketch),
          recipe.sketch,
          recipe.subdivide,
          m.measure,
          recipe.dem.size,
          recipe.dem.cell_m,
          recipe.dem.fill_m};
}

void resolve_mesh_recipe(Recipe& recipe) {
  if (!recipe.subdivide.steps && !recipe.subdivide.min_edge_m) recipe.subdivide.steps = 5;
}

Produced run_mesh_source(Recipe& recipe, const Needs& needs, const Context& context) {
  resolve_mesh_recipe(recipe);
  return mesh_on_own_grid(mesh_input(recipe), needs, context);
}

Produced mesh_on_own_grid(const MeshInput& given, const Needs& needs, const Context& context) {
  MeshInput m = given;
  if (!m.subdivide.steps && !m.subdivide.min_edge_m) m.subdivide.steps = 5;
  const CoarseMesh input = read_coarse_mesh(m.file, m.pyramid_m, m.sketch, m.sketch_params);
  mesh::BuildReport built;
  mesh::EdgeMesh coarse = mesh::build_edge_mesh(input.mesh, input.locked, &built);
  std::size_t locked = 0;
  for (std::uint8_t flag : coarse.flags) locked += (flag & mesh::vertex_locked) != 0;

  mesh::SubdividedMesh result = mesh::subdivide_to_mesh(std::move(coarse), m.subdivide, needs.mesh, context);
  TriangleMesh& fine = result.mesh;
  const int steps_done = int(result.steps.size()) - 1;
  const bool measure_wanted = m.measure && steps_done > 0;
  std::optional<mesh::FractalMeasurement> measured;
  if (measure_wanted) measured = mesh::measure_fractal(input.mesh, fine, result.steps[0].mean_edge_m, steps_done, /*max_side=*/1025);

  Produced produced;
  report(produced, result, m.subdivide, locked, measured, measure_wanted);
  produced.statistics = {
      {"steps", step_table(result)}, {"stopped_by", result.stopped_by},          {"s0_m", result.steps[0].scale_m},
      {"locked_vertices", locked},   {"welded_vertices", built.welded_vertices}, {"flipped_triangles", built.flipped_triangles}};
  if (measured)
    produced.statistics["roughness"] = {{"asked_h", m.subdivide.h},
                                        {"measured_h", measured->measured_h},
                                        {"measured_fractal_dimension", measured->measured_dimension()},
                                        {"r_squared", measured->r_squared},
                                        {"lags_m", {measured->min_lag * measured->cell_size_m, measured->max_lag * measured->cell_size_m}}};
  if (needs.heights) {
    const mesh::RasterFrame frame = m.cell_m ? mesh::frame_with_cell(fine, *m.cell_m) : mesh::square_frame(fine, m.size.value_or(1025));
    const auto fill = m.fill_m ? std::optional<float>(static_cast<float>(*m.fill_m)) : std::nullopt;
    produced.heights = mesh::rasterize(fine, frame, fill, context);
  }
  if (needs.mesh) produced.mesh = std::move(fine);
  return produced;
}

}  // namespace sansui::scene::detail
