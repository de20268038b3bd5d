// End-to-end tests of `sansui subdivide`: outputs, determinism, order independence, locks,
// the memory limit and every bad input.
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "io/heightmap_io.hpp"
#include "io/mesh_io.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

const std::string example_sketch = std::string(sansui::test::source_dir) + "/examples/sketches/mountain80.geojson";
const std::string example_mesh = std::string(sansui::test::source_dir) + "/examples/meshes/mountain80.obj";

std::uint64_t file_hash(const std::filesystem::path& path) {
  const std::string bytes = read_text(path);
  return fnv1a(bytes.data(), bytes.size());
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(SubdivideCli, ExampleMeshGivesMeshDemSidecarsAndStatistics) {
  TempDir dir("subdivide-outputs");
  const CliResult r =
      run_cli({"subdivide", example_mesh, "--steps", "3", "-o", (dir / "m.obj").string(), "-o", (dir / "m.glb").string(), "--dem",
               (dir / "m.r32").string(), "--dem", (dir / "m.png").string(), "--dem-size", "257", "--preview", (dir / "look.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("   3  "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5120"), std::string::npos) << r.out;  // 80 * 4^3 triangles
  EXPECT_NE(r.out.find("stopped by steps"), std::string::npos);
  EXPECT_NE(r.out.find("roughness: not measured"), std::string::npos);
  const TriangleMesh mesh = io::read_mesh(dir / "m.obj");
  EXPECT_EQ(mesh.triangle_count(), 5120u);
  EXPECT_EQ(io::read_mesh(dir / "m.glb").triangle_count(), 5120u);
  const Heightfield dem = io::read_heightmap(dir / "m.r32");
  EXPECT_EQ(dem.width(), 257);
  EXPECT_EQ(dem.height(), 257);
  float highest = -1e9f;
  for (float v : dem.values()) highest = std::max(highest, v);
  EXPECT_NEAR(highest, 1400.0f, 100.0f);  // the drawn peak, roughened
  EXPECT_TRUE(std::filesystem::exists(dir / "look.png"));
  const std::string sidecar = read_text(dir / "m.r32.json");
  for (const char* key : {"\"h\"", "\"roughness\"", "\"s0_m\"", "\"statistics\"", "\"triangles\"", "\"cell_size_m\""})
    EXPECT_NE(sidecar.find(key), std::string::npos) << key;
}

TEST(SubdivideCli, MeasuresTheFractalDimensionFromSevenSteps) {
  TempDir dir("subdivide-measure");
  const CliResult r = run_cli({"subdivide", "--pyramid", "1000,500", "--steps", "7", "--direction", "vertical", "--dem",
                               (dir / "p.r32").string(), "--dem-size", "65"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("roughness: asked h 0.800 (fractal dimension 2.200); measured H 0."), std::string::npos) << r.out;
  EXPECT_NE(read_text(dir / "p.r32.json").find("\"measured_fractal_dimension\""), std::string::npos);
}

TEST(SubdivideCli, SameBytesAcrossRunsThreadsAndInputOrder) {
  TempDir dir("subdivide-determinism");
  // The example with its vertices renumbered and its triangles shuffled and rotated.
  const TriangleMesh example = io::read_mesh(example_mesh);
  std::string shuffled;
  const std::size_t v = example.positions.size();
  for (std::size_t k = 0; k < v; ++k) {
    const glm::vec3 p = example.positions[(k * 7 + 3) % v];  // 7 is prime to 45
    shuffled += fmt::format("v {} {} {}\n", p.x, p.y, p.z);
  }
  std::vector<std::uint32_t> new_index(v);
  for (std::size_t k = 0; k < v; ++k) new_index[(k * 7 + 3) % v] = std::uint32_t(k + 1);
  for (std::size_t t = example.triangle_count(); t-- > 0;) {
    const std::uint32_t* c = &example.indices[3 * t];
    shuffled += fmt::format("f {} {} {}\n", new_index[c[t % 3]], new_index[c[(t + 1) % 3]], new_index[c[(t + 2) % 3]]);
  }
  write_text(dir / "shuffled.obj", shuffled);

  auto run = [&](const std::string& input, const std::string& name, const std::string& threads) {
    const CliResult r = run_cli({"--threads", threads, "subdivide", input, "--steps", "4", "--seed", "9", "-o",
                                 (dir / (name + ".glb")).string(), "--dem", (dir / (name + ".r32")).string(), "--dem-size", "129"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
  };
  run(example_mesh, "a", "0");
  run(example_mesh, "b", "1");
  run(example_mesh, "c", "2");
  run((dir / "shuffled.obj").string(), "d", "2");
  for (const char* name : {"b", "c", "d"}) {
    EXPECT_EQ(file_hash(dir / "a.glb"), file_hash(dir / (std::string(name) + ".glb"))) << name;
    EXPECT_EQ(file_hash(dir / "a.r32"), file_hash(dir / (std::string(name) + ".r32"))) << name;
  }
}

TEST(SubdivideCli, RedObjVerticesAreLocked) {
  TempDir dir("subdivide-locks");
  write_text(dir / "locked.obj",
             "v 0 0 0 1 0 0\nv 100 0 0\nv 100 0 100\nv 0 0 100 1 0 0\nv 50 30 50 1 0 0\n"
             "f 1 4 5\nf 4 3 5\nf 3 2 5\nf 2 1 5\n");
  const CliResult r = run_cli({"subdivide", (dir / "locked.obj").string(), "--steps", "3", "-o", (dir / "out.obj").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("3 locked vertices"), std::string::npos) << r.out;
  // The edges between locked corners stayed on their lines: every output vertex on the line
  // from (0,0,0) to (50,30,50) or from (0,0,100) to (50,30,50) lies exactly on it.
  const TriangleMesh out = io::read_mesh(dir / "out.obj");
  int on_first = 0;
  for (glm::vec3 p : out.positions)
    if (p.x == p.z && p.x > 0 && p.x < 50) {
      ++on_first;
      EXPECT_FLOAT_EQ(p.y, 0.6f * p.x);
    }
  EXPECT_EQ(on_first, 7);  // 2^3 - 1 midpoints
}

TEST(SubdivideCli, RefusesTooManyTrianglesUnlessForced) {
  TempDir dir("subdivide-limit");
  const CliResult big = run_cli({"subdivide", "--pyramid", "100,50", "--steps", "14", "-o", (dir / "p.obj").string()});
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_NE(big.err.find("14 steps would make 1073741824 triangles (about 150.3 GB), over the limit of 50000000"), std::string::npos)
      << big.err;
  const CliResult small =
      run_cli({"subdivide", "--pyramid", "100,50", "--steps", "5", "--max-triangles", "1000", "-o", (dir / "p.obj").string()});
  EXPECT_EQ(small.exit_code, 2);
  EXPECT_NE(small.err.find("5 steps would make 4096 triangles"), std::string::npos) << small.err;
  EXPECT_TRUE(files_in(dir.path()).empty());
  const CliResult forced =
      run_cli({"subdivide", "--pyramid", "100,50", "--steps", "5", "--max-triangles", "1000", "--force", "-o", (dir / "p.obj").string()});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(io::read_mesh(dir / "p.obj").triangle_count(), 4096u);
  const CliResult tiny = run_cli({"subdivide", "--pyramid", "100,50", "--min-edge", "0.0001", "-o", (dir / "q.obj").string()});
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_NE(tiny.err.find("min-edge 0.0001 m would need at least 20 steps and"), std::string::npos) << tiny.err;
}

TEST(SubdivideCli, MinEdgeStopsWhenEveryEdgeIsShorter) {
  TempDir dir("subdivide-min-edge");
  const CliResult r = run_cli({"subdivide", "--pyramid", "1000,500", "--min-edge", "40", "-o", (dir / "p.glb").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("stopped by min-edge"), std::string::npos) << r.out;
}

struct BadInput {
  std::vector<std::string> args;
  std::string message;  // part of the one-line message
};

class SubdivideCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SubdivideCliBadInput, IsRejectedWithExitTwoAMessageAndNoFile) {
  TempDir inputs("subdivide-bad-inputs"), dir("subdivide-bad");
  write_text(inputs / "fin.obj", "v 0 0 0\nv 10 0 0\nv 0 0 10\nv 0 10 0\nv 0 -10 0\nf 1 2 3\nf 1 2 4\nf 1 2 5\n");
  write_text(inputs / "flat.obj", "v 0 0 0\nv 10 0 0\nv 20 0 0\nv 0 0 10\nf 1 2 3\nf 1 2 4\n");
  write_text(inputs / "twice.obj", "v 0 0 0\nv 10 0 0\nv 0 0 10\nf 1 2 3\nf 1 3 2\n");
  write_text(inputs / "empty.obj", "v 0 0 0\nv 10 0 0\nv 0 0 10\n");
  write_text(inputs / "infinite.obj", "v 1e39 0 0\nv 10 0 0\nv 0 0 10\nf 1 2 3\n");  // 1e39 overflows float
  write_text(inputs / "cross.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"height": 100}, "geometry": {"type": "LineString", "coordinates": [[0, 0], [100, 100]]}},
    {"type": "Feature", "properties": {"height": 50}, "geometry": {"type": "LineString", "coordinates": [[0, 100], [100, 0]]}}]})");
  write_text(inputs / "noheight.geojson", R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {}, "geometry": {"type": "LineString", "coordinates": [[0, 0], [100, 100]]}}]})");
  std::vector<std::string> args = {"subdivide"};
  for (const auto& arg : GetParam().args) {
    if (arg.starts_with("IN/"))
      args.push_back((inputs / arg.substr(3)).string());
    else if (arg.starts_with("OUT"))
      args.push_back((dir / "out").string() + arg.substr(3));
    else
      args.push_back(arg);
  }
  if (std::ranges::find(GetParam().args, "-o") == GetParam().args.end() &&
      std::ranges::find(GetParam().args, "--dem") == GetParam().args.end()) {
    args.push_back("-o");
    args.push_back((dir / "out.obj").string());
    args.push_back("--dem");
    args.push_back((dir / "out.png").string());
  }
  expect_rejected(run_cli(args), GetParam().message, dir.path());
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SubdivideCliBadInput,
    ::testing::Values(
        BadInput{{"IN/fin.obj"}, "is shared by 3 triangles"},
        BadInput{{"IN/flat.obj"}, "triangle 1 of the input (counting from 1) has zero area"},
        BadInput{{"IN/twice.obj"}, "have the same three corners"}, BadInput{{"IN/empty.obj"}, "it has no faces"},
        BadInput{{"IN/infinite.obj"}, "vertex 1 of the input (counting from 1) has a coordinate that is not a finite number"},
        BadInput{{"IN/missing.obj"}, "missing.obj"}, BadInput{{"IN/fin.stl"}, "unknown extension '.stl'"},
        BadInput{{"--sketch", "IN/cross.geojson"}, "cross or touch at (east 50, north 50)"},
        BadInput{{"--sketch", "IN/noheight.geojson"}, "feature 1 has no height"},
        BadInput{{"--sketch", "IN/missing.geojson"}, "missing.geojson: No such file or directory"},
        BadInput{{"--pyramid", "100"}, "--pyramid 100 is not allowed: it must be 2 numbers, each > 0 and <= 10000000 m"},
        BadInput{{"--pyramid", "-1,5"}, "--pyramid -1,5 is not allowed"}, BadInput{{}, "give exactly one input"},
        BadInput{{"--pyramid", "10,5", "--sketch", "IN/cross.geojson"}, "give exactly one input"},
        BadInput{{"--pyramid", "10,5", "--h", "0"}, "--h 0 is not allowed: it must be > 0 and <= 1"},
        BadInput{{"--pyramid", "10,5", "--h", "1.5"}, "--h 1.5 is not allowed"},
        BadInput{{"--pyramid", "10,5", "--h", "nan"}, "--h nan is not allowed"},
        BadInput{{"--pyramid", "10,5", "--roughness", "-1"}, "--roughness -1 is not allowed: it must be between 0 and 100"},
        BadInput{{"--pyramid", "10,5", "--min-edge", "0"}, "--min-edge 0 is not allowed: it must be > 0 and <= 10000000 m"},
        BadInput{{"--pyramid", "10,5", "--min-edge", "-3"}, "--min-edge -3 is not allowed"},
        BadInput{{"--pyramid", "10,5", "--steps", "-1"}, "--steps -1 is not allowed: it must be between 0 and 30"},
        BadInput{{"--pyramid", "10,5", "--boundary", "sideways"},
                 "--boundary 'sideways' is not allowed: it must be one of free, vertical, fixed"},
        BadInput{{"--pyramid", "10,5", "--direction", "up"}, "--direction 'up' is not allowed: it must be one of normal, vertical"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.png", "--cell", "0"}, "--dem-cell 0 is not allowed: it must be > 0 and <= 10000000 m"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.png", "--dem-size", "1"},
                 "--dem-size 1 is not allowed: it must be between 2 and 65537"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.png", "--cell", "1", "--dem-size", "65"}, "give dem.size or dem.cell, not both"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.png", "--cell", "0.00001"}, "give a larger cell size"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.png", "--range", "5,1"},
                 "--range 5,1 is not allowed: it must be MIN,MAX with MIN below MAX"},
        BadInput{{"--pyramid", "10,5", "-o", "OUT.stl"}, "has the extension '.stl': allowed are .obj .glb"},
        BadInput{{"--pyramid", "10,5", "--dem", "OUT.jpg"}, "has the extension '.jpg': allowed are .png .raw .r16 .r32 .tif .tiff"},
        BadInput{{"--pyramid", "10,5", "--preview", "OUT.tif"}, "has the extension '.tif': allowed are .png"},
        BadInput{{"--pyramid", "10,5", "-o", "/no/such/dir/x.obj"}, "/no/such/dir"},
        BadInput{{"--pyramid", "10,5", "--no-such-option"}, "no-such-option"}));

TEST(SubdivideCli, NoOutputIsAnError) {
  const CliResult r = run_cli({"subdivide", "--pyramid", "10,5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no output"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace sansui::test
