// Rock colours for terrain cliffs and the raw .r32 volume with its sidecar.
#include <cmath>
#include <fstream>
#include <functional>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "io/volume_file.hpp"
#include "scene/solid_slice.hpp"
#include "solid/evaluator.hpp"
#include "solid/rock_albedo.hpp"
#include "solid/type1_array.hpp"
#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"

namespace sansui::solid {
namespace {

using test::message_of;

Heightfield test_terrain(int size) {
  terrain::MidpointParams params;
  params.seed = 4;
  params.sigma_m = 300.0;
  Heightfield heights = terrain::generate_midpoint(params, size);
  heights.cell_size_m = 10.0;
  return heights;
}

std::uint64_t hash_of(const Image& image) {
  return test::fnv1a(image.data(), image.size() * sizeof(Rgba8));
}

TEST(SolidRock, AlbedoCoversTheHeightfieldAndIsDeterministic) {
  const Heightfield heights = test_terrain(129);
  RockParams params;
  params.texture = "strata";
  params.levels = 9;
  Image one, two;
  tbb::task_arena(1).execute([&] { one = rock_albedo(heights, params); });
  tbb::task_arena(2).execute([&] { two = rock_albedo(heights, params); });
  ASSERT_EQ(one.width(), heights.width());
  ASSERT_EQ(one.height(), heights.height());
  EXPECT_EQ(hash_of(one), hash_of(two));
  params.texture = "white-marble";
  EXPECT_NE(hash_of(rock_albedo(heights, params)), hash_of(one));
}

TEST(SolidRock, TilesOfAnAnchoredFieldJoin) {
  const Heightfield whole = test_terrain(129);
  Heightfield tile(65, 65, 0.0f, whole.cell_size_m);
  tile.origin_x_m = 64 * whole.cell_size_m;
  tile.origin_y_m = 32 * whole.cell_size_m;
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) tile(x, y) = whole(64 + x, 32 + y);
  RockParams params;
  params.texture = "strata";
  params.levels = 12;
  params.field_cell_m = 5.0;
  const Image a = rock_albedo(whole, params);
  const Image b = rock_albedo(tile, params);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) ASSERT_EQ(b(x, y), a(64 + x, 32 + y)) << x << "," << y;
}

TEST(SolidRock, BadInputIsRejected) {
  Heightfield heights(9, 9, 0.0f);
  heights(3, 3) = std::nanf("");
  RockParams params;
  params.texture = "strata";
  EXPECT_EQ(message_of([&] { rock_albedo(heights, params); }), "the heightfield has a height nan: rock needs finite heights");
  params.texture = "basalt";
  EXPECT_EQ(message_of([&] { rock_albedo(Heightfield(9, 9, 0.0f), params); }),
            "rock.texture 'basalt' is not allowed: it must be one of none, white-marble, green-marble, oak, pine, strata, marble, wood");
  params = {};
  params.r2 = 12;
  EXPECT_EQ(message_of([&] { rock_albedo(Heightfield(9, 9, 0.0f), params); }), "rock.r2 12 is not allowed: it must be 0..levels = 11");
  EXPECT_TRUE(rock_albedo(Heightfield(9, 9, 0.0f), RockParams{}).empty());  // texture none: no rock
}

TEST(SolidVolume, R32HoldsEveryLatticePointWithASidecar) {
  test::TempDir dir("solid-volume");
  FieldParams params;
  params.levels = 4;
  params.seed = 12;
  auto field = make_evaluator(EvaluatorType::type3, params);
  io::write_volume_r32(dir / "field.r32", scene::field_volume(*field), {{"note", "test"}});
  const Volume expected = generate_type1(params);

  std::ifstream in(dir / "field.r32", std::ios::binary);
  std::vector<float> values(expected.size());
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(float)));
  ASSERT_EQ(in.gcount(), static_cast<std::streamsize>(values.size() * sizeof(float)));
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
  EXPECT_EQ(test::fnv1a(std::span<const float>(values)), test::fnv1a(expected.values()));

  const auto json = nlohmann::json::parse(std::ifstream(dir / "field.r32.json"));
  EXPECT_EQ(json["kind"], "volume");
  EXPECT_EQ(json["file"], "field.r32");
  EXPECT_EQ(json["size"], nlohmann::json({17, 17, 17}));
  EXPECT_EQ(json["format"]["order"], "x fastest, then y, then z");
  EXPECT_EQ(json["field"]["levels"], 4);
  EXPECT_EQ(json["field"]["evaluator"], "III");
  EXPECT_EQ(json["provenance"]["note"], "test");
  EXPECT_FLOAT_EQ(json["data_range"]["min"].get<float>(), *std::min_element(values.begin(), values.end()));
}

TEST(SolidVolume, AFailedWriteLeavesNoFile) {
  test::TempDir dir("solid-volume-fail");
  FieldParams params;
  params.levels = 3;
  auto field = make_evaluator(EvaluatorType::type3, params);
  EXPECT_NE(
      message_of([&] { io::write_volume_r32(dir / "missing" / "field.r32", scene::field_volume(*field), {}); }).find("does not exist"),
      std::string::npos);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace sansui::solid
