// Fractal subdivision of triangle meshes (Nishimura, Sakata; seeds/004; see subdivide.hpp).
//
// A step is three parallel passes over plain arrays, each element written by exactly one
// iteration: unit normals of the triangles, then one midpoint per edge (with its key and the
// two halves of the edge), then four triangles and three inner edges per triangle, which also
// fill in which triangles border each new edge. No hashing of edges, no locks, no atomics.
#include "mesh/subdivide.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.hpp"
#include "core/exact_math.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"

namespace sansui::mesh {
namespace {

/// The random stream of mesh midpoints ("MESHMIDP").
constexpr std::uint64_t midpoint_stream = 0x4D4553484D494450ull;

constexpr std::uint64_t index_limit = std::numeric_limits<std::uint32_t>::max();

template <class Body>
void parallel(std::size_t count, Body&& body) {
  parallel_for_ranges<std::size_t>(0, count, 4096, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t i = range_begin; i < range_end; ++i) body(i);
  });
}

Buffer<glm::vec3> unit_normals(const EdgeMesh& mesh) {
  Buffer<glm::vec3> normals(mesh.triangle_count());
  parallel(mesh.triangle_count(), [&](std::size_t t) {
    const auto& c = mesh.triangles[t];
    const glm::vec3 a = mesh.positions[c[0]];
    const glm::vec3 n = glm::cross(mesh.positions[c[1]] - a, mesh.positions[c[2]] - a);
    const float length = glm::length(n);
    normals[t] = length > 0.0f ? n / length : glm::vec3(0.0f);
  });
  return normals;
}

/// The unit direction the midpoint of `edge` moves in (zero: it does not move).
glm::vec3 direction_of(const Edge& edge, bool locked, const Buffer<glm::vec3>& normals, const StepParams& p) {
  constexpr glm::vec3 up(0.0f, 1.0f, 0.0f);
  if (locked) return glm::vec3(0.0f);
  if (edge.on_boundary()) {
    if (p.boundary == BoundaryMode::fixed) return glm::vec3(0.0f);
    if (p.boundary == BoundaryMode::vertical || p.direction == Direction::vertical) return up;
    return normals[edge.t[0]];
  }
  if (p.direction == Direction::vertical) return up;
  const glm::vec3 sum = normals[edge.t[0]] + normals[edge.t[1]];
  const float length = glm::length(sum);
  // Two triangles folded flat onto each other have no mean normal: leave the midpoint be.
  return length > 1e-6f ? sum / length : glm::vec3(0.0f);
}

/// How many steps at least, and how many triangles then, before every edge is below min_edge:
/// a midpoint never comes closer to an end than half the edge, so edges at most halve per step.
std::pair<int, double> lower_bound_for_min_edge(const EdgeMesh& mesh, double longest, double min_edge) {
  int steps = 0;
  while (longest >= min_edge && steps < 64) longest *= 0.5, ++steps;
  return {steps, double(mesh.triangle_count()) * std::pow(4.0, steps)};
}

std::string memory_text(double triangles) {
  const double bytes = triangles * bytes_per_triangle;
  return bytes < 1e9 ? fmt::format("{:.0f} MB", bytes / 1e6) : fmt::format("{:.1f} GB", bytes / 1e9);
}

/// The memory a step to `triangles` holds at its peak: the mesh it makes and the one it reads.
double step_bytes(double triangles) {
  return 1.25 * triangles * bytes_per_triangle;
}

}  // namespace

float midpoint_gaussian(std::uint64_t seed, std::uint64_t key) {
  return rng::to_gaussian(rng::bits(rng::stream_key(seed, midpoint_stream), key));
}

double displacement_scale(double s0_m, double h, int step) {
  const double factor = exact_exp2(-h);  // 0.5^h, the same bytes everywhere
  double s = s0_m;
  for (int n = 1; n <= step; ++n) s *= factor;
  return s;
}

