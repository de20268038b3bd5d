// OBJ and binary glTF meshes: round trips through read_mesh and through tinyobjloader/tinygltf
// directly, the GLB container, sidecars, node transforms and strips when reading, bad input.
#include "io/mesh_io.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include <glm/common.hpp>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "mesh/heightfield_mesh.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TriangleMesh sample_mesh() {
  Heightfield heights = test::sample_heights(17, 9, 11);
  heights.origin_x_m = -80.0;
  heights.origin_y_m = 40.0;
  return mesh::heightfield_to_mesh(heights);
}

/// Bytes as base64, for glTF buffers embedded as data: URIs.
std::string base64_of(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string base64;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned triple = 0;
    for (std::size_t k = 0; k < 3; ++k) triple = triple << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) base64 += k <= n ? alphabet[(triple >> (18 - 6 * k)) & 63] : '=';
  }
  return base64;
}

/// A .gltf of one triangle (three float VEC3 positions in a 36-byte buffer, embedded), with
/// `accessor` and `view` merged into its accessor and buffer view.
nlohmann::json triangle_gltf(const nlohmann::json& accessor, const nlohmann::json& view) {
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}},
                         {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                         {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
                         {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                         {"buffers",
                          {{{"byteLength", 36},
                            {"uri", "data:application/octet-stream;base64," +
                                        base64_of(std::string(reinterpret_cast<const char*>(positions), sizeof positions))}}}}};
  if (accessor.is_object()) gltf["accessors"][0].update(accessor);
  if (view.is_object()) gltf["bufferViews"][0].update(view);
  return gltf;
}

void expect_same_mesh(const TriangleMesh& expected, const TriangleMesh& actual) {
  ASSERT_EQ(actual.positions.size(), expected.positions.size());
  ASSERT_EQ(actual.normals.size(), expected.normals.size());
  EXPECT_EQ(actual.indices, expected.indices);
  // memcmp of empty arrays would pass null pointers (undefined behaviour, UBSan says so).
  if (!expected.positions.empty()) {
    EXPECT_EQ(0, std::memcmp(actual.positions.data(), expected.positions.data(), expected.positions.size() * 12));
  }
  if (!expected.normals.empty()) {
    EXPECT_EQ(0, std::memcmp(actual.normals.data(), expected.normals.data(), expected.normals.size() * 12));
  }
}

TEST(ObjIo, RoundTripsThroughReadMeshBitForBit) {
  test::TempDir directory("obj-round");
  const TriangleMesh mesh = sample_mesh();
  io::write_mesh(directory / "m.obj", mesh);
  expect_same_mesh(mesh, io::read_mesh(directory / "m.obj"));
}

TEST(ObjIo, RoundTripsAwkwardNumbersAndMeshesWithoutNormals) {
  test::TempDir directory("obj-awkward");
  // Shortest round-trip text for every float: large, tiny, negative zero, many digits; more
  // vertices than one formatting block of the writer (16384 lines).
  TriangleMesh mesh = mesh::heightfield_to_mesh(test::sample_heights(181, 101, 3));
  const float awkward[] = {-0.0f, 1e-30f, -3.4e38f, 123456.789f, 0.1f, 1.0f / 3.0f, 8388607.5f, -2.5e-7f};
  for (std::size_t i = 0; i < std::size(awkward); ++i) mesh.positions[i * 97] = glm::vec3(awkward[i], -awkward[i], awkward[(i + 3) % 8]);
  io::write_mesh(directory / "m.obj", mesh);
  expect_same_mesh(mesh, io::read_mesh(directory / "m.obj"));
  mesh.normals.clear();
  io::write_mesh(directory / "plain.obj", mesh);
  expect_same_mesh(mesh, io::read_mesh(directory / "plain.obj"));
}

TEST(ObjIo, TinyobjloaderReadsTheSamePositionsNormalsAndFaces) {
  test::TempDir directory("obj-tinyobj");
  const TriangleMesh mesh = sample_mesh();
  io::write_mesh(directory / "m.obj", mesh);
  tinyobj::ObjReader reader;
  ASSERT_TRUE(reader.ParseFromFile((directory / "m.obj").string()));
  const auto& attributes = reader.GetAttrib();
  ASSERT_EQ(attributes.vertices.size(), mesh.positions.size() * 3);
  ASSERT_EQ(attributes.normals.size(), mesh.normals.size() * 3);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_EQ(attributes.vertices[3 * i + 1], mesh.positions[i].y);
    EXPECT_EQ(attributes.normals[3 * i + 2], mesh.normals[i].z);
  }
  ASSERT_EQ(reader.GetShapes().size(), 1u);
  const auto& indices = reader.GetShapes()[0].mesh.indices;
  ASSERT_EQ(indices.size(), mesh.indices.size());
  for (std::size_t i = 0; i < indices.size(); ++i) {
    EXPECT_EQ(indices[i].vertex_index, static_cast<int>(mesh.indices[i]));
    EXPECT_EQ(indices[i].normal_index, static_cast<int>(mesh.indices[i]));
  }
}

