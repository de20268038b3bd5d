// Texturing outputs (issue 14 item 5): heightfield meshes carry UVs over the terrain's extent and
// a PBR material with the band colours as base colour (embedded in .glb, NAME.mtl and
// NAME_basecolor.png beside an .obj); splat maps of the land's four layers whose weights sum to
// 1, with snow above the snow line and rock on steep slopes.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include "cli/cli_runner.hpp"
#include "io/heightmap_io.hpp"
#include "io/image_io.hpp"
#include "look/surface_layers.hpp"
#include "test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

tinygltf::Model load_glb(const std::filesystem::path& file) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
  return model;
}

/// The first primitive's TEXCOORD_0 as u, v pairs (none if it has no such attribute).
std::vector<float> texture_coordinates(const tinygltf::Model& model) {
  const auto& attributes = model.meshes.at(0).primitives.at(0).attributes;
  if (attributes.count("TEXCOORD_0") == 0) return {};
  const auto& accessor = model.accessors.at(static_cast<std::size_t>(attributes.at("TEXCOORD_0")));
  const auto& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  std::vector<float> uv(2 * accessor.count);
  std::memcpy(uv.data(), model.buffers.at(0).data.data() + view.byteOffset + accessor.byteOffset, uv.size() * sizeof(float));
  return uv;
}

