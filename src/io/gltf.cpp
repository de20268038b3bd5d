// Binary glTF 2.0 (.glb): one buffer holding float32 POSITION (with the min/max the
// specification requires), float32 NORMAL, float32 TEXCOORD_0 and uint32 indices (and a PNG
// base-colour texture in a PBR material), one mesh, one node, one scene. The
// writer makes the JSON chunk with nlohmann-json (the bytes tinygltf's writer gives, keys sorted)
// and streams the binary chunk straight from the mesh's arrays: no copy of the mesh, so writing
// needs no more memory than the mesh itself. The reader (tinygltf) takes every triangle primitive
// (lists, strips, fans) of the default scene with the node transforms applied, checking every
// accessor against its buffer so a corrupt file fails with a message instead of reading out of
// bounds.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/error.hpp"
#include "io/binary_file.hpp"
#include "io/gltf_model.hpp"
#include "io/mesh_formats.hpp"

namespace sansui::io::detail {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF buffers are little-endian: this platform needs byte swapping in gltf.cpp");

// ---- reading ---------------------------------------------------------------------------------

/// Bounds-checked access to the elements of one accessor (checked by accessor_bytes).
class AccessorReader {
 public:
  AccessorReader(const std::filesystem::path& path, const tinygltf::Model& model, int index, std::string_view what)
      : bytes_(accessor_bytes(path, model, index, what)) {}

  std::size_t count() const { return bytes_.count; }
  int component_type() const { return bytes_.component_type; }
  int components() const { return bytes_.components; }

  glm::vec3 vec3(std::size_t i) const {
    glm::vec3 value;
    std::memcpy(&value[0], bytes_.base + i * bytes_.stride, 12);
    return value;
  }
  std::uint32_t index(std::size_t i) const {
    const unsigned char* at = bytes_.base + i * bytes_.stride;
    switch (bytes_.component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return at[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t value;
        std::memcpy(&value, at, 2);
        return value;
      }
      default: {
        std::uint32_t value;
        std::memcpy(&value, at, 4);
        return value;
      }
    }
  }

 private:
  AccessorBytes bytes_;
};

}  // namespace

glm::mat4 gltf_local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 matrix;
    std::memcpy(glm::value_ptr(matrix), node.matrix.data(), sizeof matrix);  // both column-major
    return glm::mat4(matrix);
  }
  glm::dmat4 transform(1.0);
  if (node.translation.size() == 3) transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
  if (node.rotation.size() == 4) {
    const auto& q = node.rotation;  // glTF stores x, y, z, w
    transform *= glm::mat4_cast(glm::dquat(q[3], q[0], q[1], q[2]));
  }
  if (node.scale.size() == 3) transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
  return glm::mat4(transform);
}

namespace {

/// Appends the triangles of one primitive, transformed to world space.
void add_primitive(const std::filesystem::path& path, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                   const glm::mat4& transform, TriangleMesh& mesh, bool& all_normals) {
  const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
    return;  // points and lines are not surfaces
  const auto position_attribute = primitive.attributes.find("POSITION");
  if (position_attribute == primitive.attributes.end()) fail("cannot read {}: a primitive has no POSITION", path.string());
  const AccessorReader positions(path, model, position_attribute->second, "POSITION");
  if (positions.component_type() != TINYGLTF_COMPONENT_TYPE_FLOAT || positions.components() != 3)
    fail("cannot read {}: POSITION must be float32 VEC3 (quantised positions are not supported)", path.string());
  std::optional<AccessorReader> normals;
  if (const auto found = primitive.attributes.find("NORMAL"); found != primitive.attributes.end()) {
    normals.emplace(path, model, found->second, "NORMAL");
    if (normals->component_type() != TINYGLTF_COMPONENT_TYPE_FLOAT || normals->components() != 3 || normals->count() != positions.count())
      fail("cannot read {}: NORMAL must be float32 VEC3, one per position", path.string());
  }
  all_normals &= normals.has_value();

  // The primitive's corner list, then triangles from it by mode.
  std::vector<std::uint32_t> corners;
  if (primitive.indices >= 0) {
    const AccessorReader indices(path, model, primitive.indices, "indices");
    if (indices.components() != 1 || (indices.component_type() != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                      indices.component_type() != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                      indices.component_type() != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail("cannot read {}: indices must be unsigned 8, 16 or 32-bit scalars", path.string());
    corners.resize(indices.count());
    for (std::size_t i = 0; i < corners.size(); ++i) {
      corners[i] = indices.index(i);
      if (corners[i] >= positions.count())
        fail("cannot read {}: index {} refers to vertex {} of {}", path.string(), i, corners[i], positions.count());
    }
  } else {
    corners.resize(positions.count());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<std::uint32_t>(i);
  }

  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  const bool identity = transform == glm::mat4(1.0f);  // then values pass through bit for bit
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (std::size_t i = 0; i < positions.count(); ++i) {
    const glm::vec3 position = positions.vec3(i);
    mesh.positions.push_back(identity ? position : glm::vec3(transform * glm::vec4(position, 1.0f)));
    if (normals) mesh.normals.push_back(identity ? normals->vec3(i) : glm::normalize(normal_matrix * normals->vec3(i)));
  }
  const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {base + a, base + b, base + c});
  };
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3) add(corners[i], corners[i + 1], corners[i + 2]);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < corners.size(); ++i)  // every other triangle flips to keep the winding
      i % 2 == 0 ? add(corners[i], corners[i + 1], corners[i + 2]) : add(corners[i + 1], corners[i], corners[i + 2]);
  } else {
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) add(corners[0], corners[i], corners[i + 1]);
  }
}

}  // namespace