TEST(ObjIo, ReadsPolygonsAndSeparateNormalIndices) {
  test::TempDir directory("obj-quads");
  // One quad with a normal shared by all corners: triangulated, one vertex per (v, vn) pair.
  test::write_text(directory / "q.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvn 0 1 0\nf 1//1 4//1 3//1 2//1\n");
  const TriangleMesh quad = io::read_mesh(directory / "q.obj");
  EXPECT_EQ(quad.triangle_count(), 2u);
  ASSERT_EQ(quad.positions.size(), 4u);
  ASSERT_EQ(quad.normals.size(), 4u);
  EXPECT_EQ(quad.normals[3], glm::vec3(0, 1, 0));
  // Without normals: positions only.
  test::write_text(directory / "t.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 3 2\n");
  const TriangleMesh plain = io::read_mesh(directory / "t.obj");
  EXPECT_EQ(plain.indices, (std::vector<std::uint32_t>{0, 2, 1}));
  EXPECT_TRUE(plain.normals.empty());
}

TEST(GlbIo, RoundTripsThroughReadMeshBitForBit) {
  test::TempDir directory("glb-round");
  const TriangleMesh mesh = sample_mesh();
  io::write_mesh(directory / "m.glb", mesh);
  expect_same_mesh(mesh, io::read_mesh(directory / "m.glb"));
}

TEST(GlbIo, TinygltfReadsPositionsWithBoundsNormalsAndUint32Indices) {
  test::TempDir directory("glb-tinygltf");
  const TriangleMesh mesh = sample_mesh();
  io::write_mesh(directory / "m.glb", mesh);
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, (directory / "m.glb").string())) << error;
  EXPECT_EQ(model.asset.version, "2.0");
  ASSERT_EQ(model.meshes.size(), 1u);
  const auto& primitive = model.meshes[0].primitives.at(0);
  EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);
  const auto& positions = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION")));
  const auto& normals = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("NORMAL")));
  const auto& indices = model.accessors.at(static_cast<std::size_t>(primitive.indices));
  EXPECT_EQ(positions.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(positions.type, TINYGLTF_TYPE_VEC3);
  EXPECT_EQ(positions.count, mesh.positions.size());
  EXPECT_EQ(normals.count, mesh.normals.size());
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(indices.count, mesh.indices.size());
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const auto& p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  EXPECT_EQ(positions.minValues, (std::vector<double>{low.x, low.y, low.z}));
  EXPECT_EQ(positions.maxValues, (std::vector<double>{high.x, high.y, high.z}));
  // The index buffer as stored.
  const auto& view = model.bufferViews.at(static_cast<std::size_t>(indices.bufferView));
  std::vector<std::uint32_t> stored(indices.count);
  std::memcpy(stored.data(), model.buffers.at(0).data.data() + view.byteOffset + indices.byteOffset, stored.size() * 4);
  EXPECT_EQ(stored, mesh.indices);
}

