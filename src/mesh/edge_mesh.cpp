// Building the edge form of a triangle mesh (see edge_mesh.hpp): validate, weld, put into a
// canonical order, orient, and make the edge table.
#include "mesh/edge_mesh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <tuple>

#include <glm/geometric.hpp>

#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"

namespace sansui::mesh {
namespace {

using Corners = std::array<std::uint32_t, 3>;
constexpr std::uint32_t none = 0xFFFFFFFFu;

/// Bits of a coordinate with -0 folded onto +0, so both weld and hash alike.
std::uint32_t coordinate_bits(float v) {
  return std::bit_cast<std::uint32_t>(v + 0.0f);
}

std::array<std::uint32_t, 3> position_bits(glm::vec3 p) {
  return {coordinate_bits(p.x), coordinate_bits(p.y), coordinate_bits(p.z)};
}

glm::dvec3 to_double(glm::vec3 p) {
  return {p.x, p.y, p.z};
}

std::string point_text(glm::vec3 p) {
  return fmt::format("({}, {}, {})", p.x, p.y, p.z);
}

void check_input(const TriangleMesh& mesh, std::span<const std::uint8_t> locked) {
  if (mesh.indices.empty()) fail("the mesh is empty: it has no triangles");
  if (mesh.indices.size() % 3 != 0)
    fail("the mesh has {} indices, which is not a multiple of 3: every triangle needs three", mesh.indices.size());
  if (!locked.empty() && locked.size() != mesh.positions.size())
    fail("the vertex locks list {} entries for {} vertices: give one per vertex", locked.size(), mesh.positions.size());
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      fail("triangle {} of the input (counting from 1) refers to vertex {}, but there are only {} vertices", i / 3 + 1, mesh.indices[i] + 1,
           mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail("vertex {} of the input (counting from 1) has a coordinate that is not a finite number: {}", v + 1, point_text(p));
  }
}

/// Vertices of the input after welding, in canonical order (by key, then by coordinates).
struct Welded {
  Buffer<glm::vec3> positions;
  Buffer<std::uint64_t> keys;
  Buffer<std::uint8_t> flags;
  std::vector<std::uint32_t> of_input;  ///< input vertex -> welded vertex, or none if unused
  std::size_t welded = 0;
  std::size_t unused = 0;
};

Welded weld(const TriangleMesh& mesh, std::span<const std::uint8_t> locked) {
  std::vector<char> used(mesh.positions.size(), 0);
  for (std::uint32_t index : mesh.indices) used[index] = 1;
  struct Item {
    std::uint64_t key;
    std::array<std::uint32_t, 3> bits;
    std::uint32_t input;
  };
  std::vector<Item> items;
  items.reserve(mesh.positions.size());
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
    if (used[v]) items.push_back({position_key(mesh.positions[v]), position_bits(mesh.positions[v]), v});
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return std::tie(a.key, a.bits, a.input) < std::tie(b.key, b.bits, b.input); });

  Welded out;
  out.of_input.assign(mesh.positions.size(), none);
  out.unused = mesh.positions.size() - items.size();
  for (std::size_t i = 0; i < items.size(); ++i) {
    const bool same_as_previous = i > 0 && items[i].key == items[i - 1].key && items[i].bits == items[i - 1].bits;
    if (same_as_previous) {
      ++out.welded;
    } else {
      out.positions.push_back(mesh.positions[items[i].input] + 0.0f);
      out.keys.push_back(items[i].key);
      out.flags.push_back(0);
    }
    const auto id = static_cast<std::uint32_t>(out.positions.size() - 1);
    out.of_input[items[i].input] = id;
    if (!locked.empty() && locked[items[i].input] != 0) out.flags[id] |= vertex_locked;
  }
  return out;
}

/// Rotates the corners so that the smallest comes first, keeping the winding.
Corners min_first(Corners c) {
  const int first = c[0] < c[1] ? (c[0] < c[2] ? 0 : 2) : (c[1] < c[2] ? 1 : 2);
  return {c[first], c[(first + 1) % 3], c[(first + 2) % 3]};
}

/// A triangle of the input with its place there (for messages).
struct InputTriangle {
  Corners corners;
  std::uint32_t input;
};

