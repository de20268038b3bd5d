// Checked glTF accessors: see gltf_model.hpp.
#include "io/gltf_model.hpp"

#include <tiny_gltf.h>

#include "core/error.hpp"

namespace sansui::io::detail {

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
