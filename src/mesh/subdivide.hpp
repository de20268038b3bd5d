// Fractal subdivision of a triangle mesh, after Nishimura and Sakata, "Realistic mountain shapes
// by fractal subdivision of triangles" (Keisoku Research Consultant; seeds/004, SPEC 4), who
// follow Tsuruoka, "Fine shape of mountains, rocks and castings by fractals", PIXEL 71, 1988.
//
// One step splits every triangle into four at its edge midpoints. The midpoint of an edge moves
// along the mean of the unit normals of the two triangles sharing the edge (the one normal on
// the boundary) by d = S(n) * g, with S(n) = S(n-1) * 0.5^h and g a standard normal number.
// The paper sets S(0) = 1; we scale to the mesh: S(0) = roughness x the mean edge length of the
// input, and step n (from 1) uses S(n), so the first midpoints move by about
// roughness x mean edge x 0.5^h, like midpoint displacement of a fractional Brownian surface
// with Hurst exponent h (fractal dimension 3 - h).
//
// g is a pure function of (seed, the keys of the edge's two ends), and a vertex's key comes
// from where it was born (see EdgeMesh::keys), never from array order: both triangles of an
// edge see the same midpoint (no cracks), and the surface does not depend on the order of the
// input's triangles or vertices, nor on the number of threads.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/context.hpp"
#include "core/params.hpp"
#include "mesh/edge_mesh.hpp"

namespace sansui::mesh {

/// What the midpoints of boundary edges may do.
enum class BoundaryMode {
  free,      ///< move along the normal of their one triangle, as in the paper
  vertical,  ///< move only up or down: the outline seen from above stays as drawn
  fixed,     ///< do not move: the boundary stays exactly as drawn
};

/// Which way midpoints move.
enum class Direction {
  normal,    ///< along the mean normal of the edge's triangles, as in the paper (may overhang)
  vertical,  ///< straight up or down (a heightfield: never overhangs)
};

/// Table: mesh_params.cpp (section [subdivide]).
struct SubdivideParams {
  /// Random seed: the same seed gives the same surface, byte for byte. [Default: 1]
  std::uint64_t seed = 1;
  /// Decay exponent h of S(n) = S(n-1) * 0.5^h: larger is smoother. [Range: 0 < h <= 1] [Default: 0.8]
  double h = 0.8;
  /// S(0) as a multiple of the input's mean edge length. [Range: >= 0] [Default: 0.1]
  double roughness = 0.1;
  /// Stop once every edge is shorter than this. [Units: m] [Range: > 0] [Default: unset]
  std::optional<double> min_edge_m;
  /// Stop after this many steps. [Range: >= 0] [Default: unset; the CLI uses 5 if neither is set]
  std::optional<int> steps;
  /// What boundary midpoints may do. [Default: free]
  BoundaryMode boundary = BoundaryMode::free;
  /// Which way midpoints move. [Default: normal]
  Direction direction = Direction::normal;
  /// Refuse to make more triangles than this unless `force`. [Range: >= 1] [Default: 50000000, about 7 GB]
  std::uint64_t max_triangles = 50'000'000;
  /// Go beyond max_triangles. [Default: false]
  bool force = false;

  /// Throws InputError naming the first bad value (also when no stop rule is set).
  void validate() const;
};
const params::Table<SubdivideParams>& parameter_table(const SubdivideParams*);

/// Memory one output triangle needs while subdividing (mesh, edge table, the step's copy and
/// the plain mesh made at the end; measured: 690 MB peak for 5.2 M triangles written as .glb
/// through subdivide() and to_triangle_mesh(), 257 MB through subdivide_to_mesh()), used for the
/// limit's message: the larger, for any caller. [Units: bytes]
inline constexpr double bytes_per_triangle = 140.0;

/// The random number g of the midpoint with key `key`. [Range: about -5.3 .. 5.3]
float midpoint_gaussian(std::uint64_t seed, std::uint64_t key);

/// The settings of one step.
struct StepParams {
  std::uint64_t seed = 1;
  double scale_m = 0.0;  ///< S(n). [Units: m]
  BoundaryMode boundary = BoundaryMode::free;
  Direction direction = Direction::normal;
};

/// One step: every triangle split into four. Vertex v of `mesh` stays vertex v; the midpoint of
/// edge e becomes vertex V + e; triangle t becomes 4t .. 4t+3 (corners a, b, c first, the middle
/// one last); edge e becomes 2e (the half at e.v[0]) and 2e + 1, and triangle t adds the inner
/// edges 2E + 3t .. 2E + 3t + 2. Uses all threads; the bytes do not depend on how many.
/// Throws InputError if the result would not fit 32-bit indices.
EdgeMesh subdivide_step(const EdgeMesh& mesh, const StepParams& params);

/// Figures of the mesh after each step (index 0: the input).
struct StepStats {
  int step = 0;
  double scale_m = 0.0;  ///< S(n) used by this step (S(0) for the input). [Units: m]
  std::size_t triangles = 0, vertices = 0, edges = 0;
  double max_edge_m = 0.0;   ///< [Units: m]
  double mean_edge_m = 0.0;  ///< [Units: m]
};

struct SubdivideResult {
  EdgeMesh mesh;
  std::vector<StepStats> steps;
  std::string stopped_by;  ///< "steps" or "min-edge"
};

/// Subdivides until the stop rule of `params` holds. Throws InputError for bad parameters, and
/// (before any long work where it can be foreseen) when the result would exceed
/// params.max_triangles and params.force is not set, saying how many triangles it would make.
/// Progress and cancellation through `context`.
SubdivideResult subdivide(EdgeMesh coarse, const SubdivideParams& params, const Context& context = quiet_context());

/// A subdivided mesh in its plain form (what files and rasterising take).
struct SubdividedMesh {
  TriangleMesh mesh;
  std::vector<StepStats> steps;
  std::string stopped_by;  ///< "steps" or "min-edge"
};

/// to_triangle_mesh(subdivide(coarse, params, context).mesh, with_normals) with the same steps,
/// byte for byte, in about half the memory: when the number of steps sets the last one, that
/// step writes its positions and corners (and the vertex normals) straight into the plain mesh,
/// without the edge table, keys and flags that only a further step would read, nor a copy.
/// Throws as subdivide().
SubdividedMesh subdivide_to_mesh(EdgeMesh coarse, const SubdivideParams& params, bool with_normals,
                                 const Context& context = quiet_context());

/// S(n) for step n: s0 * 0.5^(h n), multiplied step by step as the paper writes it.
double displacement_scale(double s0_m, double h, int step);

}  // namespace sansui::mesh
