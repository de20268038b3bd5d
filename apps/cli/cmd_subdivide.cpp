// `sansui subdivide`: fractal subdivision of a triangle mesh (SPEC 4, seeds/004), from a mesh
// file, the pyramid of Fig. 3 or a sketch of ridge and valley lines, to a mesh and/or a DEM.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "io/mesh_io.hpp"
#include "io/sketch_geojson.hpp"
#include "io/vertex_locks.hpp"
#include "mesh/fractal_stats.hpp"
#include "mesh/preview.hpp"
#include "mesh/pyramid.hpp"
#include "mesh/rasterize.hpp"
#include "mesh/sketch.hpp"
#include "mesh/subdivide.hpp"

namespace sansui::cli {
namespace {

struct SubdivideOptions {
  std::string mesh_path, pyramid, sketch;
  mesh::SubdivideParams params;
  double min_edge_m = 0.0;
  int steps = 5;
  std::string fix_boundary = "free", direction = "normal";
  double sketch_refine_m = 0.0;
  std::string sketch_frame;
  std::vector<std::string> outputs, dems;
  std::string preview;
  double cell_m = 0.0;
  int dem_size = 0;
  double dem_fill_m = 0.0;
  std::string range;
  bool no_measure = false;
  // Which options were given (CLI11 fills these after parsing).
  CLI::Option *min_edge_option = nullptr, *steps_option = nullptr, *cell_option = nullptr, *dem_size_option = nullptr,
              *fill_option = nullptr;
};

/// The coarse mesh and its vertex locks, from whichever input was given.
struct Input {
  TriangleMesh mesh;
  std::vector<std::uint8_t> locked;
  nlohmann::json description;
};

Input read_input(const SubdivideOptions& o) {
  if (o.mesh_path == "vertical" || o.mesh_path == "fixed" || o.mesh_path == "free")
    fail("'{}' was read as the input mesh: write --fix-boundary={} (with '=')", o.mesh_path, o.mesh_path);
  const int given = int(!o.mesh_path.empty()) + int(!o.pyramid.empty()) + int(!o.sketch.empty());
  if (given != 1)
    fail("give exactly one input: a mesh file (.obj .glb .gltf), --pyramid WIDTH,HEIGHT or --sketch RIDGES.geojson ({} given)",
         given);
  if (!o.pyramid.empty()) {
    const auto [width, height] = parse_pair(o.pyramid, "--pyramid");
    return {mesh::make_pyramid(width, height), {}, {{"pyramid", {{"width_m", width}, {"height_m", height}}}}};
  }
  if (!o.sketch.empty()) {
    mesh::SketchParams params;
    params.max_edge_m = o.sketch_refine_m;
    if (!o.sketch_frame.empty()) {
      if (o.sketch_frame.find(',') != std::string::npos) {
        const auto [margin, height] = parse_pair(o.sketch_frame, "--sketch-frame");
        params.frame_margin_m = margin;
        params.frame_height_m = height;
      } else {
        params.frame_margin_m = parse_pair(o.sketch_frame + ",0", "--sketch-frame").first;
      }
      if (!(params.frame_margin_m > 0.0)) fail("--sketch-frame margin {} m is not allowed: it must be > 0", params.frame_margin_m);
    }
    mesh::SketchMesh sketch = mesh::triangulate_sketch(io::read_sketch_geojson(o.sketch), params);
    nlohmann::json description = {{"sketch", o.sketch}, {"sketch_refine_m", params.max_edge_m}, {"sketch_frame_margin_m", params.frame_margin_m}};
    if (params.frame_height_m) description["sketch_frame_height_m"] = *params.frame_height_m;
    return {std::move(sketch.mesh), std::move(sketch.locked), description};
  }
  if (extension_of(o.mesh_path) != ".obj" && extension_of(o.mesh_path) != ".glb" && extension_of(o.mesh_path) != ".gltf")
    fail("input mesh {} has an unknown extension '{}': allowed are .obj .glb .gltf", o.mesh_path, extension_of(o.mesh_path));
  Input input{io::read_mesh(o.mesh_path), {}, {{"mesh", o.mesh_path}}};
  const std::vector<glm::vec3> locked = io::read_locked_positions(o.mesh_path);
  if (!locked.empty()) input.locked = io::lock_flags_for(input.mesh, locked);
  return input;
}

/// Checks every output before any work: known extension, writable directory.
void check_outputs(const SubdivideOptions& o) {
  if (o.outputs.empty() && o.dems.empty() && o.preview.empty())
    fail("no output: give -o MESH.obj|.glb, --dem HEIGHTMAP.png|.raw|.r32|.tif and/or --preview PICTURE.png");
  if (!o.preview.empty()) {
    if (extension_of(o.preview) != ".png")
      fail("preview {} has an unknown extension '{}': allowed is .png", o.preview, extension_of(o.preview));
    io::check_writable(o.preview);
  }
  for (const auto& output : o.outputs) {
    if (!io::mesh_format_for(output))
      fail("mesh output {} has an unknown extension '{}': allowed are .obj .glb", output, extension_of(output));
    io::check_writable(output);
  }
  for (const auto& dem : o.dems) {
    if (!io::heightmap_format_for(dem))
      fail("DEM output {} has an unknown extension '{}': allowed are .png .raw .r32 .tif .tiff", dem, extension_of(dem));
    io::check_writable(dem);
  }
  if (o.cell_option->count() > 0 && o.dem_size_option->count() > 0) fail("give --cell or --dem-size, not both");
  if (o.cell_option->count() > 0 && !(o.cell_m > 0.0 && std::isfinite(o.cell_m)))
    fail("--cell {} m is not allowed: it must be > 0", o.cell_m);
  if (o.dem_size_option->count() > 0 && (o.dem_size < 2 || o.dem_size > mesh::max_raster_side))
    fail("--dem-size {} is not allowed: it must be 2..{}", o.dem_size, mesh::max_raster_side);
  if (o.fill_option->count() > 0 && !std::isfinite(o.dem_fill_m)) fail("--dem-fill {} m is not a finite number", o.dem_fill_m);
}

mesh::BoundaryMode boundary_from(const std::string& name) {
  if (name == "free") return mesh::BoundaryMode::free;
  if (name == "vertical") return mesh::BoundaryMode::vertical;
  if (name == "fixed") return mesh::BoundaryMode::fixed;
  fail("--fix-boundary '{}' is not allowed: use --fix-boundary (fixed), --fix-boundary=vertical or --fix-boundary=fixed", name);
}

mesh::Direction direction_from(const std::string& name) {
  if (name == "normal") return mesh::Direction::normal;
  if (name == "vertical") return mesh::Direction::vertical;
  fail("--direction '{}' is not allowed: use normal or vertical", name);
}

nlohmann::json step_table(const mesh::SubdivideResult& result) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : result.steps)
    steps.push_back({{"step", s.step}, {"scale_m", s.scale_m}, {"triangles", s.triangles}, {"vertices", s.vertices},
                     {"max_edge_m", s.max_edge_m}, {"mean_edge_m", s.mean_edge_m}});
  return steps;
}

