// glTF read from the input file alone, and checked accessors: see gltf_model.hpp.
#include "io/gltf_model.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/error.hpp"
#include "io/json_text.hpp"
#include "io/mesh_formats.hpp"
#include "io/text_file.hpp"

namespace sansui::io::detail {
namespace {

/// glTF files name other files (buffers and images by `uri`): Sansui reads only the input
/// itself, so every file system callback refuses, and records the names asked for, so the
/// message can say which one. data: URIs are decoded by tinygltf without these callbacks.
struct RefusedFiles {
  std::vector<std::string> names;
};

bool refuse_exists(const std::string& name, void* user) {
  static_cast<RefusedFiles*>(user)->names.push_back(name);
  return false;
}

std::string keep_path(const std::string& path, void*) {
  return path;  // no ~ or $VARIABLE expansion either
}

bool refuse_read(std::vector<unsigned char>*, std::string* error, const std::string& name, void* user) {
  static_cast<RefusedFiles*>(user)->names.push_back(name);
  if (error) *error = "external files are not read";
  return false;
}

bool refuse_write(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
  if (error) *error = "not written";
  return false;
}

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;  // geometry only: textures are neither decoded nor needed
}

/// tinygltf's messages end in a newline and may hold several lines: the first.
std::string first_line(std::string_view message) {
  return std::string(message.substr(0, message.find('\n')));
}

/// The JSON of a .gltf (all of it) or a .glb (its first chunk), for the nesting check.
std::string_view json_part(std::string_view bytes, bool binary) {
  if (!binary) return bytes;
  if (bytes.size() < 20) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

}  // namespace

tinygltf::Model load_gltf_model(const std::filesystem::path& path, bool binary) {
  // tinygltf takes the size as an unsigned int.
  const std::string bytes = read_text_file(path, std::min<std::size_t>(max_mesh_file_bytes, 0xFFFFFFFFu));
  // tinygltf walks "extras" and "extensions" recursively: deep nesting would overflow the stack.
  check_json_nesting(json_part(bytes, binary), "cannot read " + path.string());
  RefusedFiles refused;
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  loader.SetFsCallbacks({refuse_exists, keep_path, refuse_read, refuse_write, &refused});
  tinygltf::Model model;
  std::string message, warning;
  bool loaded = false;
  try {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    loaded = binary ? loader.LoadBinaryFromMemory(&model, &message, &warning, data, static_cast<unsigned>(bytes.size()), "")
                    : loader.LoadASCIIFromString(&model, &message, &warning, bytes.data(), static_cast<unsigned>(bytes.size()), "");
  } catch (const std::bad_alloc&) {
    fail("cannot read {}: its buffers do not fit in memory", path.string());
  } catch (const std::exception& e) {  // tinygltf's JSON library, on input it did not expect
    fail("cannot read {}: not a readable glTF file ({})", path.string(), first_line(e.what()));
  }
  if (!loaded) {
    if (!refused.names.empty())
      fail(
          "cannot read {}: it refers to the external file '{}': Sansui reads only the input file itself (embed buffers in a .glb or "
          "as data: URIs)",
          path.string(), refused.names.front());
    fail("cannot read {}: not a readable glTF file ({})", path.string(), message.empty() ? "corrupt" : first_line(message));
  }
  return model;
}

AccessorBytes accessor_bytes(const std::filesystem::path& path, const tinygltf::Model& model, int index, std::string_view what) {
  if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
    fail("cannot read {}: {} refers to accessor {}, which does not exist", path.string(), what, index);
  const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
  if (accessor.sparse.isSparse) fail("cannot read {}: sparse accessors are not supported ({})", path.string(), what);
  AccessorBytes out;
  out.count = accessor.count;
  out.component_type = accessor.componentType;
  out.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
  const int component_bytes = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
  if (out.components <= 0 || component_bytes <= 0) fail("cannot read {}: {} has an invalid type", path.string(), what);
  out.element_bytes = static_cast<std::size_t>(out.components) * static_cast<std::size_t>(component_bytes);
  if (out.count == 0) return out;
  if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
    fail("cannot read {}: {} has no buffer view", path.string(), what);
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
    fail("cannot read {}: {} refers to a missing buffer", path.string(), what);
  const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
  out.stride = view.byteStride != 0 ? view.byteStride : out.element_bytes;
  // Each bound is compared before it is added to or multiplied: a fuzzed file's offsets made
  // offset + stride * (count - 1) wrap around, and the reader read far outside the buffer.
  const bool view_fits = view.byteOffset <= data.size() && view.byteLength <= data.size() - view.byteOffset;
  const bool elements_fit = view_fits && out.stride >= out.element_bytes && accessor.byteOffset <= view.byteLength &&
                            out.element_bytes <= view.byteLength - accessor.byteOffset &&
                            out.count - 1 <= (view.byteLength - accessor.byteOffset - out.element_bytes) / out.stride;
  if (!elements_fit)
    fail(
        "cannot read {}: {} lies outside its buffer (corrupt or truncated file): {} elements of {} bytes every {} from byte {} of a "
        "view of {} bytes at byte {} of {}",
        path.string(), what, out.count, out.element_bytes, out.stride, accessor.byteOffset, view.byteLength, view.byteOffset, data.size());
  out.base = data.data() + view.byteOffset + accessor.byteOffset;
  return out;
}

}  // namespace sansui::io::detail
