// Plant instance lists (CSV, JSON): exact content, round trips, sidecars, bad input.
#include "io/plant_instances.hpp"

#include <cmath>
#include <cstring>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/text_file.hpp"
#include "scene/plants.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;
using vegetation::Instance;
using vegetation::Placement;

std::uint16_t index_of(std::string_view name) {
  const auto& library = vegetation::species_library();
  for (std::size_t i = 0; i < library.size(); ++i)
    if (library[i].name == name) return static_cast<std::uint16_t>(i);
  ADD_FAILURE() << "no species " << name;
  return 0;
}

Placement small_placement() {
  Placement placement;
  placement.trees.push_back({12.5f, -3.25f, 101.75f, 1.125f, static_cast<float>(std::numbers::pi / 2), index_of("oak"), 3});
  placement.trees.push_back({1234.567f, 89.0123f, 0.5f, 0.8f, 0.0f, index_of("spruce"), 0});
  placement.ground.push_back({7.0f, 8.0f, 9.0f, 1.0f, 6.2f, index_of("short_grass"), 1});
  return placement;
}

/// Many plants from a real placement, for round trips.
Placement large_placement() {
  Heightfield heights = test::sample_heights(65, 65, 3, -50.0, 500.0);
  vegetation::PlacementRules rules;
  rules.ground_density = 0.2;
  rules.species = {{"oak"}, {"pine", 0.5, 1.0}, {"short_grass"}};
  vegetation::VegetationParams params;
  params.spacing_m = 5.0;
  return vegetation::place_plants(heights, params, rules);
}

void expect_same(const std::vector<Instance>& expected, const std::vector<Instance>& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Instance &e = expected[i], &a = actual[i];
    EXPECT_EQ(e.x_m, a.x_m) << i;  // shortest float text reads back to the same float
    EXPECT_EQ(e.y_m, a.y_m) << i;
    EXPECT_EQ(e.height_m, a.height_m) << i;
    EXPECT_EQ(e.scale, a.scale) << i;
    EXPECT_NEAR(e.rotation_rad, a.rotation_rad, 1e-6) << i;  // through degrees
    EXPECT_EQ(e.species, a.species) << i;
    EXPECT_EQ(e.variant, a.variant) << i;
  }
}

TEST(PlantInstances, CsvHasAHeaderAndOneRowPerPlant) {
  test::TempDir directory("plants-csv");
  scene::write_plant_instances(directory / "plants.csv", small_placement());
  EXPECT_EQ(io::read_text_file(directory / "plants.csv"),
            "layer,species,x_east_m,y_south_m,height_m,scale,rotation_deg,variant\n"
            "tree,oak,12.5,-3.25,101.75,1.125,90,3\n"
            "tree,spruce,1234.567,89.0123,0.5,0.8,0,0\n"
            "ground,short_grass,7,8,9,1,355.23383,1\n");
  EXPECT_EQ(test::files_in(directory.path()), std::vector<std::string>{"plants.csv"});  // no sidecar unless asked
}

TEST(PlantInstances, JsonIsAnObjectWithOneEntryPerPlant) {
  test::TempDir directory("plants-json");
  scene::write_plant_instances(directory / "plants.json", small_placement());
  const nlohmann::json root = nlohmann::json::parse(io::read_text_file(directory / "plants.json"));
  EXPECT_EQ(root["sansui_plant_instances"], 1);
  ASSERT_EQ(root["instances"].size(), 3u);
  const auto& oak = root["instances"][0];
  EXPECT_EQ(oak["layer"], "tree");
  EXPECT_EQ(oak["species"], "oak");
  EXPECT_EQ(oak["x_east_m"], 12.5);
  EXPECT_EQ(oak["y_south_m"], -3.25);
  EXPECT_EQ(oak["height_m"], 101.75);
  EXPECT_EQ(oak["scale"], 1.125);
  EXPECT_EQ(oak["rotation_deg"], 90);
  EXPECT_EQ(oak["variant"], 3);
  EXPECT_EQ(root["instances"][2]["layer"], "ground");
}

TEST(PlantInstances, RoundTripThroughCsvAndJson) {
  const Placement placement = large_placement();
  ASSERT_GT(placement.trees.size(), 50u);
  ASSERT_GT(placement.ground.size(), 50u);
  test::TempDir directory("plants-round-trip");
  for (const char* name : {"plants.csv", "plants.json", "PLANTS.CSV"}) {
    scene::write_plant_instances(directory / name, placement);
    const Placement back = scene::read_plant_instances(directory / name);
    expect_same(placement.trees, back.trees);
    expect_same(placement.ground, back.ground);
  }
}