void print_report(const mesh::SubdivideResult& result, const mesh::SubdivideParams& p, std::size_t locked,
                  const std::optional<mesh::FractalMeasurement>& measured, bool measure_wanted) {
  fmt::print("step  S(n) m        triangles   longest edge m   mean edge m\n");
  for (const auto& s : result.steps)
    fmt::print("{:>4}  {:>10.4g}  {:>12}  {:>15.4g}  {:>12.4g}\n", s.step, s.scale_m, s.triangles, s.max_edge_m, s.mean_edge_m);
  fmt::print("stopped by {}", result.stopped_by);
  if (locked > 0) fmt::print("; {} locked vertices", locked);
  fmt::print("\n");
  if (!measure_wanted) return;
  if (!measured) {
    fmt::print("roughness: not measured (needs 7 or more steps for a variogram over 3 octaves)\n");
    return;
  }
  fmt::print("roughness: asked h {:.3f} (fractal dimension {:.3f}); measured H {:.3f} (dimension {:.3f}, profile "
             "spectral slope {:.2f}) from the height variogram over {:.3g}-{:.3g} m, r^2 {:.3f}\n",
             p.h, 3.0 - p.h, measured->measured_h, measured->measured_dimension(), measured->implied_spectral_slope(),
             measured->min_lag * measured->cell_size_m, measured->max_lag * measured->cell_size_m, measured->r_squared);
}