TEST(GlbIo, TheContainerHeaderAndChunksAreWellFormed) {
  test::TempDir directory("glb-header");
  io::write_mesh(directory / "m.glb", sample_mesh());
  const auto bytes = test::file_bytes(directory / "m.glb");
  ASSERT_GE(bytes.size(), 28u);
  const auto u32 = [&](std::size_t at) {
    std::uint32_t value;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
  };
  EXPECT_EQ(u32(0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), bytes.size());
  const std::uint32_t json_length = u32(12);
  EXPECT_EQ(u32(16), 0x4E4F534Au);  // "JSON"
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(u32(20 + json_length + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(20 + json_length + 8 + u32(20 + json_length), bytes.size());
}

/// The straightforward writer the streaming one replaced: the whole model in tinygltf, the mesh
/// copied into its buffer, written by tinygltf.
std::vector<unsigned char> tinygltf_glb(const TriangleMesh& mesh, const std::filesystem::path& path) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Sansui " SANSUI_VERSION;
  model.buffers.emplace_back();
  const auto add = [&](const auto& values, int target, int component_type, int type) {
    auto& data = model.buffers[0].data;
    const std::size_t offset = data.size(), bytes = values.size() * sizeof(values[0]);
    data.resize(offset + bytes);
    std::memcpy(data.data() + offset, values.data(), bytes);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = bytes;
    view.target = target;
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = values.size();
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
  };
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const int positions = add(mesh.positions, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
  glm::vec3 low = mesh.positions.front(), high = low;
  for (const auto& p : mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  model.accessors[static_cast<std::size_t>(positions)].minValues = {low.x, low.y, low.z};
  model.accessors[static_cast<std::size_t>(positions)].maxValues = {high.x, high.y, high.z};
  primitive.attributes["POSITION"] = positions;
  if (!mesh.normals.empty())
    primitive.attributes["NORMAL"] = add(mesh.normals, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
  if (!mesh.colors.empty()) {
    std::vector<glm::vec3> linear;
    for (const auto& c : mesh.colors) {
      auto channel = [](float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); };
      linear.emplace_back(channel(c.r), channel(c.g), channel(c.b));
    }
    primitive.attributes["COLOR_0"] = add(linear, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    tinygltf::Material material;
    material.name = "vertex colours";
    material.doubleSided = true;
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = 0.9;
    model.materials.push_back(material);
    primitive.material = 0;
  }
  if (!mesh.uvs.empty())
    primitive.attributes["TEXCOORD_0"] = add(mesh.uvs, TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2);
  primitive.indices = add(mesh.indices, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
  tinygltf::Mesh gltf_mesh;
  gltf_mesh.name = "terrain";
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "terrain";
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  EXPECT_TRUE(writer.WriteGltfSceneToFile(&model, path.string(), false, false, false, /*writeBinary=*/true));
  return test::file_bytes(path);
}

TEST(GlbIo, TheStreamedFileIsByteIdenticalToTinygltfsWriter) {
  test::TempDir directory("glb-identical");
  TriangleMesh mesh = sample_mesh();
  const auto expect_identical = [&](std::string_view what) {
    io::write_mesh(directory / "m.glb", mesh, {.sidecar = false});
    EXPECT_EQ(test::file_bytes(directory / "m.glb"), tinygltf_glb(mesh, directory / "reference.glb")) << what;
  };
  expect_identical("with normals");
  // Vertex colours (plants), in more than one block of the writer, and no normals.
  mesh = mesh::heightfield_to_mesh(test::sample_heights(181, 101, 5));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    mesh.colors.emplace_back(static_cast<float>(i % 256) / 255.0f, 0.5f, static_cast<float>(i % 7) / 6.0f);
  expect_identical("with colours");
  mesh.normals.clear();
  expect_identical("without normals");
  // And it reads back as written.
  const TriangleMesh read = io::read_mesh(directory / "m.glb");
  EXPECT_TRUE(read.normals.empty());
  EXPECT_EQ(read.indices, mesh.indices);
  EXPECT_EQ(0, std::memcmp(read.positions.data(), mesh.positions.data(), mesh.positions.size() * 12));
}

TEST(GlbIo, ReadsGltfWithNodeTransformsAndStrips) {
  test::TempDir directory("gltf-transform");
  // A strip of 4 vertices (two triangles) in a node translated by (10, 0, 0) and scaled by 2,
  // buffer embedded as base64: positions (0,0,0) (0,0,1) (1,0,0) (1,0,1).
  const float positions[12] = {0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 1};
  const std::string base64 = base64_of(std::string(reinterpret_cast<const char*>(positions), sizeof positions));
  const nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 5}}}}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 0, 1}}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}}},
      {"buffers", {{{"byteLength", 48}, {"uri", "data:application/octet-stream;base64," + base64}}}}};
  test::write_text(directory / "strip.gltf", gltf.dump());
  const TriangleMesh mesh = io::read_mesh(directory / "strip.gltf");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_EQ(mesh.positions[3], glm::vec3(12, 0, 2));
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));  // the second one flipped to keep winding
  EXPECT_TRUE(mesh.normals.empty());
}

TEST(GlbIo, AccessorsAndBufferViewsWhoseOffsetsWrapAroundAreRefused) {
  test::TempDir directory("gltf-wrap");
  test::write_text(directory / "ok.gltf", triangle_gltf({}, {}).dump());
  EXPECT_EQ(io::read_mesh(directory / "ok.gltf").positions.size(), 3u);
  // Offsets near 2^64 made offset + stride * (count - 1) + 12 wrap around to a small number, and
  // the reader read far outside the buffer.
  const std::uint64_t near_wrap = std::numeric_limits<std::uint64_t>::max() - 11;
  const std::pair<nlohmann::json, nlohmann::json> bad[] = {
      {{{"byteOffset", near_wrap}, {"count", 1}}, {}},
      {{}, {{"byteOffset", near_wrap}}},
      {{}, {{"byteLength", near_wrap}}},
      {{{"count", std::uint64_t{1} << 62}}, {{"byteStride", 12}}},
      {{{"count", 2}}, {{"byteStride", std::uint64_t{1} << 63}}},
      {{{"byteOffset", 28}}, {}},
      {{}, {{"byteOffset", 4}}},
  };
  for (const auto& [accessor, view] : bad) {
    test::write_text(directory / "bad.gltf", triangle_gltf(accessor, view).dump());
    EXPECT_THAT(test::input_error_of([&] { io::read_mesh(directory / "bad.gltf"); }),
                StartsWith("cannot read " + (directory / "bad.gltf").string()))
        << accessor << view;
  }
}

