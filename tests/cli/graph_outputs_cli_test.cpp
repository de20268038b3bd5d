// A graph writes every output a chain writes (issue 46): heights, rivers, lakes, flow, erosion
// and deposition maps, splat map, mesh and picture, the same bytes as the chain recipe of the
// same world; erosion maps follow the erode nodes through the shaping nodes after them.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

/// The recipe's head: `top` (its keys before any table) and a small world and picture.
std::string world(const std::string& top = "") {
  return "sansui_recipe = 4\n" + top + "[world]\nsize = 129\ncell = 30.0\n[render]\nwidth = 160\nheight = 90\n";
}

/// One [[output]] table per (file, kind).
std::string outputs(const std::vector<std::pair<std::string, std::string>>& files) {
  std::string text;
  for (const auto& [file, kind] : files) text += fmt::format("[[output]]\nfile = \"{}\"\nkind = \"{}\"\n", file, kind);
  return text;
}

TEST(GraphOutputs, AGraphWritesEveryOutputOfTheChainWithTheSameBytes) {
  TempDir dir("graph-outputs");
  const std::vector<std::pair<std::string, std::string>> files{
      {"h.png", "heightmap"},     {"rivers.geojson", "rivers"},  {"lakes.geojson", "lakes"}, {"flow.png", "flow_map"},
      {"ero.png", "erosion_map"}, {"dep.png", "deposition_map"}, {"splat.png", "splat_map"}, {"t.glb", "mesh"},
      {"view.png", "render"}};
  std::ofstream(dir / "chain.toml") << world("source = \"midpoint\"\n")
                                    << "[midpoint]\nseed = 3\n[[shape]]\nstep = \"erode\"\nstage = \"young\"\n"
                                    << outputs(files);
  std::ofstream(dir / "graph.toml") << world() << "[[node]]\nid = \"hills\"\nkind = \"midpoint\"\nseed = 3\n"
                                    << "[[node]]\nid = \"worn\"\nkind = \"erode\"\ninputs = [\"hills\"]\nstage = \"young\"\n"
                                    << outputs(files);
  const CliResult chain = run_cli_line("run chain.toml --out-dir chain", dir.path());
  ASSERT_EQ(chain.exit_code, 0) << chain.err;
  const CliResult graph = run_cli_line("run graph.toml --out-dir graph", dir.path());
  ASSERT_EQ(graph.exit_code, 0) << graph.err;
  for (const auto& [file, kind] : files) {
    const std::string bytes = read_text(dir / "graph" / file);
    EXPECT_FALSE(bytes.empty()) << kind;
    EXPECT_EQ(bytes, read_text(dir / "chain" / file)) << kind << " " << file;
  }
}

// A flow map alone is made from the routing alone (no lakes, rivers or wetness): the same bytes
// as one written beside the outputs that need those.
TEST(GraphOutputs, AFlowMapAloneHasTheBytesOfOneWrittenBesideRiversAndWetness) {
  TempDir dir("flow-map-alone");
  const std::string head = world("source = \"midpoint\"\n") + "[midpoint]\nseed = 3\n[[shape]]\nstep = \"erode\"\nstage = \"young\"\n";
  std::ofstream(dir / "alone.toml") << head << outputs({{"flow.png", "flow_map"}});
  std::ofstream(dir / "beside.toml") << head
                                     << outputs({{"rivers.geojson", "rivers"}, {"flow.png", "flow_map"}, {"wet.png", "wetness_map"}});
  ASSERT_EQ(run_cli_line("run alone.toml --out-dir alone", dir.path()).exit_code, 0);
  ASSERT_EQ(run_cli_line("run beside.toml --out-dir beside", dir.path()).exit_code, 0);
  const std::string bytes = read_text(dir / "alone" / "flow.png");
  EXPECT_FALSE(bytes.empty());
  EXPECT_EQ(bytes, read_text(dir / "beside" / "flow.png"));
}

TEST(GraphOutputs, ErosionMapsAddUpOverErodeNodesThroughTheShapingNodesAfterThem) {
  TempDir dir("graph-erosion-maps");
  const std::string maps = outputs({{"h.r32", "heightmap"}, {"ero.r32", "erosion_map"}, {"dep.r32", "deposition_map"}});
  std::ofstream(dir / "chain.toml") << world("source = \"midpoint\"\n") << "[midpoint]\nseed = 5\n"
                                    << "[[shape]]\nstep = \"erode\"\nstage = \"young\"\n[[shape]]\nstep = \"erode\"\nstage = \"young\"\n"
                                    << maps;
  // The same two erosions, and a clamp after them that passes their maps on.
  std::ofstream(dir / "graph.toml") << world() << "[[node]]\nid = \"hills\"\nkind = \"midpoint\"\nseed = 5\n"
                                    << "[[node]]\nid = \"once\"\nkind = \"erode\"\ninputs = [\"hills\"]\nstage = \"young\"\n"
                                    << "[[node]]\nid = \"twice\"\nkind = \"erode\"\ninputs = [\"once\"]\nstage = \"young\"\n"
                                    << "[[node]]\nid = \"kept\"\nkind = \"clamp\"\ninputs = [\"twice\"]\nmin = -100000\nmax = 100000\n"
                                    << maps;
  ASSERT_EQ(run_cli_line("run chain.toml --out-dir chain", dir.path()).exit_code, 0);
  const CliResult graph = run_cli_line("run graph.toml --out-dir graph", dir.path());
  ASSERT_EQ(graph.exit_code, 0) << graph.err;
  for (const char* file : {"h.r32", "ero.r32", "dep.r32"})
    EXPECT_EQ(read_text(dir / "graph" / file), read_text(dir / "chain" / file)) << file;
}

TEST(GraphOutputs, AnErosionMapOfANodeWithoutErosionIsRefusedNamingTheNode) {
  TempDir dir("graph-erosion-refused");
  std::ofstream(dir / "graph.toml") << world() << "[[node]]\nid = \"hills\"\nkind = \"midpoint\"\nseed = 3\n"
                                    << "[[node]]\nid = \"worn\"\nkind = \"erode\"\ninputs = [\"hills\"]\n"
                                    << "[[node]]\nid = \"both\"\nkind = \"max\"\ninputs = [\"hills\", \"worn\"]\n"
                                    << outputs({{"ero.png", "erosion_map"}});
  const CliResult refused = run_cli_line("run graph.toml --out-dir out", dir.path());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.err, HasSubstr("takes node `both` (max), which carries no erosion"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "ero.png"));
}

}  // namespace
}  // namespace sansui::test