void run_subdivide(SubdivideOptions o) {
  // Parameters and outputs first: bad input fails before any work.
  if (o.min_edge_option->count() > 0) o.params.min_edge_m = o.min_edge_m;
  if (o.steps_option->count() > 0 || o.min_edge_option->count() == 0) o.params.steps = o.steps;
  o.params.boundary = boundary_from(o.fix_boundary);
  o.params.direction = direction_from(o.direction);
  o.params.validate();
  check_outputs(o);
  std::optional<io::HeightRange> range;
  if (!o.range.empty()) {
    const auto [low, high] = parse_pair(o.range, "--range");
    if (!(low < high)) fail("--range {} is not allowed: MIN must be below MAX", o.range);
    range = io::HeightRange{low, high};
  }

  Input input = read_input(o);
  mesh::BuildReport built;
  mesh::EdgeMesh coarse = mesh::build_edge_mesh(input.mesh, input.locked, &built);
  std::size_t locked = 0;
  for (std::uint8_t flag : coarse.flags) locked += (flag & mesh::vertex_locked) != 0;

  mesh::SubdivideResult result;
  TriangleMesh fine;
  {
    ProgressBar progress;
    result = mesh::subdivide(coarse, o.params, progress.context());
    fine = mesh::to_triangle_mesh(result.mesh, !o.outputs.empty());
  }
  const int steps_done = int(result.steps.size()) - 1;
  const bool measure_wanted = !o.no_measure && steps_done > 0;
  std::optional<mesh::FractalMeasurement> measured;
  if (measure_wanted)
    measured = mesh::measure_fractal(input.mesh, fine, result.steps[0].mean_edge_m, steps_done, /*max_side=*/1025);
  print_report(result, o.params, locked, measured, measure_wanted);

  nlohmann::json provenance = run_provenance("subdivide");
  nlohmann::json parameters = {{"input", input.description},
                               {"seed", o.params.seed},
                               {"h", o.params.h},
                               {"roughness", o.params.roughness},
                               {"s0_m", result.steps[0].scale_m},
                               {"boundary", o.fix_boundary},
                               {"direction", o.direction},
                               {"max_triangles", o.params.max_triangles},
                               {"force", o.params.force},
                               {"locked_vertices", locked},
                               {"welded_vertices", built.welded_vertices},
                               {"flipped_triangles", built.flipped_triangles}};
  if (o.params.min_edge_m) parameters["min_edge_m"] = *o.params.min_edge_m;
  if (o.params.steps) parameters["steps"] = *o.params.steps;
  provenance["parameters"] = parameters;
  provenance["statistics"] = {{"steps", step_table(result)}, {"stopped_by", result.stopped_by}};
  if (measured)
    provenance["statistics"]["roughness"] = {{"asked_h", o.params.h},
                                             {"measured_h", measured->measured_h},
                                             {"measured_fractal_dimension", measured->measured_dimension()},
                                             {"r_squared", measured->r_squared},
                                             {"lags_m", {measured->min_lag * measured->cell_size_m, measured->max_lag * measured->cell_size_m}}};

  for (const auto& output : o.outputs) io::write_mesh(output, fine, {provenance, true});
  if (!o.dems.empty() || !o.preview.empty()) {
    const mesh::RasterFrame frame = o.cell_option->count() > 0 ? mesh::frame_with_cell(fine, o.cell_m)
                                                                 : mesh::square_frame(fine, o.dem_size > 0 ? o.dem_size : 1025);
    Heightfield dem;
    {
      ProgressBar progress;
      const auto fill = o.fill_option->count() > 0 ? std::optional<float>(float(o.dem_fill_m)) : std::nullopt;
      dem = mesh::rasterize(fine, frame, fill, progress.context());
    }
    provenance["parameters"]["dem"] = {{"cell_size_m", frame.cell_size_m}, {"width", frame.width}, {"height", frame.height}};
    for (const auto& path : o.dems) io::write_heightmap(path, dem, {range, provenance, true});
    if (!o.preview.empty()) io::write_png(o.preview, mesh::shaded_relief(dem));
  }
}

}  // namespace