TEST(MeshIoSidecar, CarriesCountsBoundsAndProvenance) {
  test::TempDir directory("mesh-sidecar");
  const TriangleMesh mesh = sample_mesh();
  io::MeshWriteOptions options;
  options.provenance = {{"seed", 3}};
  io::write_mesh(directory / "m.glb", mesh, options);
  io::write_mesh(directory / "m.obj", mesh, {{}, false});
  EXPECT_EQ(test::files_in(directory.path()), (std::vector<std::string>{"m.glb", "m.glb.json", "m.obj"}));
  std::ifstream stream(directory / "m.glb.json");
  const nlohmann::json sidecar = nlohmann::json::parse(stream);
  EXPECT_EQ(sidecar["kind"], "mesh");
  EXPECT_EQ(sidecar["vertex_count"], mesh.positions.size());
  EXPECT_EQ(sidecar["triangle_count"], mesh.triangle_count());
  EXPECT_EQ(sidecar["units"], "m");
  EXPECT_EQ(sidecar["bounds_m"]["min"][0], -80.0);
  EXPECT_EQ(sidecar["provenance"], options.provenance);
}

TEST(MeshIoErrors, BadMeshesAreRefusedAndLeaveNoFile) {
  test::TempDir directory("mesh-bad");
  for (const char* name : {"m.obj", "m.glb"}) {
    const auto path = directory / name;
    TriangleMesh mesh = sample_mesh();
    mesh.positions[7].y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(test::input_error_of([&] { io::write_mesh(path, mesh); }),
              "cannot write " + path.string() + ": vertex 7 is not finite (NaN or infinity)");
    mesh = sample_mesh();
    mesh.indices[4] = static_cast<std::uint32_t>(mesh.positions.size());
    EXPECT_THAT(test::input_error_of([&] { io::write_mesh(path, mesh); }), HasSubstr("an index refers to vertex"));
    EXPECT_THAT(test::input_error_of([&] { io::write_mesh(path, TriangleMesh{}); }), HasSubstr("the mesh has no triangles"));
    EXPECT_THAT(test::input_error_of([&] { io::write_mesh(directory / "missing" / name, sample_mesh()); }), HasSubstr("does not exist"));
  }
  EXPECT_THAT(test::input_error_of([&] { io::write_mesh(directory / "m.stl", sample_mesh()); }),
              HasSubstr("unknown extension '.stl': meshes are .obj .glb"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST(MeshIoErrors, MissingTruncatedAndCorruptFilesAreNamed) {
  test::TempDir directory("mesh-corrupt");
  for (const char* name : {"m.obj", "m.glb", "m.gltf"}) {
    const auto path = directory / name;
    EXPECT_THAT(test::input_error_of([&] { io::read_mesh(path); }), StartsWith("cannot read " + path.string() + ": "));
    test::write_text(path, "garbage\n");
    EXPECT_THAT(test::input_error_of([&] { io::read_mesh(path); }), StartsWith("cannot read " + path.string() + ": "));
  }
  for (const char* name : {"m.obj", "m.glb"}) {
    io::write_mesh(directory / name, sample_mesh());
    test::truncate_file(directory / name, std::filesystem::file_size(directory / name) - 100);
    EXPECT_THAT(test::input_error_of([&] { io::read_mesh(directory / name); }),
                StartsWith("cannot read " + (directory / name).string() + ": "));
  }
  test::write_text(directory / "m.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  EXPECT_THAT(test::input_error_of([&] { io::read_mesh(directory / "m.obj"); }), HasSubstr("m.obj: "));
  // tinyobjloader reads a word as 0 and takes nan: both refused, naming the line.
  for (const char* bad : {"abc", "nan", "inf", "1e999"}) {
    test::write_text(directory / "m.obj", fmt::format("v 0 0 0\nv 1 0 0\nv 0 1 {}\nf 1 2 3\n", bad));
    EXPECT_THAT(test::input_error_of([&] { io::read_mesh(directory / "m.obj"); }),
                HasSubstr(fmt::format("line 3: '{}' is not a finite number", bad)));
  }
  test::write_text(directory / "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 0\nf 1//1 2//1 3//7\n");
  EXPECT_THAT(test::input_error_of([&] { io::read_mesh(directory / "m.obj"); }), HasSubstr("a face refers to normal 7 of 1"));
}

}  // namespace
}  // namespace sansui