EdgeMesh subdivide_step(const EdgeMesh& mesh, const StepParams& p) {
  const std::size_t V = mesh.vertex_count(), E = mesh.edge_count(), T = mesh.triangle_count();
  if (V + E > index_limit || 2 * E + 3 * T > index_limit || 4 * T > index_limit)
    fail("a step would make {} triangles, more than 32-bit indices can number", 4 * T);
  const auto v_base = static_cast<std::uint32_t>(V);
  const auto e_inner = static_cast<std::uint32_t>(2 * E);

  EdgeMesh out;
  out.positions.resize(V + E);
  out.keys.resize(V + E);
  out.flags.resize(V + E);
  out.triangles.resize(4 * T);
  out.triangle_edges.resize(4 * T);
  out.edges.resize(2 * E + 3 * T);
  std::copy(mesh.positions.begin(), mesh.positions.end(), out.positions.begin());
  std::copy(mesh.keys.begin(), mesh.keys.end(), out.keys.begin());
  std::copy(mesh.flags.begin(), mesh.flags.end(), out.flags.begin());

  // Midpoints: one per edge, displaced along the edge's direction by S(n) * g.
  const Buffer<glm::vec3> normals = unit_normals(mesh);
  const std::uint64_t stream = rng::stream_key(p.seed, midpoint_stream);
  const auto scale = static_cast<float>(p.scale_m);
  parallel(E, [&](std::size_t e) {
    const Edge& edge = mesh.edges[e];
    const std::uint32_t a = edge.v[0], b = edge.v[1], m = v_base + static_cast<std::uint32_t>(e);
    const bool locked = mesh.locked(a) && mesh.locked(b);
    const std::uint64_t key = midpoint_key(mesh.keys[a], mesh.keys[b]);
    const float g = rng::to_gaussian(rng::bits(stream, key));
    const glm::vec3 middle = (mesh.positions[a] + mesh.positions[b]) * 0.5f;
    out.positions[m] = middle + direction_of(edge, locked, normals, p) * (scale * g);
    out.keys[m] = key;
    out.flags[m] = locked ? std::uint8_t{vertex_locked} : std::uint8_t{0};
    // The halves keep the edge's direction, so each triangle walks them as it walked the edge.
    out.edges[2 * e] = {{a, m}, {no_triangle, no_triangle}};
    out.edges[2 * e + 1] = {{m, b}, {no_triangle, no_triangle}};
  });

  // Four triangles per triangle. Corners a, b, c; midpoints ab, bc, ca; inner edges
  // i0 = ab->ca, i1 = bc->ab, i2 = ca->bc, which the middle triangle walks backwards.
  parallel(T, [&](std::size_t t) {
    const auto& c = mesh.triangles[t];
    const auto& te = mesh.triangle_edges[t];
    std::array<std::uint32_t, 3> mid, side;
    for (int i = 0; i < 3; ++i) {
      mid[i] = v_base + te[i];
      side[i] = mesh.edges[te[i]].v[0] == c[i] ? 0u : 1u;  // which side of edge i triangle t is
    }
    // The half of edge i at corner `corner`.
    auto half = [&](int i, std::uint32_t corner) { return 2 * te[i] + (mesh.edges[te[i]].v[0] == corner ? 0u : 1u); };
    const auto first = static_cast<std::uint32_t>(4 * t);
    const std::uint32_t inner = e_inner + static_cast<std::uint32_t>(3 * t);
    const std::uint32_t ab = mid[0], bc = mid[1], ca = mid[2];

    out.triangles[first + 0] = {c[0], ab, ca};
    out.triangles[first + 1] = {ab, c[1], bc};
    out.triangles[first + 2] = {ca, bc, c[2]};
    out.triangles[first + 3] = {ab, bc, ca};
    const std::uint32_t h0a = half(0, c[0]), h0b = half(0, c[1]);
    const std::uint32_t h1b = half(1, c[1]), h1c = half(1, c[2]);
    const std::uint32_t h2c = half(2, c[2]), h2a = half(2, c[0]);
    out.triangle_edges[first + 0] = {h0a, inner + 0, h2a};
    out.triangle_edges[first + 1] = {h0b, h1b, inner + 1};
    out.triangle_edges[first + 2] = {inner + 2, h1c, h2c};
    out.triangle_edges[first + 3] = {inner + 1, inner + 2, inner + 0};

    out.edges[inner + 0] = {{ab, ca}, {first + 0, first + 3}};
    out.edges[inner + 1] = {{bc, ab}, {first + 1, first + 3}};
    out.edges[inner + 2] = {{ca, bc}, {first + 2, first + 3}};
    out.edges[h0a].t[side[0]] = first + 0;
    out.edges[h0b].t[side[0]] = first + 1;
    out.edges[h1b].t[side[1]] = first + 1;
    out.edges[h1c].t[side[1]] = first + 2;
    out.edges[h2c].t[side[2]] = first + 2;
    out.edges[h2a].t[side[2]] = first + 0;
  });
  return out;
}