void add_subdivide_command(CLI::App& app) {
  auto options = std::make_shared<SubdivideOptions>();
  SubdivideOptions& o = *options;
  CLI::App* command = app.add_subcommand(
      "subdivide", "Fractal subdivision of a triangle mesh (Nishimura & Sakata): a coarse mountain to a detailed one and a DEM.");
  command->add_option("mesh", o.mesh_path, "Coarse mesh: .obj (red vertex colours lock vertices) or .glb/.gltf (attribute _LOCK).");
  command->add_option("--pyramid", o.pyramid, "Start from the quadrangular pyramid of Fig. 3: base width and apex height, WIDTH,HEIGHT. [Units: m]");
  command->add_option("--sketch", o.sketch, "Start from a GeoJSON sketch: ridge/valley LineStrings and spot-height Points with heights (3rd coordinate or \"height\").");
  command->add_option("--sketch-refine", o.sketch_refine_m, "Refine the sketch's triangulation until no edge is longer than this. [Units: m] [Default: 0 = no refinement]");
  command->add_option("--sketch-frame", o.sketch_frame, "Add a rectangular frame this far around the sketch, MARGIN[,HEIGHT]. [Units: m] [Default: none; height: the lowest drawn]");
  command->add_option("--h", o.params.h, "Decay exponent h: S(n) = S(n-1) * 0.5^h; larger is smoother (fractal dimension 3 - h). [Range: 0 < h <= 1] [Default: 0.8]");
  command->add_option("--roughness", o.params.roughness, "S(0) as a multiple of the input's mean edge length. [Range: >= 0] [Default: 0.1]");
  o.min_edge_option = command->add_option("--min-edge", o.min_edge_m, "Stop once every edge is shorter than this. [Units: m] [Range: > 0]");
  o.steps_option = command->add_option("--steps", o.steps, "Stop after this many steps (with --min-edge: whichever comes first). [Range: >= 0] [Default: 5]");
  command->add_option("--seed", o.params.seed, "Random seed: the same seed gives the same surface, byte for byte. [Default: 1]");
  command->add_flag("--fix-boundary{fixed}", o.fix_boundary, "Keep the boundary as drawn: --fix-boundary (fixed) or --fix-boundary=vertical (moves only up and down). [Default: free]");
  command->add_option("--direction", o.direction, "Which way midpoints move: normal (the paper; may overhang) or vertical (a heightfield). [Default: normal]");
  command->add_option("--max-triangles", o.params.max_triangles, "Refuse to make more triangles than this unless --force. [Default: 50000000, about 7 GB]");
  command->add_flag("--force", o.params.force, "Subdivide beyond --max-triangles.");
  command->add_option("-o,--out", o.outputs, "Mesh output, repeatable: .obj or .glb (with a JSON sidecar).");
  command->add_option("--dem", o.dems, "DEM output, repeatable: .png (16-bit) .raw (16-bit LE) .r32 (float32) .tif (GeoTIFF); highest surface wins.");
  command->add_option("--preview", o.preview, "Top-down shaded relief of the DEM (.png, north up), for a quick look; sansui render draws the full picture.");
  o.cell_option = command->add_option("--cell", o.cell_m, "DEM sample spacing over the mesh's footprint. [Units: m] [Range: > 0]");
  o.dem_size_option = command->add_option("--dem-size", o.dem_size, "DEM of N x N samples over the footprint's longer side (e.g. 1025, 4097 for Unity). [Default: 1025]");
  o.fill_option = command->add_option("--dem-fill", o.dem_fill_m, "Height of DEM samples no triangle covers. [Units: m] [Default: the lowest vertex]");
  command->add_option("--range", o.range, "Metres mapped to 0 and 65535 in 16-bit DEMs, as MIN,MAX. [Units: m] [Default: the data's range]");
  command->add_flag("--no-measure", o.no_measure, "Skip measuring the fractal dimension of the result.");
  command->callback([options] { run_subdivide(*options); });
}

}  // namespace sansui::cli
