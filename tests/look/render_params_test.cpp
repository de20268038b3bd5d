#include "look/render_params.hpp"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"

namespace sansui::look {
namespace {

using ::testing::HasSubstr;

std::string message_of(const RenderParams& params) {
  try {
    params.validate();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(RenderParams, DefaultsAreValidAndTheFallbacksFollowTheTemperateClimate) {
  const RenderParams params;
  EXPECT_NO_THROW(params.validate());
  EXPECT_FALSE(params.land.tree_line_m);  // a scene derives it
  // Without a scene: the climate table's Cfb at 45 degrees in summer, in metres...
  const RenderParams fallback = with_fallbacks(params);
  EXPECT_DOUBLE_EQ(*fallback.land.tree_line_m, 2200.0);
  EXPECT_DOUBLE_EQ(*fallback.land.snow_line_m, 2850.0);
  // ... or with the paper's lines, Table 4: Cw, Cfa, Cfb, Cfc have tree line 50 % and snow line 75 %.
  RenderParams paper;
  paper.land.lines = LandLines::paper;
  EXPECT_DOUBLE_EQ(*with_fallbacks(paper).land.tree_line, 0.50);
  EXPECT_DOUBLE_EQ(*with_fallbacks(paper).land.snow_line, 0.75);
  EXPECT_TRUE(fallback.sky.sunlight && fallback.atmosphere.fog && fallback.water.deep && fallback.sun_elevation_deg);
  EXPECT_EQ(params.view, View::perspective);
}

TEST(RenderParams, EachBadValueIsNamedWithWhatIsAllowed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    void (*spoil)(RenderParams&);
    const char* expected;
  };
  const Case cases[] = {
      {[](RenderParams& p) { p.width = 8; }, "render.width 8 is not allowed: it must be between 16 and 8192 px"},
      {[](RenderParams& p) { p.height = 9000; }, "render.height 9000 is not allowed"},
      {[](RenderParams& p) { p.sun_azimuth_deg = 300, p.sun_elevation_deg = -95; },
       "render.sun 300,-95 is not allowed: it must be AZIMUTH,ELEVATION with the elevation -90..90"},
      {[](RenderParams& p) { p.sun_azimuth_deg = std::numeric_limits<double>::infinity(), p.sun_elevation_deg = 32; },
       "render.sun inf,32 is not allowed"},
      {[](RenderParams& p) { p.camera.elevation_deg = 90; }, "camera.elevation 90 is not allowed: it must be between -89 and 89 deg"},
      {[](RenderParams& p) { p.camera.distance = 0.01; }, "camera.distance 0.01 is not allowed: it must be 0 or 0.05..20"},
      {[](RenderParams& p) { p.camera.fov_deg = 150; }, "camera.fov 150 is not allowed"},
      {[](RenderParams& p) { p.camera.target_y = 1.5; },
       "camera.target 0.5,1.5 is not allowed: it must be 2 numbers, each between 0 and 1"},
      {[](RenderParams& p) { p.exaggeration = 0; }, "render.exaggeration 0 is not allowed: it must be between 0.1 and 20"},
      {[](RenderParams& p) { p.sea_level_m = std::numeric_limits<double>::quiet_NaN(); },
       "render.sea_level nan is not allowed: it must be between -100000 and 100000 m"},
      {[](RenderParams& p) { p.land.snow_line = 1.2; }, "land.snow_line 1.2 is not allowed: it must be between 0 and 1"},
      {[](RenderParams& p) { p.land.cliff_slope_deg = 95; }, "land.cliff_slope 95 is not allowed"},
      {[](RenderParams& p) { p.atmosphere.fog = -1; }, "atmosphere.fog -1 is not allowed"},
      {[](RenderParams& p) { p.samples = 0; }, "render.samples 0 is not allowed"},
      {[](RenderParams& p) {
         p.land.snow = Rgb{0.95f, 2.0f, 0.99f};
       },
       "land.snow 0.95,2,0.99 is not allowed: it must be 3 numbers, each between 0 and 1"},
      {[](RenderParams& p) { p.sky.turbidity = 11; }, "sky.turbidity 11 is not allowed: it must be between 2 and 10"},
  };
  for (const Case& c : cases) {
    RenderParams params;
    c.spoil(params);
    EXPECT_THAT(message_of(params), HasSubstr(c.expected));
  }
  RenderParams params;
  params.exaggeration = nan;
  EXPECT_THAT(message_of(params), HasSubstr("render.exaggeration nan is not allowed"));
}

TEST(RenderParams, ViewNamesRoundTrip) {
  for (View view : {View::perspective, View::top}) EXPECT_EQ(view_from_name(view_name(view)), view);
  EXPECT_FALSE(view_from_name("oblique").has_value());
  for (View view : {View::perspective, View::top, View::front, View::side}) EXPECT_EQ(view_from_name(view_name(view)), view);
  EXPECT_FALSE(view_from_name("Top").has_value());
}

}  // namespace
}  // namespace sansui::look
