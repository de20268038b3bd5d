// Wavefront OBJ: "v x y z", "vn x y z" (one normal per vertex, same index), "vt u v" (same index;
// v up the image, OBJ's convention) and "f a/a/a b/b/b c/c/c" (1-based; "f a//a ..." without
// texture coordinates), with "mtllib NAME.mtl" when the mesh has a material. Numbers are
// formatted by fmt (the shortest text that reads back to the same float),
// blocks of lines in parallel, written in order.
// Read with tinyobjloader (triangulating polygons).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include <fmt/compile.h>
#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/binary_file.hpp"
#include "io/mesh_formats.hpp"
#include "io/text_file.hpp"

namespace sansui::io::detail {
namespace {

/// Lines per formatting task, and tasks formatted before their output is written: bounds the
/// memory held at once to a few MiB whatever the mesh size.
constexpr std::size_t lines_per_block = 16384;
constexpr std::size_t blocks_per_round = 16;

/// Formats lines 0..count-1 with `format_line` into `file`, in order.
template <class FormatLine>
void write_blocks(OutputFile& file, std::size_t count, const FormatLine& format_line) {
  std::vector<fmt::memory_buffer> blocks(blocks_per_round);
  for (std::size_t first = 0; first < count; first += lines_per_block * blocks_per_round) {
    const std::size_t round_blocks = std::min(blocks_per_round, (count - first + lines_per_block - 1) / lines_per_block);
    parallel_for(std::size_t{0}, round_blocks, [&](std::size_t block) {
      fmt::memory_buffer& out = blocks[block];
      out.clear();
      const std::size_t begin = first + block * lines_per_block, end = std::min(count, begin + lines_per_block);
      for (std::size_t i = begin; i < end; ++i) format_line(out, i);
    });
    for (std::size_t block = 0; block < round_blocks; ++block) file.write(blocks[block].data(), blocks[block].size());
  }
}

/// OBJ has no end marker, so a truncated file parses as a smaller mesh. Files Sansui wrote state
/// their counts in the first line; if they do, the counts read must match.
void check_sansui_counts(const std::filesystem::path& path, std::string_view text, std::size_t vertices, std::size_t triangles) {
  const std::string line(text.substr(0, std::min<std::size_t>(text.find('\n'), 200)));
  unsigned long long stated_vertices = 0, stated_triangles = 0;
  if (std::sscanf(line.c_str(), "# Sansui %*s %llu vertices, %llu triangles", &stated_vertices, &stated_triangles) == 2 &&
      (stated_vertices != vertices || stated_triangles != triangles))
    fail("cannot read {}: it is truncated or corrupt ({} vertices and {} triangles instead of the {} and {} it states)", path.string(),
         vertices, triangles, stated_vertices, stated_triangles);
}

/// tinyobjloader reads a number it cannot parse as 0 and takes nan and inf: a vertex line with
/// a word or a non-finite number where a coordinate belongs is refused here, naming the line.
void check_vertex_numbers(const std::filesystem::path& path, std::string_view text) {
  std::size_t line_number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    if (!(line.starts_with("v ") || line.starts_with("vn ") || line.starts_with("vt ") || line.starts_with("v\t"))) continue;
    line.remove_prefix(line.find_first_of(" \t"));
    for (std::size_t at = 0;;) {
      at = line.find_first_not_of(" \t\r", at);
      if (at == std::string_view::npos) break;
      const std::size_t token_end = std::min(line.find_first_of(" \t\r", at), line.size());
      std::string_view token = line.substr(at, token_end - at);
      if (token.starts_with('+')) token.remove_prefix(1);
      double value = 0.0;
      const auto [stop, error] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (error != std::errc() || stop != token.data() + token.size() || !std::isfinite(value))
        fail("cannot read {}: line {}: '{}' is not a finite number (vertex lines hold numbers only)", path.string(), line_number,
             line.substr(at, std::min<std::size_t>(token_end - at, 40)));
      at = token_end;
    }
  }
}

}  // namespace

