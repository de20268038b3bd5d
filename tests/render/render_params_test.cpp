#include "render/render_params.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "core/error.hpp"

namespace sansui::render {
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

TEST(RenderParams, DefaultsAreValidAndFollowTheTemperateClimate) {
  const RenderParams params;
  EXPECT_NO_THROW(params.validate());
  // Seed 003, Table 4: Cw, Cfa, Cfb, Cfc have tree line 50 % and snow line 75 %.
  EXPECT_DOUBLE_EQ(params.bands.tree_line, 0.50);
  EXPECT_DOUBLE_EQ(params.bands.snow_line, 0.75);
  EXPECT_EQ(params.view, View::perspective);
}

TEST(RenderParams, EachBadValueIsNamedWithWhatIsAllowed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    void (*spoil)(RenderParams&);
    const char* expected;
  };
  const Case cases[] = {
      {[](RenderParams& p) { p.width = 8; }, "width 8 pixels is not allowed: it must be between 16 and 8192"},
      {[](RenderParams& p) { p.height = 9000; }, "height 9000 pixels is not allowed"},
      {[](RenderParams& p) { p.sun_elevation_deg = -5; }, "sun elevation -5 degrees is not allowed: it must be between 0 and 90"},
      {[](RenderParams& p) { p.sun_azimuth_deg = std::numeric_limits<double>::infinity(); }, "sun azimuth inf is not allowed"},
      {[](RenderParams& p) { p.camera.elevation_deg = 90; }, "camera elevation 90 degrees is not allowed"},
      {[](RenderParams& p) { p.camera.distance = 0.01; }, "camera distance 0.01 terrain sizes (or 0 to fit) is not allowed"},
      {[](RenderParams& p) { p.camera.fov_deg = 150; }, "camera field of view 150 degrees is not allowed"},
      {[](RenderParams& p) { p.camera.target_y = 1.5; }, "camera target y 1.5 is not allowed"},
      {[](RenderParams& p) { p.exaggeration = 0; }, "vertical exaggeration 0 is not allowed: it must be between 0.1 and 20"},
      {[](RenderParams& p) { p.sea_level_m = std::numeric_limits<double>::quiet_NaN(); }, "sea level nan is not allowed"},
      {[](RenderParams& p) { p.bands.snow_line = 1.2; }, "snow line 1.2 is not allowed: it must be between 0 and 1"},
      {[](RenderParams& p) { p.bands.cliff_slope_deg = 95; }, "cliff slope 95 degrees is not allowed"},
      {[](RenderParams& p) { p.fog_density = -1; }, "fog density -1 is not allowed"},
      {[](RenderParams& p) { p.samples = 0; }, "antialiasing samples 0 is not allowed"},
      {[](RenderParams& p) { p.palette.snow.g = 2.0f; }, "palette colour snow has channel 2"},
  };
  for (const Case& c : cases) {
    RenderParams params;
    c.spoil(params);
    EXPECT_THAT(message_of(params), HasSubstr(c.expected));
  }
  RenderParams params;
  params.exaggeration = nan;
  EXPECT_THAT(message_of(params), HasSubstr("vertical exaggeration nan"));
}

TEST(RenderParams, ViewNamesRoundTrip) {
  for (View view : {View::perspective, View::top}) EXPECT_EQ(view_from_name(view_name(view)), view);
  EXPECT_FALSE(view_from_name("side").has_value());
  EXPECT_FALSE(view_from_name("Top").has_value());
}

}  // namespace
}  // namespace sansui::render
