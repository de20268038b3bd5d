// write_mesh / read_mesh: validation, the sidecar, and dispatch to obj.cpp and gltf.cpp.
#include "io/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/common.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/extension.hpp"
#include "io/heightmap_io.hpp"
#include "io/mesh_formats.hpp"
#include "io/sidecar.hpp"

namespace sansui::io {
namespace {

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Checks the mesh; returns the bounds of its positions (one pass for both).
detail::MeshBounds validate(const std::filesystem::path& path, const TriangleMesh& mesh) {
  if (mesh.indices.empty() || mesh.positions.empty()) fail("cannot write {}: the mesh has no triangles", path.string());
  if (mesh.indices.size() % 3 != 0)
    fail("cannot write {}: the mesh has {} indices, not a multiple of 3", path.string(), mesh.indices.size());
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    fail("cannot write {}: the mesh has {} normals for {} positions", path.string(), mesh.normals.size(), mesh.positions.size());
  detail::MeshBounds bounds{mesh.positions.front(), mesh.positions.front()};
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    if (!finite(p) || (!mesh.normals.empty() && !finite(mesh.normals[i])))
      fail("cannot write {}: vertex {} is not finite (NaN or infinity)", path.string(), i);
    bounds.low = glm::min(bounds.low, p);
    bounds.high = glm::max(bounds.high, p);
  }
  const auto largest = std::ranges::max(mesh.indices);
  if (largest >= mesh.positions.size())
    fail("cannot write {}: an index refers to vertex {} of {}", path.string(), largest, mesh.positions.size());
  return bounds;
}

nlohmann::json mesh_sidecar(const std::filesystem::path& path, const TriangleMesh& mesh, const detail::MeshBounds& bounds,
                            MeshFormat format, const MeshWriteOptions& options) {
  const glm::vec3 low = bounds.low, high = bounds.high;
  nlohmann::json description =
      format == MeshFormat::obj
          ? nlohmann::json{{"name", "obj"}, {"description", "Wavefront OBJ: v, vn (same index as v), f v//vn, 1-based"}}
          : nlohmann::json{{"name", "glb"}, {"description", "binary glTF 2.0: float32 POSITION and NORMAL, uint32 indices, one mesh"}};
  return {{"sansui_sidecar", sidecar_version},
          {"kind", "mesh"},
          {"file", path.filename().string()},
          {"format", description},
          {"units", "m"},
          {"axes", "x east, y up, z south (right-handed, glTF's convention); triangles counter-clockwise seen from above"},
          {"vertex_count", mesh.positions.size()},
          {"triangle_count", mesh.triangle_count()},
          {"has_normals", !mesh.normals.empty()},
          {"bounds_m", {{"min", {low.x, low.y, low.z}}, {"max", {high.x, high.y, high.z}}}},
          {"provenance", options.provenance}};
}

}  // namespace

std::optional<MeshFormat> mesh_format_for(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return MeshFormat::obj;
  if (extension == ".glb") return MeshFormat::glb;
  return std::nullopt;
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshWriteOptions& options) {
  const auto format = mesh_format_for(path);
  if (!format) fail("cannot write {}: unknown extension '{}': meshes are .obj .glb", path.string(), path.extension().string());
  check_writable(path);
  const detail::MeshBounds bounds = validate(path, mesh);
  std::optional<nlohmann::json> sidecar;
  if (options.sidecar) sidecar = mesh_sidecar(path, mesh, bounds, *format, options);
  detail::write_with_sidecar(path, sidecar, [&](const std::filesystem::path& temporary) {
    if (*format == MeshFormat::obj)
      detail::write_obj(temporary, path, mesh);
    else
      detail::write_glb(temporary, path, mesh, bounds);
  });
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return detail::read_obj(path);
  if (extension == ".glb") return detail::read_gltf(path, true);
  if (extension == ".gltf") return detail::read_gltf(path, false);
  fail("cannot read {}: unknown extension '{}': meshes are .obj .glb .gltf", path.string(), path.extension().string());
}

}  // namespace sansui::io
