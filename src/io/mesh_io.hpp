// Triangle meshes as Wavefront OBJ (with normals) and binary glTF 2.0 (.glb).
// Writers are atomic (see atomic_file.hpp) and write a JSON sidecar NAME.json with provenance.
#pragma once

#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/color.hpp"
#include "core/triangle_mesh.hpp"
#include "io/file_formats.hpp"

namespace sansui::io {

/// The mesh format (io/file_formats.hpp) written for a file name's extension (.obj .glb), or null.
const FileFormat* mesh_format_for(const std::filesystem::path& path);

struct MeshWriteOptions {
  nlohmann::json provenance = nlohmann::json::object();  ///< copied into the sidecar
  bool sidecar = true;                                   ///< [Default: true]
  /// A base-colour texture (sRGB) for the mesh's UVs, in a PBR material: embedded in a .glb as
  /// a PNG; beside an .obj as NAME.png with a material file NAME.mtl. Needs mesh.uvs. [Default: none]
  const Image* base_color = nullptr;
  /// What the mesh holds, as the glTF names its node and mesh ("terrain", "oak"). [Default: terrain]
  std::string name = "terrain";
};

/// Writes the mesh in the format of the extension. Throws InputError.
void write_mesh(const std::filesystem::path& path, const TriangleMesh& mesh, const MeshWriteOptions& options = {});

/// Reads an OBJ (tinyobjloader) or glTF/.glb (tinygltf) mesh, triangulated. Throws InputError.
TriangleMesh read_mesh(const std::filesystem::path& path);

}  // namespace sansui::io
