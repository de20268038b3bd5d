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
                        "northern edge and negative below it)"));
  return table;
}

namespace {

void check_mesh_node(const MeshNode& p) {
  params::validate(p);
  detail::check_mesh_inputs(p.file, p.pyramid_m.has_value(), p.sketch, "file, pyramid, sketch");
  mesh::SubdivideParams subdivide = p.subdivide;
  if (!subdivide.steps && !subdivide.min_edge_m) subdivide.steps = 5;
  subdivide.validate();
}

Heightfield run_mesh(const MeshNode& p, std::span<const Grid<float>* const>, const GraphWorld& world, const Context& context) {
  check_mesh_node(p);
  if (!world.has_grid()) fail("a mesh node makes its heights on the world's grid: give [world] size");
  mesh::SubdivideParams subdivide = p.subdivide;
  if (!subdivide.steps && !subdivide.min_edge_m) subdivide.steps = 5;
  const detail::CoarseMesh coarse =
      detail::read_coarse_mesh(p.file.empty() ? std::filesystem::path() : world.resolve(p.file), p.pyramid_m,
                               p.sketch.empty() ? std::filesystem::path() : world.resolve(p.sketch), p.sketch_params);
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
