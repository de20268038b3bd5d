// The mesh node kind: fractal subdivision of a coarse triangle mesh (seed 004) from a mesh file
// (with its vertex locks), the pyramid of Fig. 3 or a sketch of ridge and valley lines, as the
// mesh source makes it, rasterised on the world's grid. See node_kinds.hpp.
#include <array>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "mesh/edge_mesh.hpp"
#include "mesh/rasterize.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"
#include "scene/node_kinds.hpp"
#include "scene/sources.hpp"

namespace sansui::scene {

/// [[node]] kind = "mesh"
struct MeshNode {
  std::string file;                                ///< .obj .glb .gltf
  std::optional<std::array<double, 2>> pyramid_m;  ///< WIDTH,HEIGHT
  std::string sketch;                              ///< GeoJSON ridge and valley lines
  mesh::SubdivideParams subdivide;
  mesh::SketchParams sketch_params;
  std::optional<double> fill_m;
  std::optional<std::array<double, 2>> at_m;
  bool measure = true;
  bool keep_mesh = false;
  // The mesh's own grid over its footprint, in a world without one (a chain's [dem] size and cell).
  std::optional<int> grid_size;
  std::optional<double> grid_cell_m;
};
const params::Table<MeshNode>& parameter_table(const MeshNode*) {
  using P = MeshNode;
  static const auto table =
      params::Table<P>("mesh", "A fractally subdivided mesh (Yokoya et al.) rasterised on the world's grid")
          .add(params::path("file", &P::file).doc("The coarse mesh (.obj .glb .gltf), x east, y up, z south, metres"))
          .add(params::field("pyramid", &P::pyramid_m).units("m").doc("Or the pyramid of the paper's Fig. 3, WIDTH,HEIGHT"))
          .add(params::path("sketch", &P::sketch).doc("Or a sketch: GeoJSON ridge and valley lines with heights (docs/mesh.md)"))
          .nest("", "", &P::subdivide, params::table_of<mesh::SubdivideParams>())
          .nest("sketch_", "", &P::sketch_params, params::table_of<mesh::SketchParams>())
          .add(params::field("fill", &P::fill_m)
                   .in(-1e5, 1e5)
                   .units("m")
                   .unset("the mesh's lowest vertex")
                   .doc("The height around the mesh"))
          .add(params::field("at", &P::at_m)
                   .units("m")
                   .unset("the world's centre")
                   .doc("Where the centre of the mesh's footprint stands in the world, EAST,NORTH (north is 0 on the world's "
                        "northern edge and negative below it)"))
          .add(params::field("measure", &P::measure)
                   .doc("Measure the subdivided mesh's roughness (H and fractal dimension, for the sidecars and the report)"))
          .add(params::field("keep_mesh", &P::keep_mesh)
                   .doc("Only in a world without a grid of its own: carry the fine mesh, with its normals, beside the heights "
                        "(a chain recipe's mesh output writes it)"))
          .add(params::field("grid_size", &P::grid_size)
                   .in(2, 65537)
                   .unset("the world's grid; in a world without one, 1025")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] size): samples along the longer side "
                        "of the fine mesh's footprint"))
          .add(params::field("grid_cell", &P::grid_cell_m)
                   .above(0)
                   .at_most(1e7)
                   .units("m")
                   .unset("the world's grid")
                   .doc("Only in a world without a grid of its own (a chain recipe's [dem] cell): the cell over the footprint"));
  return table;
}

namespace {

void check_mesh_node(const MeshNode& p) {
  params::validate(p);
  detail::check_mesh_inputs(p.file, p.pyramid_m.has_value(), p.sketch, "file, pyramid, sketch");
  mesh::SubdivideParams subdivide = p.subdivide;
  if (!subdivide.steps && !subdivide.min_edge_m) subdivide.steps = 5;
  subdivide.validate();
  if (p.grid_size && p.grid_cell_m) fail("a mesh node takes grid_size or grid_cell, not both");
}

/// The mesh source's input from the node's keys, paths resolved in `world`.
detail::MeshInput input_of(const MeshNode& p, const GraphWorld& world) {
  return {p.file.empty() ? std::filesystem::path() : world.resolve(p.file),
          p.pyramid_m,
          p.sketch.empty() ? std::filesystem::path() : world.resolve(p.sketch),
          p.sketch_params,
          p.subdivide,
          p.measure,
          p.grid_size,
          p.grid_cell_m,
          p.fill_m};
}

/// In a world without a grid (a chain's mesh source): the mesh on its own grid, its report and,
/// with keep_mesh, the fine mesh itself, which the chain's mesh output writes.
NodeOutput run_mesh_on_own_grid(const MeshNode& p, const GraphWorld& world, const Context& context) {
  detail::Produced made = detail::mesh_on_own_grid(input_of(p, world), {.heights = true, .mesh = p.keep_mesh}, context);
  NodeOutput out(std::move(*made.heights));
  out.statistics = std::move(made.statistics);
  out.lines = std::move(made.lines);
  if (made.mesh) out.mesh = std::make_shared<const TriangleMesh>(std::move(*made.mesh));
  return out;
}

NodeOutput run_mesh(const MeshNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context& context) {
  check_mesh_node(p);
  if (!world.has_grid()) return run_mesh_on_own_grid(p, world, context);
  if (p.grid_size || p.grid_cell_m || p.keep_mesh)
    fail(
        "a mesh node on a world with a grid takes it: grid_size, grid_cell and keep_mesh are for a chain recipe's [dem] and mesh "
        "output");
  mesh::SubdivideParams subdivide = p.subdivide;
  if (!subdivide.steps && !subdivide.min_edge_m) subdivide.steps = 5;
  const detail::MeshInput input = input_of(p, world);
  const detail::CoarseMesh coarse = detail::read_coarse_mesh(input.file, input.pyramid_m, input.sketch, input.sketch_params);
  const TriangleMesh fine = mesh::subdivide_to_mesh(mesh::build_edge_mesh(coarse.mesh, coarse.locked), subdivide, false, context).mesh;
  // The footprint's centre (mesh x east, z south) goes to `at` (east, north = -south).
  const mesh::RasterFrame around = mesh::square_frame(fine, 2);
  const double centre_x = around.origin_x_m + 0.5 * around.cell_size_m, centre_z = around.origin_y_m + 0.5 * around.cell_size_m;
  const std::array<double, 2> at = p.at_m.value_or(world.centre_m());
  const mesh::RasterFrame frame{centre_x - at[0], centre_z + at[1], world.cell_m, world.width, world.height};
  const auto fill = p.fill_m ? std::optional<float>(static_cast<float>(*p.fill_m)) : std::nullopt;
  Heightfield heights = mesh::rasterize(fine, frame, fill, context);
  heights.origin_x_m = world.origin_x_m, heights.origin_y_m = world.origin_y_m;
  return heights;
}

}  // namespace

void add_mesh_kinds(std::vector<NodeKind>& kinds) {
  NodeKind kind =
      kind_of<MeshNode>("mesh", "source", "A coarse mesh, pyramid or sketch subdivided fractally (Yokoya et al.), on the world's grid", {},
                        ValueType::heights, run_mesh);
  // One of file, pyramid and sketch, and a stop rule: refused before any node runs.
  kind.validate = [](const std::any& params) { check_mesh_node(std::any_cast<const MeshNode&>(params)); };
  kinds.push_back(std::move(kind));
}

}  // namespace sansui::scene