TEST(Texturing, GlbHasMonotoneUvsInZeroOneAndAnEmbeddedBaseColourTexture) {
  const test::TempDir dir("texturing-glb");
  const auto file = dir / "t.glb";
  const auto run = test::run_cli({"terrain", "--size", "33", "--seed", "2", "-o", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const tinygltf::Model model = load_glb(file);
  const auto& primitive = model.meshes.at(0).primitives.at(0);
  ASSERT_EQ(primitive.attributes.count("TEXCOORD_0"), 1u);
  const auto& accessor = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("TEXCOORD_0")));
  EXPECT_EQ(accessor.type, TINYGLTF_TYPE_VEC2);
  EXPECT_EQ(accessor.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  const std::vector<float> uv = texture_coordinates(model);
  ASSERT_EQ(uv.size(), 2u * 33u * 33u);
  for (int j = 0; j < 33; ++j)
    for (int i = 0; i < 33; ++i) {
      const float u = uv[2 * (j * 33 + i)], v = uv[2 * (j * 33 + i) + 1];
      ASSERT_GE(u, 0.0f);
      ASSERT_LE(u, 1.0f);
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
      if (i > 0) {
        ASSERT_GT(u, uv[2 * (j * 33 + i - 1)]);  // east: u grows
      }
      if (j > 0) {
        ASSERT_GT(v, uv[2 * ((j - 1) * 33 + i) + 1]);  // south: v grows
      }
    }
  EXPECT_EQ(uv.front(), 0.0f);
  EXPECT_EQ(uv.back(), 1.0f);

  ASSERT_EQ(primitive.material, 0);
  const auto& material = model.materials.at(0);
  EXPECT_EQ(material.pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_EQ(material.pbrMetallicRoughness.metallicFactor, 0.0);
  const auto& texture = model.textures.at(0);
  const auto& image = model.images.at(static_cast<std::size_t>(texture.source));
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_EQ(image.width, 33);
  EXPECT_EQ(image.height, 33);
  EXPECT_EQ(image.image.size(), 33u * 33u * 4u);
}

TEST(Texturing, ObjNamesItsMaterialAndTextureWrittenBesideIt) {
  const test::TempDir dir("texturing-obj");
  const auto file = dir / "t.obj";
  const auto run = test::run_cli({"terrain", "--size", "17", "--seed", "2", "-o", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ASSERT_TRUE(std::filesystem::exists(dir / "t.mtl"));
  const Image texture = io::read_png(dir / "t_basecolor.png");
  EXPECT_EQ(texture.width(), 17);
  tinyobj::ObjReaderConfig config;
  config.mtl_search_path = dir.path().string();
  tinyobj::ObjReader reader;
  ASSERT_TRUE(reader.ParseFromFile(file.string(), config)) << reader.Error();
  ASSERT_EQ(reader.GetMaterials().size(), 1u);
  EXPECT_EQ(reader.GetMaterials()[0].diffuse_texname, "t_basecolor.png");
  const auto& texcoords = reader.GetAttrib().texcoords;
  ASSERT_EQ(texcoords.size(), 2u * 17u * 17u);
  for (float t : texcoords) {
    EXPECT_GE(t, 0.0f);
    EXPECT_LE(t, 1.0f);
  }
  EXPECT_GE(reader.GetShapes().at(0).mesh.indices.at(0).texcoord_index, 0);
}

/// Output of a shell command (stderr too); fails the test on a non-zero exit.
std::string command_output(const std::string& command, const std::filesystem::path& dir) {
  const auto out = dir / "command.txt";
  const int status = std::system((command + " > '" + out.string() + "' 2>&1").c_str());
  EXPECT_EQ(status, 0) << command << "\n" << test::read_text(out);
  return test::read_text(out);
}

bool have_assimp() {
  if (std::system("command -v assimp > /dev/null 2>&1") == 0) return true;
  if (std::getenv("CI") != nullptr) ADD_FAILURE() << "assimp is not installed (scripts/setup --test installs assimp-utils)";
  return false;
}

TEST(Texturing, GlbAccessorsHaveTheirBoundsAndUvsSpanTheTexture) {
  const test::TempDir dir("texturing-bounds");
  const auto file = dir / "t.glb";
  ASSERT_EQ(test::run_cli({"terrain", "--size", "33", "--seed", "3", "--cell", "5", "-o", file.string()}).exit_code, 0);
  const tinygltf::Model model = load_glb(file);
  const auto& primitive = model.meshes.at(0).primitives.at(0);
  // glTF requires min and max on POSITION; they must hold the data's real bounds.
  const auto& position = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION")));
  ASSERT_EQ(position.minValues.size(), 3u);
  ASSERT_EQ(position.maxValues.size(), 3u);
  EXPECT_EQ(position.minValues[0], 0.0);
  EXPECT_EQ(position.maxValues[0], 160.0);  // 32 cells of 5 m
  EXPECT_EQ(position.maxValues[2], 160.0);
  const auto& uv = model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("TEXCOORD_0")));
  for (const auto& accessor : {position, uv}) {
    const auto& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
    EXPECT_LE(accessor.byteOffset + accessor.count * (accessor.type == TINYGLTF_TYPE_VEC3 ? 12u : 8u), view.byteLength);
    EXPECT_LE(view.byteOffset + view.byteLength, model.buffers.at(0).data.size());
  }
  const auto& indices = model.accessors.at(static_cast<std::size_t>(primitive.indices));
  EXPECT_EQ(indices.count, 32u * 32u * 6u);
}

TEST(Texturing, AssimpLoadsTheGlbAndObjWithTheirMaterialAndTexture) {
  if (!have_assimp()) GTEST_SKIP() << "assimp is not installed";
  const test::TempDir dir("texturing-assimp");
  ASSERT_EQ(test::run_cli({"terrain", "--size", "65", "-o", (dir / "t.glb").string(), "-o", (dir / "t.obj").string()}).exit_code, 0);
  const std::string glb = command_output("assimp info '" + (dir / "t.glb").string() + "'", dir.path());
  EXPECT_THAT(glb, ::testing::ContainsRegex("Meshes: +1\n"));
  EXPECT_THAT(glb, ::testing::ContainsRegex("Faces: +8192\n"));
  EXPECT_THAT(glb, ::testing::ContainsRegex("Textures \\(embed.\\): +1\n"));
  EXPECT_THAT(glb, HasSubstr("| BaseColor]"));
  const std::string obj = command_output("cd '" + dir.path().string() + "' && assimp info t.obj", dir.path());
  EXPECT_THAT(obj, ::testing::ContainsRegex("Faces: +8192\n"));
  EXPECT_THAT(obj, HasSubstr("'t_basecolor.png'"));
  // Re-exported by assimp, the UVs survive: the glb's texture coordinates are real data.
  command_output("assimp export '" + (dir / "t.glb").string() + "' '" + (dir / "again.obj").string() + "'", dir.path());
  EXPECT_THAT(test::read_text(dir / "again.obj"), HasSubstr("\nvt "));
}

TEST(Texturing, SubdividedMeshesAreDrapedWithTheirDemsBandColours) {
  const test::TempDir dir("texturing-subdivide");
  const auto file = dir / "p.glb";
  const auto run = test::run_cli({"subdivide", "--pyramid", "1000,600", "--steps", "3", "--no-measure", "-o", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const tinygltf::Model model = load_glb(file);
  const auto& primitive = model.meshes.at(0).primitives.at(0);
  const std::vector<float> uv = texture_coordinates(model);
  ASSERT_FALSE(uv.empty());
  float low[2] = {1.0f, 1.0f}, high[2] = {0.0f, 0.0f};
  for (std::size_t i = 0; i < uv.size(); ++i) {
    low[i % 2] = std::min(low[i % 2], uv[i]);
    high[i % 2] = std::max(high[i % 2], uv[i]);
  }
  // Over the footprint's extent seen from above: 0 to 1 along its longer side.
  EXPECT_GE(std::min(low[0], low[1]), 0.0f);
  EXPECT_LE(std::max(high[0], high[1]), 1.0f);
  EXPECT_EQ(std::max(high[0] - low[0], high[1] - low[1]), 1.0f);
  ASSERT_EQ(primitive.material, 0);
  EXPECT_EQ(model.materials.at(0).pbrMetallicRoughness.baseColorTexture.index, 0);
  EXPECT_GT(model.images.at(0).width, 1);
}

TEST(Texturing, SplatWeightsSumToOneWithSnowUpHighAndRockOnSteepSlopes) {
  // A ramp up to 3000 m with a cliff: sand at the coast, grass low, snow on the gentle top,
  // rock on the cliff.
  Heightfield heights(200, 3, 0.0f, 100.0);  // 100 m cells: the ramps are 6, 56 and 3 degrees
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 200; ++x) {
      const auto fx = static_cast<float>(x);
      heights(x, y) = x < 100 ? 1.0f + 10.0f * fx : (x < 110 ? 1000.0f + 150.0f * (fx - 100) : 2500.0f + 5.0f * (fx - 110));
    }
  const look::RenderParams look = look::with_fallbacks({});
  const look::SurfaceWeights w = look::surface_weights(heights, look);
  for (int x = 0; x < 200; ++x) {
    const float sum = w.sand(x, 1) + w.grass(x, 1) + w.rock(x, 1) + w.snow(x, 1);
    ASSERT_NEAR(sum, 1.0f, 1e-5f) << x;
  }
  EXPECT_GT(w.sand(0, 1), 0.9f);    // 1 m above the sea: beach
  EXPECT_GT(w.grass(30, 1), 0.9f);  // 300 m of 2945: forest
  EXPECT_GT(w.rock(105, 1), 0.9f);  // 150 m per 100 m cell: a cliff
  EXPECT_GT(w.snow(199, 1), 0.9f);  // the gentle top above the snow line
  EXPECT_LT(w.snow(105, 1), 0.1f);  // no snow on the cliff

  // Through the CLI: the RGBA bytes sum to 255 at every pixel, and the sidecar gives the grid.
  const test::TempDir dir("texturing-splat");
  const auto file = dir / "s.png";
  const auto run =
      test::run_cli({"terrain", "--size", "65", "--seed", "5", "--sigma", "2500", "--cell", "200", "--splat-map", file.string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Image splat = io::read_png(file);
  ASSERT_EQ(splat.width(), 65);
  int snowy = 0;
  for (const Rgba8& p : splat.values()) {
    ASSERT_EQ(p.r + p.g + p.b + p.a, 255);
    snowy += p.a > 128;
  }
  EXPECT_GT(snowy, 0);
  std::ifstream in(io::sidecar_path(file));
  const nlohmann::json sidecar = nlohmann::json::parse(in);
  EXPECT_EQ(sidecar.at("cell_size_m").get<double>(), 200.0);
  EXPECT_THAT(sidecar.at("/layers/a"_json_pointer).get<std::string>(), HasSubstr("snow"));
}

}  // namespace
}  // namespace sansui
