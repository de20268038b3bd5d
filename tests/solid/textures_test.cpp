// Solid textures and pictures (seeds/002 Sec. 3, SPEC 2): layers where the formula puts them,
// presets, pictures identical for every evaluator type and thread count.
#include <cmath>
#include <functional>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "solid/evaluator.hpp"
#include "solid/pictures.hpp"
#include "solid/texture.hpp"
#include "tests/test_util.hpp"

namespace sansui::solid {
namespace {

using test::message_of;

std::uint64_t hash_of(const Image& image) {
  return test::fnv1a(image.data(), image.size() * sizeof(Rgba8));
}

FieldParams small_field(int levels = 6) {
  FieldParams params;
  params.levels = levels;
  params.seed = 21;
  return params;
}

TEST(SolidTextures, MarbleBaseFollowsEquationSix) {
  MarbleParams marble;
  marble.layers = {{0.3, 0.1, 40.0}, {0.7, 0.02, 100.0}};
  for (int i = 0; i <= 1000; ++i) {
    const double z = i / 1000.0;
    double expected = 0.0;
    for (const auto& layer : marble.layers) {
      const double d = std::abs(z - layer.centre) - layer.width / 2;
      expected += d > 0.0 ? std::exp(-layer.falloff * d) : 1.0;
    }
    ASSERT_NEAR(marble_base(marble, z), expected, 1e-9 * (1.0 + expected)) << "z = " << z;
  }
  EXPECT_GE(marble_base(marble, 0.3), 1.0);    // inside a layer's core
  EXPECT_GE(marble_base(marble, 0.345), 1.0);  // still inside (half width 0.05)
  EXPECT_LT(marble_base(marble, 0.5), 0.02);   // between the layers
}

TEST(SolidTextures, PeriodicLayersRepeat) {
  MarbleParams marble;
  marble.layers = {{0.05, 0.01, 80.0}};
  marble.period = 0.25;
  for (double z : {0.0, 0.02, 0.05, 0.13, 0.2}) {
    EXPECT_NEAR(marble_base(marble, z), marble_base(marble, z + 0.25), 1e-9);
    EXPECT_NEAR(marble_base(marble, z), marble_base(marble, z + 0.75), 1e-9);
  }
}

TEST(SolidTextures, MarbleLayersAppearWhereTheFormulaPutsThemWithKZero) {
  // A vertical slice (y = const) of marble with k = 0: every picture row has the colour of
  // G at that row's z, whatever the field does.
  SolidTexture texture = texture_preset("white-marble");
  texture.marble.layers = {{0.25, 0.08, 60.0}, {0.6, 0.0, 150.0}};
  texture.marble.period = 0.0;
  texture.marble.strength = 0.0;
  const FieldParams params = small_field(5);
  auto field = make_evaluator(EvaluatorType::type3, params);
  const int size = 33;  // one pixel per lattice point
  const Image slice = render_slice(*field, texture, 1, 16.0, size, quiet_context());
  const TextureSampler sampler(texture);
  for (int row = 0; row < size; ++row) {
    const double z = (size - 1 - row) / 32.0;
    const Rgb expected = texture.marble.palette.at(static_cast<float>(std::min(marble_base(texture.marble, z), 1.0)));
    for (int x = 0; x < size; ++x) {
      ASSERT_NEAR(slice(x, row).r, expected.r * 255.0f, 0.51f) << "row " << row;
      ASSERT_EQ(slice(x, row), slice(0, row));
    }
  }
  // The darkest rows are the layers' cores: z = 0.25 (row 24) and z = 0.6 (about row 13).
  EXPECT_LT(slice(0, 24).r, slice(0, 19).r);
  EXPECT_EQ(slice(0, 24), slice(0, 23));  // both within the 0.08 core around 0.25
}

TEST(SolidTextures, WoodRingsRepeatWithTheRingSpacing) {
  SolidTexture texture = texture_preset("oak");
  texture.wood.strength = 0.0;
  texture.wood.grain = 0.0;
  texture.wood.axis = 2;
  texture.wood.centre_u = 0.0;
  texture.wood.centre_v = 0.0;
  const TextureSampler sampler(texture);
  const double spacing = texture.wood.ring_spacing;
  for (double r : {0.013, 0.2, 0.31}) {
    const Rgb a = sampler.color(r, 0.0, 0.5, 0.0f);
    const Rgb b = sampler.color(r + 3 * spacing, 0.0, 0.1, 0.0f);
    EXPECT_NEAR(a.r, b.r, 1e-5);
    EXPECT_NEAR(a.g, b.g, 1e-5);
  }
  // Along a radius, colour changes; around the axis at one radius, it does not.
  EXPECT_NEAR(sampler.color(0.2, 0.0, 0.5, 0.0f).r, sampler.color(0.0, 0.2, 0.9, 0.0f).r, 1e-5);
}

TEST(SolidTextures, StrataBedsAreLevelOrDipAsAsked) {
  SolidTexture texture = texture_preset("strata");
  texture.strata.strength = 0.0;
  texture.strata.dip_deg = 0.0;
  const TextureSampler level(texture);
  for (double z : {0.01, 0.2, 0.47, 0.9}) {
    const Rgb a = level.color(0.1, 0.7, z, 1.0f), b = level.color(0.8, 0.05, z, -2.0f);
    EXPECT_EQ(a.r, b.r);
    EXPECT_EQ(a.g, b.g);
  }
  texture.strata.dip_deg = 10.0;
  texture.strata.dip_azimuth_deg = 0.0;  // rising along +x
  const TextureSampler dipping(texture);
  const double rise = std::tan(10.0 * 3.14159265358979 / 180.0);
  int same = 0;
  for (int i = 0; i < 100; ++i) {
    const double x = 0.01 * i, z = 0.3;
    same += dipping.color(x, 0.5, z, 0.0f).r == dipping.color(0.0, 0.5, z + rise * x, 0.0f).r ? 1 : 0;
  }
  EXPECT_GE(same, 97);  // equal but for rounding at a few lamina boundaries
}

TEST(SolidTextures, PresetsExistAndUnknownNamesAreRejected) {
  for (const auto& name : texture_names()) EXPECT_NO_THROW(TextureSampler(texture_preset(name))) << name;
  EXPECT_EQ(message_of([] { texture_preset("granite"); }),
            "texture 'granite' is unknown: allowed are white-marble, green-marble, oak, pine, strata, marble, wood, field");
  SolidTexture bad = texture_preset("oak");
  bad.wood.ring_spacing = 0.0;
  EXPECT_EQ(message_of([&] { TextureSampler{bad}; }), "ring spacing 0 is not allowed: it must be > 0");
}

TEST(SolidPictures, EveryEvaluatorTypeDrawsTheSamePicture) {
  const FieldParams params = small_field(6);
  const SolidTexture texture = texture_preset("green-marble");
  std::uint64_t sphere = 0, cube = 0, slice = 0;
  for (auto type : {EvaluatorType::type1, EvaluatorType::type2, EvaluatorType::type3, EvaluatorType::type4}) {
    auto field = make_evaluator(type, params, {3, true});
    const std::uint64_t s = hash_of(render_sphere(*field, texture, 64));
    const std::uint64_t c = hash_of(render_cube(*field, texture, 64));
    const std::uint64_t l = hash_of(render_slice(*field, texture, 2, 20.5, 64));
    if (type == EvaluatorType::type1) {
      sphere = s;
      cube = c;
      slice = l;
    } else {
      EXPECT_EQ(s, sphere) << type_name(type);
      EXPECT_EQ(c, cube) << type_name(type);
      EXPECT_EQ(l, slice) << type_name(type);
    }
  }
}

TEST(SolidPictures, OneAndTwoThreadsDrawTheSameBytes) {
  const FieldParams params = small_field(7);
  auto field = make_evaluator(EvaluatorType::type4, params, {4, true});
  const SolidTexture texture = texture_preset("pine");
  Image one, two;
  tbb::task_arena(1).execute([&] { one = render_sphere(*field, texture, 96); });
  tbb::task_arena(2).execute([&] { two = render_sphere(*field, texture, 96); });
  EXPECT_EQ(hash_of(one), hash_of(two));
}

TEST(SolidPictures, ASliceOfTheFieldShowsTheLatticeValues) {
  const FieldParams params = small_field(5);
  auto field = make_evaluator(EvaluatorType::type1, params);
  const Image slice = render_slice(*field, texture_preset("field"), 2, 7.0, 33);
  for (int y = 0; y < 33; y += 5)
    for (int x = 0; x < 33; x += 3) {
      const float grey = std::clamp(0.5f + 0.2f * field->at(x, 32 - y, 7), 0.0f, 1.0f);
      EXPECT_EQ(slice(x, y).r, static_cast<std::uint8_t>(grey * 255.0f + 0.5f));
    }
}

TEST(SolidPictures, SphereAndCubeLookRight) {
  auto field = make_evaluator(EvaluatorType::type3, small_field(6));
  const Image sphere = render_sphere(*field, texture_preset("white-marble"), 128);
  // The corners show the dark ground, the centre the lit white marble.
  EXPECT_LT(sphere(2, 2).r, 70);
  EXPECT_GT(sphere(64, 64).r, 120);
  const Image cube = render_cube(*field, texture_preset("white-marble"), 128);
  EXPECT_LT(cube(2, 2).r, 70);
  EXPECT_GT(cube(64, 64).r, 90);
}

TEST(SolidPictures, BadPictureRequestsAreRejected) {
  auto field = make_evaluator(EvaluatorType::type3, small_field(4));
  const SolidTexture texture = texture_preset("marble");
  EXPECT_EQ(message_of([&] { render_slice(*field, texture, 2, 16.5, 64); }),
            "slice position 16.5 is outside the block: it must be in [0, 16]");
  EXPECT_EQ(message_of([&] { render_slice(*field, texture, 3, 1.0, 64); }), "slice axis 3 is not allowed: it must be x, y or z");
  EXPECT_EQ(message_of([&] { render_sphere(*field, texture, 4); }), "picture size 4 px is not allowed: it must be 8..8192");
}

}  // namespace
}  // namespace sansui::solid