void write_obj(const std::filesystem::path& temporary, const std::filesystem::path& target, const TriangleMesh& mesh,
               const std::string& material_file) {
  OutputFile file(temporary, target);
  file.write(fmt::format("# Sansui {}: {} vertices, {} triangles; metres, x east, y up, z south\n", SANSUI_VERSION, mesh.positions.size(),
                         mesh.triangle_count()));
  if (!material_file.empty()) file.write(fmt::format("mtllib {}\nusemtl terrain\n", material_file));
  const bool with_normals = !mesh.normals.empty();
  const bool with_uvs = !mesh.uvs.empty();
  // Lines are formatted in parallel, a block of lines per task, and written in order: the bytes
  // do not depend on the thread count.
  write_blocks(file, mesh.positions.size(), [&](fmt::memory_buffer& out, std::size_t i) {
    const auto& p = mesh.positions[i];
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("v {} {} {}\n"), p.x, p.y, p.z);
  });
  write_blocks(file, mesh.normals.size(), [&](fmt::memory_buffer& out, std::size_t i) {
    const auto& n = mesh.normals[i];
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("vn {} {} {}\n"), n.x, n.y, n.z);
  });
  // OBJ's v runs up the image; ours (glTF's) runs down it.
  write_blocks(file, mesh.uvs.size(), [&](fmt::memory_buffer& out, std::size_t i) {
    const auto& uv = mesh.uvs[i];
    fmt::format_to(std::back_inserter(out), FMT_COMPILE("vt {} {}\n"), uv.x, 1.0f - uv.y);
  });
  write_blocks(file, mesh.triangle_count(), [&](fmt::memory_buffer& out, std::size_t t) {
    const std::uint64_t a = mesh.indices[3 * t] + 1ull, b = mesh.indices[3 * t + 1] + 1ull, c = mesh.indices[3 * t + 2] + 1ull;
    if (with_uvs && with_normals)
      fmt::format_to(std::back_inserter(out), FMT_COMPILE("f {}/{}/{} {}/{}/{} {}/{}/{}\n"), a, a, a, b, b, b, c, c, c);
    else if (with_uvs)
      fmt::format_to(std::back_inserter(out), FMT_COMPILE("f {}/{} {}/{} {}/{}\n"), a, a, b, b, c, c);
    else if (with_normals)
      fmt::format_to(std::back_inserter(out), FMT_COMPILE("f {}//{} {}//{} {}//{}\n"), a, a, b, b, c, c);
    else
      fmt::format_to(std::back_inserter(out), FMT_COMPILE("f {} {} {}\n"), a, b, c);
  });
  file.close();
}

TriangleMesh read_obj(const std::filesystem::path& path) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  // From the text, with no material text: an OBJ's `mtllib` names another file, which must
  // never be opened (it could be a device; an input makes Sansui read nothing but itself).
  // Materials are not needed for geometry.
  const std::string text = read_text_file(path, max_mesh_file_bytes);
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, "", config)) {
    std::string message = reader.Error();
    while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
    std::ranges::replace(message, '\n', ' ');
    fail("cannot read {}: {}", path.string(), message.empty() ? "not a readable OBJ file" : message);
  }
  check_vertex_numbers(path, text);
  const tinyobj::attrib_t& attributes = reader.GetAttrib();
  const auto vertex_count = attributes.vertices.size() / 3, normal_count = attributes.normals.size() / 3;

  // OBJ indexes positions and normals separately; a TriangleMesh has one normal per position.
  // Sansui's own files use the same index for both, which maps straight through; other files
  // get one vertex per distinct (position, normal) pair.
  bool same_indices = true, all_normals = true;
  std::size_t corners = 0;
  for (const auto& shape : reader.GetShapes()) {
    for (const auto& index : shape.mesh.indices) {
      if (index.vertex_index < 0 || static_cast<std::size_t>(index.vertex_index) >= vertex_count)
        fail("cannot read {}: a face refers to vertex {} of {} (corrupt or truncated file)", path.string(), index.vertex_index + 1,
             vertex_count);
      if (index.normal_index >= static_cast<int>(normal_count))
        fail("cannot read {}: a face refers to normal {} of {} (corrupt or truncated file)", path.string(), index.normal_index + 1,
             normal_count);
      same_indices &= index.normal_index == index.vertex_index;
      all_normals &= index.normal_index >= 0;
    }
    corners += shape.mesh.indices.size();
  }
  // Shared indices map normals straight through only if every position has one (a fuzzed file
  // had faces using 3 of 5 positions and 3 normals: normal 4 would be read past the array).
  same_indices &= normal_count >= vertex_count;
  if (corners == 0) fail("cannot read {}: it has no faces", path.string());
  check_sansui_counts(path, text, vertex_count, corners / 3);

  TriangleMesh mesh;
  mesh.indices.reserve(corners);
  const auto position_of = [&](int i) {
    return glm::vec3(attributes.vertices[3 * i], attributes.vertices[3 * i + 1], attributes.vertices[3 * i + 2]);
  };
  const auto normal_of = [&](int i) {
    return glm::vec3(attributes.normals[3 * i], attributes.normals[3 * i + 1], attributes.normals[3 * i + 2]);
  };
  if (same_indices || !all_normals) {
    for (std::size_t i = 0; i < vertex_count; ++i) mesh.positions.push_back(position_of(static_cast<int>(i)));
    if (same_indices && all_normals)
      for (std::size_t i = 0; i < vertex_count; ++i) mesh.normals.push_back(normal_of(static_cast<int>(i)));
    for (const auto& shape : reader.GetShapes())
      for (const auto& index : shape.mesh.indices) mesh.indices.push_back(static_cast<std::uint32_t>(index.vertex_index));
  } else {
    std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_pair;
    for (const auto& shape : reader.GetShapes())
      for (const auto& index : shape.mesh.indices) {
        const std::uint64_t key = std::uint64_t(std::uint32_t(index.vertex_index)) << 32 | std::uint32_t(index.normal_index);
        const auto [where, added] = vertex_of_pair.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
        if (added) {
          mesh.positions.push_back(position_of(index.vertex_index));
          mesh.normals.push_back(normal_of(index.normal_index));
        }
        mesh.indices.push_back(where->second);
      }
  }
  return mesh;
}

}  // namespace sansui::io::detail
