#include "io/vertex_locks.hpp"

#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "core/error.hpp"
#include "test_util.hpp"

namespace sansui::io {
namespace {

using ::testing::HasSubstr;

TEST(VertexLocks, RedObjVertexColoursAreLocked) {
  test::TempDir dir("locks-obj");
  std::ofstream(dir / "m.obj") << "v 0 0 0 1 0 0\nv 10 0 0 1 1 1\nv 10 5 10 0.9 0.1 0.2\nv 0 0 10 0 0 1\nf 1 2 3\nf 1 3 4\n";
  const std::vector<glm::vec3> locked = read_locked_positions(dir / "m.obj");
  ASSERT_EQ(locked.size(), 2u);
  EXPECT_EQ(locked[0], glm::vec3(0, 0, 0));
  EXPECT_EQ(locked[1], glm::vec3(10, 5, 10));
  // Matched by position, whatever the mesh reader's numbering and copies.
  TriangleMesh mesh;
  mesh.positions = {{10, 5, 10}, {0, 0, 10}, {0, 0, 0}, {10, 5, 10}, {-0.0f, 0, 0}};
  EXPECT_EQ(lock_flags_for(mesh, locked), (std::vector<std::uint8_t>{1, 0, 1, 1, 1}));

  std::ofstream(dir / "plain.obj") << "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n";
  EXPECT_TRUE(read_locked_positions(dir / "plain.obj").empty());
}

TEST(VertexLocks, GltfLockAttributeInWorldPositions) {
  test::TempDir dir("locks-gltf");
  tinygltf::Model model;
  const float positions[] = {0, 0, 0, 10, 0, 0, 0, 0, 10};
  const unsigned char locks[] = {0, 1, 0, 0};  // padded to 4 bytes
  tinygltf::Buffer buffer;
  buffer.data.resize(sizeof positions + sizeof locks);
  std::memcpy(buffer.data.data(), positions, sizeof positions);
  std::memcpy(buffer.data.data() + sizeof positions, locks, sizeof locks);
  model.buffers.push_back(buffer);
  tinygltf::BufferView position_view, lock_view;
  position_view.buffer = 0, position_view.byteOffset = 0, position_view.byteLength = sizeof positions;
  lock_view.buffer = 0, lock_view.byteOffset = sizeof positions, lock_view.byteLength = 3;
  model.bufferViews = {position_view, lock_view};
  tinygltf::Accessor position_accessor, lock_accessor;
  position_accessor.bufferView = 0, position_accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  position_accessor.count = 3, position_accessor.type = TINYGLTF_TYPE_VEC3;
  position_accessor.minValues = {0, 0, 0}, position_accessor.maxValues = {10, 0, 10};
  lock_accessor.bufferView = 1, lock_accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  lock_accessor.count = 3, lock_accessor.type = TINYGLTF_TYPE_SCALAR;
  model.accessors = {position_accessor, lock_accessor};
  tinygltf::Primitive primitive;
  primitive.attributes = {{"POSITION", 0}, {"_LOCK", 1}};
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.primitives = {primitive};
  model.meshes = {mesh};
  tinygltf::Node node;
  node.mesh = 0;
  node.translation = {100, 0, 0};
  model.nodes = {node};
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes = {scene};
  model.defaultScene = 0;
  model.asset.version = "2.0";
  ASSERT_TRUE(tinygltf::TinyGLTF().WriteGltfSceneToFile(&model, (dir / "m.glb").string(), true, true, false, true));
  const std::vector<glm::vec3> locked = read_locked_positions(dir / "m.glb");
  ASSERT_EQ(locked.size(), 1u);
  EXPECT_EQ(locked[0], glm::vec3(110, 0, 0));
}

TEST(VertexLocks, BadFilesAreRefusedWithAMessage) {
  auto error = [](const std::filesystem::path& path) {
    try {
      read_locked_positions(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(error("/nonexistent/m.obj"), HasSubstr("cannot read /nonexistent/m.obj: No such file or directory"));
  EXPECT_THAT(error("/nonexistent/m.glb"), HasSubstr("cannot read /nonexistent/m.glb: No such file or directory"));
  EXPECT_THAT(error("m.stl"), HasSubstr("mesh m.stl has an unknown extension '.stl': allowed are .obj .glb .gltf"));
}

}  // namespace
}  // namespace sansui::io
