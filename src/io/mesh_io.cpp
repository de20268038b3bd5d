// write_mesh / read_mesh: validation, the sidecar, and dispatch to obj.cpp and gltf.cpp.
#include "io/mesh_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/common.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/binary_file.hpp"
#include "io/file_formats.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
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
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
    fail("cannot write {}: the mesh has {} texture coordinates for {} positions", path.string(), mesh.uvs.size(), mesh.positions.size());
  for (const glm::vec2& uv : mesh.uvs)
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) fail("cannot write {}: a texture coordinate is not finite", path.string());
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
                            const FileFormat& format, const MeshWriteOptions& options, const nlohmann::json& material) {
  const glm::vec3 low = bounds.low, high = bounds.high;
  const nlohmann::json description{{"name", format.name}, {"description", format.mesh_driver->description}};
  nlohmann::json sidecar = {
      {"sansui_sidecar", sidecar_version},
      {"kind", "mesh"},
      {"file", path.filename().string()},
      {"format", description},
      {"units", "m"},
      {"axes", "x east, y up, z south (right-handed, glTF's convention); triangles counter-clockwise seen from above"},
      {"vertex_count", mesh.positions.size()},
      {"triangle_count", mesh.triangle_count()},
      {"has_normals", !mesh.normals.empty()},
      {"has_uvs", !mesh.uvs.empty()},
      {"bounds_m", {{"min", {low.x, low.y, low.z}}, {"max", {high.x, high.y, high.z}}}},
      {"provenance", options.provenance}};
  if (!material.is_null()) sidecar["material"] = material;
  return sidecar;
}

}  // namespace

const FileFormat* mesh_format_for(const std::filesystem::path& path) {
  return file_format_for(path, FormatData::mesh, Access::write);
}

void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshWriteOptions& options) {
  const auto format = mesh_format_for(path);
  if (!format)
    fail("cannot write {}: unknown extension '{}': meshes are {}", path.string(), path.extension().string(),
         format_extension_list(FormatData::mesh, Access::write));
  check_writable(path);
  const detail::MeshBounds bounds = validate(path, mesh);
  const Image* texture = options.base_color;
  if (texture && (texture->empty() || mesh.uvs.empty() || !mesh.colors.empty()))
    fail("cannot write {}: a base-colour texture needs a mesh with texture coordinates and no vertex colours", path.string());
  // An OBJ's material and texture go beside it (NAME.mtl, NAME_basecolor.png), each written
  // atomically before the mesh, so a mesh never names a file that is not there.
  const std::string stem = path.stem().string();
  const detail::MeshDriver& driver = *format->mesh_driver;
  const std::string mtl_name = texture && !driver.embeds_texture ? stem + ".mtl" : "";
  const std::string png_name = stem + "_basecolor.png";
  nlohmann::json material = nullptr;
  if (texture)
    material = {{"name", "terrain"},
                {"model", "glTF PBR metallic-roughness: base colour texture on the UVs, metallic 0, roughness 0.9"},
                {"base_color", driver.embeds_texture ? "embedded PNG (images[0])" : png_name},
                {"texture_size", {texture->width(), texture->height()}}};
  if (!mtl_name.empty()) material["mtl"] = mtl_name;
  std::optional<nlohmann::json> sidecar;
  if (options.sidecar) sidecar = mesh_sidecar(path, mesh, bounds, *format, options, material);
  std::vector<unsigned char> png;
  if (texture && driver.embeds_texture) png = encode_png(*texture);
  if (!mtl_name.empty()) {
    write_png(path.parent_path() / png_name, *texture);
    write_atomically(path.parent_path() / mtl_name, [&](const std::filesystem::path& temporary) {
      detail::OutputFile file(temporary, path.parent_path() / mtl_name);
      file.write(
          fmt::format("# Sansui {}: the material of {}\nnewmtl terrain\nKa 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 1\nd 1\nillum 1\nmap_Kd {}\n"
                      "# PBR extension (Blender, assimp): roughness, metallic, base colour\nPr 0.9\nPm 0\n",
                      SANSUI_VERSION, path.filename().string(), png_name));
      file.close();
    });
  }
  const detail::MeshWrite request{bounds, mtl_name, &png, options.name};
  detail::write_with_sidecar(path, sidecar, [&](const std::filesystem::path& temporary) { driver.write(temporary, path, mesh, request); });
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
  const FileFormat* format = file_format_for(path, FormatData::mesh, Access::read);
  if (format == nullptr)
    fail("cannot read {}: unknown extension '{}': meshes are {}", path.string(), path.extension().string(),
         format_extension_list(FormatData::mesh, Access::read));
  return format->mesh_driver->read(path);
}

}  // namespace sansui::io