std::vector<InputTriangle> canonical_triangles(const TriangleMesh& mesh, const Welded& welded) {
  std::vector<InputTriangle> triangles(mesh.triangle_count());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const Corners c{welded.of_input[mesh.indices[3 * t]], welded.of_input[mesh.indices[3 * t + 1]],
                    welded.of_input[mesh.indices[3 * t + 2]]};
    for (int i = 0; i < 3; ++i)
      if (c[i] == c[(i + 1) % 3])
        fail("triangle {} of the input (counting from 1) has zero area: two of its corners are the same point {}", t + 1,
             point_text(welded.positions[c[i]]));
    const glm::dvec3 a = to_double(welded.positions[c[0]]), b = to_double(welded.positions[c[1]]), d = to_double(welded.positions[c[2]]);
    const double longest = std::max({glm::length(b - a), glm::length(d - b), glm::length(a - d)});
    if (glm::length(glm::cross(b - a, d - a)) <= 1e-10 * longest * longest)
      fail("triangle {} of the input (counting from 1) has zero area: its corners {}, {}, {} lie on one line", t + 1,
           point_text(welded.positions[c[0]]), point_text(welded.positions[c[1]]), point_text(welded.positions[c[2]]));
    triangles[t] = {min_first(c), t};
  }
  std::sort(triangles.begin(), triangles.end(),
            [](const InputTriangle& a, const InputTriangle& b) { return std::tie(a.corners, a.input) < std::tie(b.corners, b.input); });

  // The same three corners twice (in either winding) is not a surface.
  std::vector<std::pair<Corners, std::uint32_t>> sets(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    Corners sorted = triangles[t].corners;
    std::sort(sorted.begin(), sorted.end());
    sets[t] = {sorted, triangles[t].input};
  }
  std::sort(sets.begin(), sets.end());
  for (std::size_t t = 1; t < sets.size(); ++t)
    if (sets[t].first == sets[t - 1].first)
      fail("triangles {} and {} of the input (counting from 1) have the same three corners", sets[t - 1].second + 1, sets[t].second + 1);
  return triangles;
}

/// One side of an edge: triangle t's edge from corner i to corner i+1.
struct HalfEdge {
  std::uint32_t lo, hi;  ///< the end vertices, smaller first
  std::uint32_t t;
  std::uint8_t i;
};

std::vector<HalfEdge> half_edges_of(const std::vector<InputTriangle>& triangles) {
  std::vector<HalfEdge> half(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint8_t i = 0; i < 3; ++i) {
      const std::uint32_t a = triangles[t].corners[i], b = triangles[t].corners[(i + 1) % 3];
      half[3 * t + i] = {std::min(a, b), std::max(a, b), t, i};
    }
  std::sort(half.begin(), half.end(),
            [](const HalfEdge& a, const HalfEdge& b) { return std::tie(a.lo, a.hi, a.t, a.i) < std::tie(b.lo, b.hi, b.t, b.i); });
  return half;
}

/// Calls visit(first, count) for each run of half-edges on the same edge.
template <class Visit>
void for_each_edge(const std::vector<HalfEdge>& half, Visit&& visit) {
  for (std::size_t first = 0; first < half.size();) {
    std::size_t last = first + 1;
    while (last < half.size() && half[last].lo == half[first].lo && half[last].hi == half[first].hi) ++last;
    visit(first, last - first);
    first = last;
  }
}

void check_manifold(const std::vector<HalfEdge>& half, const std::vector<InputTriangle>& triangles, const Welded& welded) {
  for_each_edge(half, [&](std::size_t first, std::size_t count) {
    if (count <= 2) return;
    std::vector<std::uint32_t> inputs;
    for (std::size_t k = first; k < first + count; ++k) inputs.push_back(triangles[half[k].t].input + 1);
    std::sort(inputs.begin(), inputs.end());
    fail(
        "the edge from {} to {} is shared by {} triangles (input triangles {}, counting from 1): a surface edge may "
        "border at most two",
        point_text(welded.positions[half[first].lo]), point_text(welded.positions[half[first].hi]), count, fmt::join(inputs, ", "));
  });
}

