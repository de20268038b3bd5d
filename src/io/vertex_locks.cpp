// Vertex locks from OBJ vertex colours and the glTF attribute "_LOCK" (see vertex_locks.hpp).
#include "io/vertex_locks.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <functional>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "core/error.hpp"
#include "io/extension.hpp"
#include "io/gltf_model.hpp"
#include "io/mesh_formats.hpp"
#include "io/text_file.hpp"

namespace sansui::io {
namespace {

std::vector<glm::vec3> obj_locks(const std::filesystem::path& path) {
  tinyobj::ObjReaderConfig config;
  config.vertex_color = true;
  // From the text, with no material text: `mtllib` is never followed (see obj.cpp).
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(read_text_file(path, detail::max_mesh_file_bytes), "", config))
    fail("cannot read mesh {}: {}", path.string(), reader.Error().empty() ? "not an OBJ file" : reader.Error());
  const auto& attrib = reader.GetAttrib();
  std::vector<glm::vec3> locked;
  if (attrib.colors.size() != attrib.vertices.size()) return locked;
  for (std::size_t v = 0; 3 * v + 2 < attrib.vertices.size(); ++v) {
    const float r = attrib.colors[3 * v], g = attrib.colors[3 * v + 1], b = attrib.colors[3 * v + 2];
    if (r >= 0.5f && g < 0.5f && b < 0.5f)
      locked.emplace_back(attrib.vertices[3 * v], attrib.vertices[3 * v + 1], attrib.vertices[3 * v + 2]);
  }
  return locked;
}

/// Calls visit(i, bytes) for each element of an accessor (checked against its buffer).
void for_each_element(const detail::AccessorBytes& bytes, const std::function<void(std::size_t, const unsigned char*)>& visit) {
  for (std::size_t i = 0; i < bytes.count; ++i) visit(i, bytes.base + i * bytes.stride);
}

void primitive_locks(const std::filesystem::path& path, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                     const glm::mat4& world, std::vector<glm::vec3>& locked) {
  const auto lock = primitive.attributes.find("_LOCK");
  const auto position = primitive.attributes.find("POSITION");
  if (lock == primitive.attributes.end() || position == primitive.attributes.end()) return;
  const detail::AccessorBytes locks = detail::accessor_bytes(path, model, lock->second, "_LOCK");
  if (locks.components != 1) fail("cannot read {}: glTF attribute _LOCK must be a scalar", path.string());
  if (locks.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && locks.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      locks.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
    fail("cannot read {}: glTF attribute _LOCK must be float, unsigned byte or unsigned short", path.string());
  const detail::AccessorBytes positions = detail::accessor_bytes(path, model, position->second, "POSITION");
  if (positions.component_type != TINYGLTF_COMPONENT_TYPE_FLOAT || positions.components != 3)
    fail("cannot read {}: POSITION must be float32 VEC3", path.string());
  std::vector<bool> is_locked(locks.count, false);
  for_each_element(locks, [&](std::size_t i, const unsigned char* bytes) {
    switch (locks.component_type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, bytes, 4);
        is_locked[i] = v != 0.0f;
        break;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        is_locked[i] = bytes[0] != 0;
        break;
      default:  // unsigned short
        is_locked[i] = (bytes[0] | bytes[1]) != 0;
        break;
    }
  });
  for_each_element(positions, [&](std::size_t i, const unsigned char* bytes) {
    if (i >= is_locked.size() || !is_locked[i]) return;
    glm::vec3 p;
    std::memcpy(&p.x, bytes, 4), std::memcpy(&p.y, bytes + 4, 4), std::memcpy(&p.z, bytes + 8, 4);
    locked.push_back(world == glm::mat4(1.0f) ? p : glm::vec3(world * glm::vec4(p, 1.0f)));
  });
}

std::vector<glm::vec3> gltf_locks(const std::filesystem::path& path) {
  const tinygltf::Model model = detail::load_gltf_model(path, lower_extension(path) == ".glb");
  std::vector<glm::vec3> locked;
  if (model.scenes.empty()) {
    for (const auto& mesh : model.meshes)
      for (const auto& primitive : mesh.primitives) primitive_locks(path, model, primitive, glm::mat4(1.0f), locked);
    return locked;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (std::size_t(scene) >= model.scenes.size()) fail("cannot read {}: the default scene {} does not exist", path.string(), scene);
  std::vector<bool> seen(model.nodes.size(), false);
  std::vector<std::pair<int, glm::mat4>> stack;
  for (int root : model.scenes[std::size_t(scene)].nodes) stack.emplace_back(root, glm::mat4(1.0f));
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    if (index < 0 || std::size_t(index) >= model.nodes.size() || seen[std::size_t(index)])
      fail("cannot read {}: node {} is missing or appears twice in the scene tree", path.string(), index);
    seen[std::size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[std::size_t(index)];
    const glm::mat4 world = parent * detail::gltf_local_transform(node);
    if (node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size())
      for (const auto& primitive : model.meshes[std::size_t(node.mesh)].primitives) primitive_locks(path, model, primitive, world, locked);
    for (int child : node.children) stack.emplace_back(child, world);
  }
  return locked;
}

std::array<std::uint32_t, 3> bits_of(glm::vec3 p) {
  return {std::bit_cast<std::uint32_t>(p.x + 0.0f), std::bit_cast<std::uint32_t>(p.y + 0.0f), std::bit_cast<std::uint32_t>(p.z + 0.0f)};
}

}  // namespace

std::vector<glm::vec3> read_locked_positions(const std::filesystem::path& path) {
  const std::string extension = lower_extension(path);
  if (extension == ".obj") return obj_locks(path);
  if (extension == ".glb" || extension == ".gltf") return gltf_locks(path);
  fail("mesh {} has an unknown extension '{}': allowed are .obj .glb .gltf", path.string(), extension);
}

std::vector<std::uint8_t> lock_flags_for(const TriangleMesh& mesh, std::span<const glm::vec3> locked) {
  std::vector<std::array<std::uint32_t, 3>> keys;
  keys.reserve(locked.size());
  for (glm::vec3 p : locked) keys.push_back(bits_of(p));
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint8_t> flags(mesh.positions.size(), 0);
  for (std::size_t v = 0; v < flags.size(); ++v)
    flags[v] = std::binary_search(keys.begin(), keys.end(), bits_of(mesh.positions[v])) ? 1 : 0;
  return flags;
}

}  // namespace sansui::io
