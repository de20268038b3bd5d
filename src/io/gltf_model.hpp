// Reading glTF safely: every offset, length, stride and count in a glTF file is a number the
// file states, so each accessor is checked against its buffer view and buffer before a byte is
// read, with arithmetic that cannot wrap around. Shared by the mesh reader (gltf.cpp) and the
// vertex locks (vertex_locks.cpp). Internal to io/.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace tinygltf {
class Model;
}

namespace sansui::io::detail {

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