/// Turns triangles over so that neighbours agree, then each connected piece outwards (closed)
/// or upwards (open). Returns the number of triangles turned over.
std::size_t orient(std::vector<InputTriangle>& triangles, const std::vector<HalfEdge>& half, const Welded& welded) {
  const std::size_t count = triangles.size();
  // Neighbours across each interior edge, and whether they walk it the same way (disagree).
  std::vector<std::array<std::uint32_t, 3>> neighbour(count, {none, none, none});
  std::vector<std::array<bool, 3>> disagree(count, {false, false, false});
  for_each_edge(half, [&](std::size_t first, std::size_t n) {
    if (n != 2) return;
    const HalfEdge& a = half[first];
    const HalfEdge& b = half[first + 1];
    const bool same_way = triangles[a.t].corners[a.i] == triangles[b.t].corners[b.i];
    neighbour[a.t][a.i] = b.t, disagree[a.t][a.i] = same_way;
    neighbour[b.t][b.i] = a.t, disagree[b.t][b.i] = same_way;
  });

  std::vector<int> flip(count, -1);
  std::vector<std::uint32_t> piece, queue;
  std::size_t flipped = 0;
  for (std::uint32_t start = 0; start < count; ++start) {
    if (flip[start] >= 0) continue;
    piece.clear();
    queue.assign(1, start);
    flip[start] = 0;
    bool closed = true;
    while (!queue.empty()) {
      const std::uint32_t t = queue.back();
      queue.pop_back();
      piece.push_back(t);
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t u = neighbour[t][i];
        if (u == none) {
          closed = false;
          continue;
        }
        const int wanted = flip[t] ^ int(disagree[t][i]);
        if (flip[u] < 0) {
          flip[u] = wanted;
          queue.push_back(u);
        } else if (flip[u] != wanted) {
          fail("the surface cannot be oriented (it is like a Moebius strip) near input triangle {} (counting from 1)",
               triangles[u].input + 1);
        }
      }
    }
    // Which way the piece faces: signed volume if closed, else the upward part of its area.
    double measure = 0.0;
    for (std::uint32_t t : piece) {
      Corners c = triangles[t].corners;
      if (flip[t]) std::swap(c[1], c[2]);
      const glm::dvec3 a = to_double(welded.positions[c[0]]), b = to_double(welded.positions[c[1]]), d = to_double(welded.positions[c[2]]);
      measure += closed ? glm::dot(a, glm::cross(b, d)) : glm::cross(b - a, d - a).y;
    }
    const int turn_all = measure < 0.0 ? 1 : 0;
    for (std::uint32_t t : piece) {
      if ((flip[t] ^ turn_all) == 0) continue;
      std::swap(triangles[t].corners[1], triangles[t].corners[2]);  // keeps the smallest first
      ++flipped;
    }
  }
  return flipped;
}

}  // namespace

std::uint64_t position_key(glm::vec3 position) {
  const auto bits = position_bits(position);
  const std::uint64_t xy = std::uint64_t(bits[0]) | (std::uint64_t(bits[1]) << 32);
  return rng::mix64(rng::mix64(xy) + std::uint64_t(bits[2]) * rng::golden_gamma);
}

std::uint64_t midpoint_key(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
  return rng::mix64(rng::mix64(lo ^ 0x6D6964706F696E74ull) + hi * rng::golden_gamma);
}

EdgeMesh build_edge_mesh(const TriangleMesh& input, std::span<const std::uint8_t> locked, BuildReport* report) {
  check_input(input, locked);
  Welded welded = weld(input, locked);
  std::vector<InputTriangle> triangles = canonical_triangles(input, welded);
  check_manifold(half_edges_of(triangles), triangles, welded);
  const std::size_t flipped = orient(triangles, half_edges_of(triangles), welded);

  EdgeMesh mesh;
  mesh.positions = std::move(welded.positions);
  mesh.keys = std::move(welded.keys);
  mesh.flags = std::move(welded.flags);
  mesh.triangles.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) mesh.triangles[t] = triangles[t].corners;
  mesh.triangle_edges.assign(triangles.size(), {none, none, none});

  // The edge table, in the order of the sorted half-edges; after orient() the two sides of an
  // interior edge walk it in opposite directions.
  const std::vector<HalfEdge> half = half_edges_of(triangles);
  for_each_edge(half, [&](std::size_t first, std::size_t n) {
    const auto e = static_cast<std::uint32_t>(mesh.edges.size());
    const HalfEdge& side = half[first];
    const Corners& c = mesh.triangles[side.t];
    Edge edge{{c[side.i], c[(side.i + 1) % 3]}, {side.t, no_triangle}};
    mesh.triangle_edges[side.t][side.i] = e;
    if (n == 2) {
      edge.t[1] = half[first + 1].t;
      mesh.triangle_edges[half[first + 1].t][half[first + 1].i] = e;
    }
    mesh.edges.push_back(edge);
  });

  if (report != nullptr) *report = {welded.welded, welded.unused, flipped};
  return mesh;
}