void write_glb(const std::filesystem::path& temporary, const std::filesystem::path& target, const TriangleMesh& mesh,
               const MeshBounds& bounds, const std::vector<unsigned char>& base_color_png, const std::string& name) {
  // The binary chunk's layout: positions, normals, colours, texture coordinates, indices, the
  // base-colour PNG; each 4-byte aligned (the PNG padded with zeros).
  const std::size_t vertex_bytes = mesh.positions.size() * sizeof(glm::vec3);
  const std::size_t normal_bytes = mesh.normals.size() * sizeof(glm::vec3);
  const std::size_t color_bytes = mesh.colors.size() * sizeof(glm::vec3);
  const std::size_t uv_bytes = mesh.uvs.size() * sizeof(glm::vec2);
  const std::size_t index_bytes = mesh.indices.size() * sizeof(std::uint32_t);
  const bool textured = !base_color_png.empty() && !mesh.uvs.empty() && mesh.colors.empty();
  const std::size_t png_bytes = textured ? (base_color_png.size() + 3) / 4 * 4 : 0;
  const std::size_t bin_bytes = vertex_bytes + normal_bytes + color_bytes + uv_bytes + index_bytes + png_bytes;

  nlohmann::json accessors = nlohmann::json::array(), views = nlohmann::json::array(), attributes = nlohmann::json::object();
  std::size_t offset = 0;
  const auto add = [&](std::size_t bytes, int target_kind, int component_type, const char* type, std::size_t count) {
    nlohmann::json view = {{"buffer", 0}, {"byteLength", bytes}, {"target", target_kind}};
    if (offset > 0) view["byteOffset"] = offset;
    views.push_back(std::move(view));
    offset += bytes;
    accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", component_type}, {"count", count}, {"type", type}});
    return accessors.size() - 1;
  };
  const std::size_t positions =
      add(vertex_bytes, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC3", mesh.positions.size());
  // As doubles, as glTF readers and tinygltf's writer give them.
  accessors[positions]["min"] = {double{bounds.low.x}, double{bounds.low.y}, double{bounds.low.z}};
  accessors[positions]["max"] = {double{bounds.high.x}, double{bounds.high.y}, double{bounds.high.z}};
  attributes["POSITION"] = positions;
  if (!mesh.normals.empty())
    attributes["NORMAL"] = add(normal_bytes, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC3", mesh.normals.size());
  nlohmann::json primitive = {{"mode", TINYGLTF_MODE_TRIANGLES}};
  nlohmann::json model = {{"asset", {{"generator", "Sansui " SANSUI_VERSION}, {"version", "2.0"}}}};
  if (!mesh.colors.empty()) {
    // glTF's vertex colours are linear; ours are sRGB. A coloured mesh (a plant) has leaf cards
    // seen from both sides: its material is double-sided.
    attributes["COLOR_0"] = add(color_bytes, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC3", mesh.colors.size());
    model["materials"] = {
        {{"name", "vertex colours"}, {"doubleSided", true}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}}}};
    primitive["material"] = 0;
  }
  if (!mesh.uvs.empty())
    attributes["TEXCOORD_0"] = add(uv_bytes, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC2", mesh.uvs.size());
  primitive["indices"] =
      add(index_bytes, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "SCALAR", mesh.indices.size());
  if (textured) {
    // The terrain's colours as a PBR material: the texture as base colour, rough and not metal.
    views.push_back({{"buffer", 0}, {"byteLength", base_color_png.size()}, {"byteOffset", offset}});
    offset += png_bytes;
    model["images"] = {{{"bufferView", views.size() - 1}, {"mimeType", "image/png"}, {"name", "base colour"}}};
    model["samplers"] = {{{"magFilter", TINYGLTF_TEXTURE_FILTER_LINEAR},
                          {"minFilter", TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR},
                          {"wrapS", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE},
                          {"wrapT", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE}}};
    model["textures"] = {{{"sampler", 0}, {"source", 0}}};
    model["materials"] = {{{"name", "terrain"},
                           {"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", 0}, {"texCoord", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.9}}}}};
    primitive["material"] = 0;
  }
  primitive["attributes"] = std::move(attributes);
  model["accessors"] = std::move(accessors);
  model["bufferViews"] = std::move(views);
  model["buffers"] = {{{"byteLength", bin_bytes}}};
  model["meshes"] = {{{"name", name}, {"primitives", {std::move(primitive)}}}};
  model["nodes"] = {{{"mesh", 0}, {"name", name}}};
  model["scene"] = 0;
  model["scenes"] = {{{"nodes", {0}}}};

  // The container: a 12-byte header, then the JSON chunk padded with spaces and the binary chunk
  // (already a multiple of 4 bytes), each after its 8-byte length and type. Lengths are 32-bit.
  std::string json = model.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const std::uint64_t total = 12 + 8 + json.size() + 8 + bin_bytes;
  if (total > std::numeric_limits<std::uint32_t>::max())
    fail("cannot write {}: the mesh needs {} bytes, more than the 4 GiB a .glb can hold (write .obj, or a smaller mesh)", target.string(),
         total);
  const std::uint32_t header[5] = {0x46546C67u /* glTF */, 2, static_cast<std::uint32_t>(total), static_cast<std::uint32_t>(json.size()),
                                   0x4E4F534Au /* JSON */};
  const std::uint32_t bin_header[2] = {static_cast<std::uint32_t>(bin_bytes), 0x004E4942u /* BIN */};

  // The arrays go to the file straight from the mesh: no copy of it is made.
  OutputFile file(temporary, target);
  file.write(header, sizeof header);
  file.write(json);
  file.write(bin_header, sizeof bin_header);
  file.write(mesh.positions.data(), vertex_bytes);
  file.write(mesh.normals.data(), normal_bytes);
  std::vector<glm::vec3> linear;  // a block of colours at a time
  constexpr std::size_t colors_per_block = 16384;
  for (std::size_t first = 0; first < mesh.colors.size(); first += colors_per_block) {
    const auto block = std::span(mesh.colors).subspan(first, std::min(colors_per_block, mesh.colors.size() - first));
    linear.resize(block.size());
    std::ranges::transform(block, linear.begin(), [](const glm::vec3& c) {
      auto channel = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
      return glm::vec3{channel(c.r), channel(c.g), channel(c.b)};
    });
    file.write(linear.data(), linear.size() * sizeof(glm::vec3));
  }
  file.write(mesh.uvs.data(), uv_bytes);
  file.write(mesh.indices.data(), index_bytes);
  if (png_bytes > 0) {
    file.write(base_color_png.data(), base_color_png.size());
    const unsigned char zeros[3] = {0, 0, 0};
    file.write(zeros, png_bytes - base_color_png.size());
  }
  file.close();
}