TEST(PlantInstances, SidecarWhenAsked) {
  test::TempDir directory("plants-sidecar");
  scene::write_plant_instances(directory / "plants.csv", small_placement(), nlohmann::json{{"seed", 3}});
  EXPECT_EQ(test::files_in(directory.path()), (std::vector<std::string>{"plants.csv", "plants.csv.json"}));
  const nlohmann::json sidecar = nlohmann::json::parse(io::read_text_file(directory / "plants.csv.json"));
  EXPECT_EQ(sidecar["kind"], "plant instances");
  EXPECT_EQ(sidecar["provenance"]["seed"], 3);
}

TEST(PlantInstances, UnknownExtensionIsNamedWithTheAllowedOnes) {
  test::TempDir directory("plants-extension");
  const std::string message = test::message_of([&] { scene::write_plant_instances(directory / "plants.txt", small_placement()); });
  EXPECT_THAT(message, HasSubstr("'.txt'"));
  EXPECT_THAT(message, HasSubstr(".csv .json"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST(PlantInstances, BadSpeciesIndexLeavesNoFile) {
  test::TempDir directory("plants-bad-index");
  Placement placement = small_placement();
  placement.ground.back().species = 60000;
  EXPECT_THAT(test::message_of([&] { scene::write_plant_instances(directory / "plants.json", placement); }),
              HasSubstr("species index 60000"));
  EXPECT_TRUE(test::files_in(directory.path()).empty());
}

TEST(PlantInstances, BadFilesNameTheFileAndLine) {
  test::TempDir directory("plants-bad-files");
  const std::string header = "layer,species,x_east_m,y_south_m,height_m,scale,rotation_deg,variant\n";
  test::write_text(directory / "unknown.csv", header + "tree,oak,1,2,3,1,0,0\ntree,triffid,1,2,3,1,0,0\n");
  EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "unknown.csv"); }),
              testing::AllOf(HasSubstr("unknown.csv:3"), HasSubstr("triffid")));
  test::write_text(directory / "number.csv", header + "tree,oak,1,two,3,1,0,0\n");
  EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "number.csv"); }),
              testing::AllOf(HasSubstr("number.csv:2"), HasSubstr("y_south_m 'two'")));
  test::write_text(directory / "layer.csv", header + "shrub,oak,1,2,3,1,0,0\n");
  EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "layer.csv"); }), HasSubstr("layer 'shrub'"));
  test::write_text(directory / "header.csv", "x,y\n");
  EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "header.csv"); }), HasSubstr("header.csv:1"));
  test::write_text(directory / "bad.json", "{\"sansui_plant_instances\":1,\"instances\":[{\"layer\":\"tree\"}]}");
  EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "bad.json"); }), HasSubstr("instance 0"));
}

TEST(PlantInstances, AJsonVariantMustBeOneOfTheWholeNumbersAllowed) {
  // Fuzz finding: a variant of -873.5 was undefined behaviour in nlohmann's get<uint16_t>.
  test::TempDir directory("plants-variant");
  for (const std::string variant : {"-873.5", "-1", "4", "65536", "1e+300", "\"two\""}) {
    test::write_text(directory / "v.json",
                     "{\"sansui_plant_instances\":1,\"instances\":[{\"layer\":\"tree\",\"species\":\"oak\","
                     "\"x_east_m\":1,\"y_south_m\":2,\"height_m\":3,\"scale\":1,\"rotation_deg\":0,"
                     "\"variant\":" +
                         variant + "}]}");
    EXPECT_THAT(test::message_of([&] { (void)scene::read_plant_instances(directory / "v.json"); }),
                testing::AllOf(HasSubstr("instance 0: variant " + variant + " is not allowed"), HasSubstr("it must be 0..3")))
        << variant;
  }
  test::write_text(directory / "ok.json",
                   "{\"sansui_plant_instances\":1,\"instances\":[{\"layer\":\"tree\",\"species\":\"oak\","
                   "\"x_east_m\":1,\"y_south_m\":2,\"height_m\":3,\"scale\":1,\"rotation_deg\":0,\"variant\":3}]}");
  EXPECT_EQ(scene::read_plant_instances(directory / "ok.json").trees.at(0).variant, 3);
}

}  // namespace
}  // namespace sansui
