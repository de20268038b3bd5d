// The per-format mesh writers and readers behind write_mesh/read_mesh. Internal to io/:
// mesh_io.cpp validates the mesh (finite, indices in range) and writes the sidecar.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/triangle_mesh.hpp"

namespace sansui::io::detail {

/// The largest mesh file read (OBJ text, glTF JSON or GLB): input meshes are the coarse meshes
/// that subdivision refines; 4 GiB of OBJ is about 100 million triangles.
inline constexpr std::size_t max_mesh_file_bytes = std::size_t{4} << 30;

/// The smallest and largest coordinates of a mesh's positions.
struct MeshBounds {
  glm::vec3 low, high;
};

// Writers: `temporary` is the file to create, `target` the name for messages.
/// `material_file`: the .mtl the OBJ names (mtllib, usemtl terrain), if any.
/// What a mesh writer is told.
struct MeshWrite {
  MeshBounds bounds;
  std::string material_file;                                   ///< an OBJ's NAME.mtl beside it, or empty
  const std::vector<unsigned char>* base_color_png = nullptr;  ///< a glb's embedded texture, or null
  std::string name = "terrain";                                ///< a glTF's node and mesh name
};

/// A mesh format's driver (registered in io/file_formats.cpp).
struct MeshDriver {
  /// The base colour texture goes inside the file; else beside it (NAME.mtl, NAME_basecolor.png).
  bool embeds_texture = false;
  TriangleMesh (*read)(const std::filesystem::path& path);
  /// Null for a format that is only read.
  void (*write)(const std::filesystem::path& temporary, const std::filesystem::path& target, const TriangleMesh& mesh,
                const MeshWrite& request);
  const char* description;  ///< the sidecar's "format": what the file holds
};
extern const MeshDriver obj_driver, glb_driver, gltf_driver;

void write_obj(const std::filesystem::path& temporary, const std::filesystem::path& target, const TriangleMesh& mesh,
               const std::string& material_file = {});
/// `bounds`: those of mesh.positions (the accessor's min and max). `base_color_png`: a PNG to
/// embed as the base-colour texture of a PBR material on TEXCOORD_0, if not empty.
void write_glb(const std::filesystem::path& temporary, const std::filesystem::path& target, const TriangleMesh& mesh,
               const MeshBounds& bounds, const std::vector<unsigned char>& base_color_png = {}, const std::string& name = "terrain");

TriangleMesh read_obj(const std::filesystem::path& path);
/// Reads .gltf (JSON) or .glb (binary), every triangle primitive of the default scene with its
/// node transforms applied.
TriangleMesh read_gltf(const std::filesystem::path& path, bool binary);

}  // namespace sansui::io::detail

namespace tinygltf {
class Node;
}

namespace sansui::io::detail {

/// A glTF node's local transform (matrix, or translation * rotation * scale), computed in double
/// then rounded to float: every reader of glTF positions uses it so they agree bit for bit.
glm::mat4 gltf_local_transform(const tinygltf::Node& node);

}  // namespace sansui::io::detail