SubdivideResult subdivide(EdgeMesh coarse, const SubdivideParams& params, const Context& context) {
  params.validate();
  SubdivideResult result;
  const EdgeLengths initial = edge_lengths(coarse);
  double scale = params.roughness * initial.mean_m;
  double longest = initial.longest_m;
  result.steps.push_back({0, scale, coarse.triangle_count(), coarse.vertex_count(), coarse.edge_count(), longest, initial.mean_m});

  // Refuse early what can be foreseen: the exact count for a number of steps, a lower bound
  // for a minimum edge length.
  const double limit = double(params.max_triangles);
  if (params.steps) {
    const double triangles = double(coarse.triangle_count()) * std::pow(4.0, *params.steps);
    if (triangles > limit && !params.force)
      fail("{} steps would make {:.0f} triangles (about {}), over the limit of {}: give fewer steps, or force it", *params.steps, triangles,
           memory_text(triangles), params.max_triangles);
    check_memory(step_bytes(triangles), fmt::format("subdivision to {} steps ({:.0f} triangles)", *params.steps, triangles));
  }
  if (params.min_edge_m) {
    const auto [steps, triangles] = lower_bound_for_min_edge(coarse, longest, *params.min_edge_m);
    const bool steps_stop_first = params.steps && *params.steps < steps;
    if (triangles > limit && !params.force && !steps_stop_first)
      fail(
          "min-edge {} m would need at least {} steps and {:.0f} triangles (about {}), over the limit of {}: give a "
          "larger min-edge, or force it",
          *params.min_edge_m, steps, triangles, memory_text(triangles), params.max_triangles);
  }

  const double factor = exact_exp2(-params.h);  // S(n) = S(n-1) * 0.5^h
  const int planned = params.steps.value_or(-1);
  result.mesh = std::move(coarse);
  for (int n = 1;; ++n) {
    if (params.steps && n > *params.steps) {
      result.stopped_by = "steps";
      break;
    }
    if (params.min_edge_m && longest < *params.min_edge_m) {
      result.stopped_by = "min-edge";
      break;
    }
    const double next = 4.0 * double(result.mesh.triangle_count());
    if (next > limit && !params.force)
      fail(
          "after {} steps the longest edge is still {:.3g} m (min-edge {} m); step {} would make {:.0f} triangles "
          "(about {}), over the limit of {}: give a larger min-edge, or force it",
          n - 1, longest, params.min_edge_m.value_or(0.0), n, next, memory_text(next), params.max_triangles);
    check_memory(step_bytes(next), fmt::format("subdivision step {} ({:.0f} triangles)", n, next));  // min-edge runs, forced runs
    context.check_cancelled();
    scale *= factor;
    result.mesh = subdivide_step(result.mesh, {params.seed, scale, params.boundary, params.direction});
    const EdgeLengths lengths = edge_lengths(result.mesh);
    longest = lengths.longest_m;
    const EdgeMesh& m = result.mesh;
    result.steps.push_back({n, scale, m.triangle_count(), m.vertex_count(), m.edge_count(), longest, lengths.mean_m});
    if (planned > 0) context.report("subdivide", double(n) / planned);
  }
  return result;
}

}  // namespace sansui::mesh