TriangleMesh read_gltf(const std::filesystem::path& path, bool binary) {
  const tinygltf::Model model = load_gltf_model(path, binary);

  TriangleMesh mesh;
  bool all_normals = true;
  const auto add_mesh = [&](int index, const glm::mat4& transform) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.meshes.size())
      fail("cannot read {}: a node refers to mesh {}, which does not exist", path.string(), index);
    for (const auto& primitive : model.meshes[static_cast<std::size_t>(index)].primitives)
      add_primitive(path, model, primitive, transform, mesh, all_normals);
  };
  const int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
  if (scene < 0) {
    for (std::size_t m = 0; m < model.meshes.size(); ++m) add_mesh(static_cast<int>(m), glm::mat4(1.0f));
  } else {
    if (static_cast<std::size_t>(scene) >= model.scenes.size())
      fail("cannot read {}: the default scene {} does not exist", path.string(), scene);
    // Depth-first over the node tree; a node seen twice means a cycle or a shared child, which
    // glTF forbids, and which would otherwise loop forever.
    std::vector<bool> seen(model.nodes.size(), false);
    std::vector<std::pair<int, glm::mat4>> stack;
    for (const int root : model.scenes[static_cast<std::size_t>(scene)].nodes) stack.emplace_back(root, glm::mat4(1.0f));
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size() || seen[static_cast<std::size_t>(index)])
        fail("cannot read {}: node {} is missing or appears twice in the scene tree", path.string(), index);
      seen[static_cast<std::size_t>(index)] = true;
      const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(index)];
      const glm::mat4 transform = parent * gltf_local_transform(node);
      if (node.mesh >= 0) add_mesh(node.mesh, transform);
      for (const int child : node.children) stack.emplace_back(child, transform);
    }
  }
  if (mesh.indices.empty()) fail("cannot read {}: it has no triangles", path.string());
  if (!all_normals) mesh.normals.clear();
  return mesh;
}

}  // namespace sansui::io::detail
