// Reading glTF safely, for the mesh reader (gltf.cpp) and the vertex locks (vertex_locks.cpp):
// the file alone is read (never the files its `uri`s name, which could be anything, a device
// included), and every offset, length, stride and count in it is a number the file states, so
// each accessor is checked against its buffer view and buffer before a byte is read, with
// arithmetic that cannot wrap around. Internal to io/.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace tinygltf {
class Model;
}

namespace sansui::io::detail {

/// The model in `path` (.gltf JSON, or .glb if `binary`), read by tinygltf from the file's bytes
/// alone: buffers are embedded (GLB chunk, data: URIs); a buffer naming an external file is
/// refused, an image naming one is skipped (images are not needed). Throws InputError naming
/// the file for anything tinygltf refuses or throws, and for JSON nested deeper than
/// max_json_depth (tinygltf walks "extras" recursively).
tinygltf::Model load_gltf_model(const std::filesystem::path& path, bool binary);

/// The bytes of one accessor: element i starts at base + i * stride and has element_bytes.
struct AccessorBytes {
  const unsigned char* base = nullptr;  ///< null when count is 0
  std::size_t count = 0, stride = 0, element_bytes = 0;
  int component_type = 0, components = 0;
};

/// Accessor `index` of `model`, checked: it exists, is not sparse, has a known type, and all
/// its elements lie inside its buffer view, which lies inside its buffer. Throws InputError
/// naming `path` and `what` (e.g. "POSITION") otherwise.
AccessorBytes accessor_bytes(const std::filesystem::path& path, const tinygltf::Model& model, int index, std::string_view what);

}  // namespace sansui::io::detail