TrianglesByBlock triangles_by_block(const EdgeMesh& mesh) {
  constexpr int block_bits = TrianglesByBlock::block_bits;
  constexpr std::size_t chunk = 1 << 16;
  const std::size_t triangle_count = mesh.triangle_count();
  const std::size_t blocks = (mesh.vertex_count() >> block_bits) + 1, chunks = (triangle_count + chunk - 1) / chunk;
  // Calls visit(block) once for each block that a corner of triangle t falls in.
  auto for_blocks_of = [&](std::size_t t, auto&& visit) {
    const auto& c = mesh.triangles[t];
    const std::uint32_t b0 = c[0] >> block_bits, b1 = c[1] >> block_bits, b2 = c[2] >> block_bits;
    visit(b0);
    if (b1 != b0) visit(b1);
    if (b2 != b0 && b2 != b1) visit(b2);
  };
  std::vector<std::uint32_t> count(chunks * blocks, 0);
  parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    for (std::size_t t = k * chunk; t < std::min(triangle_count, (k + 1) * chunk); ++t)
      for_blocks_of(t, [&](std::uint32_t b) { ++count[k * blocks + b]; });
  });
  TrianglesByBlock by_block;
  by_block.blocks = blocks;
  std::vector<std::size_t> offset(chunks * blocks);
  std::vector<std::size_t>& block_start = by_block.block_start;
  block_start.resize(blocks + 1);
  std::size_t total = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    block_start[b] = total;
    for (std::size_t k = 0; k < chunks; ++k) offset[k * blocks + b] = total, total += count[k * blocks + b];
  }
  block_start[blocks] = total;
  Buffer<std::uint32_t>& listed = by_block.listed;
  listed.resize(total);
  parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
    for (std::size_t t = k * chunk; t < std::min(triangle_count, (k + 1) * chunk); ++t)
      for_blocks_of(t, [&](std::uint32_t b) { listed[offset[k * blocks + b]++] = std::uint32_t(t); });
  });
  return by_block;
}

TriangleMesh to_triangle_mesh(const EdgeMesh& mesh, bool with_normals) {
  TriangleMesh out;
  reserve_on_huge_pages(out.positions, mesh.vertex_count());
  out.positions.assign(mesh.positions.begin(), mesh.positions.end());
  reserve_on_huge_pages(out.indices, 3 * mesh.triangle_count());
  out.indices.resize(3 * mesh.triangle_count());
  parallel_for_ranges<std::size_t>(0, mesh.triangle_count(), 1, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t t = range_begin; t < range_end; ++t)
      for (int i = 0; i < 3; ++i) out.indices[3 * t + i] = mesh.triangles[t][i];
  });
  if (!with_normals) return out;

  // Area-weighted vertex normals. Each vertex sums its triangles in increasing triangle order,
  // so the bytes never depend on the thread count. Triangles are listed per block of vertices
  // (once per block their corners fall in) by a counting sort over fixed chunks of triangles,
  // which keeps triangle order inside each block; then blocks are summed in parallel. A
  // triangle's normal is worked out again in each block it is listed in (two or three): the
  // same bytes as keeping them, without an array as large as the triangles.
  const std::size_t vertex_count = mesh.vertex_count();
  const auto face = [&](std::uint32_t t) {
    const auto& c = mesh.triangles[t];
    const glm::vec3 a = mesh.positions[c[0]];
    return glm::cross(mesh.positions[c[1]] - a, mesh.positions[c[2]] - a);
  };
  constexpr int block_bits = TrianglesByBlock::block_bits;
  const TrianglesByBlock by_block = triangles_by_block(mesh);
  const std::vector<std::size_t>& block_start = by_block.block_start;
  const Buffer<std::uint32_t>& listed = by_block.listed;
  reserve_on_huge_pages(out.normals, vertex_count);
  out.normals.resize(vertex_count);
  parallel_for(std::size_t{0}, by_block.blocks, [&](std::size_t b) {
    const std::size_t first = b << block_bits, last = std::min(vertex_count, (b + 1) << block_bits);
    std::vector<glm::vec3> sum(last - first, glm::vec3(0.0f));
    for (std::size_t n = block_start[b]; n < block_start[b + 1]; ++n) {
      const glm::vec3 normal = face(listed[n]);
      for (std::uint32_t v : mesh.triangles[listed[n]])
        if ((v >> block_bits) == b) sum[v - first] += normal;
    }
    for (std::size_t v = first; v < last; ++v) {
      const float length = glm::length(sum[v - first]);
      out.normals[v] = length > 0.0f ? sum[v - first] / length : glm::vec3(0.0f, 1.0f, 0.0f);
    }
  });
  return out;
}

EdgeLengths edge_lengths(const EdgeMesh& mesh) {
  return edge_lengths_of(mesh.edge_count(), mesh.positions.data(), [&](std::size_t e) { return mesh.edges[e].v; });
}

long long euler_characteristic(const EdgeMesh& mesh) {
  return static_cast<long long>(mesh.vertex_count()) - static_cast<long long>(mesh.edge_count()) +
         static_cast<long long>(mesh.triangle_count());
}

}  // namespace sansui::mesh
