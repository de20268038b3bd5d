#include "look/sky_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "test_util.hpp"

namespace sansui::look {
namespace {

using ::testing::HasSubstr;

// ---------------------------------------------------------------------------------------------
// The sun's position

SolarTime at(int year, int month, int day, int hour, int minute, double second, double utc_offset_hours) {
  return {year, month, day, hour, minute, second, utc_offset_hours};
}

TEST(SunPosition, MatchesTheRowsOfNoaasSpreadsheet) {
  // NOAA_Solar_Calculations_day.xls, its example inputs and outputs (elevation corrected for
  // refraction, azimuth clockwise from north), as pysunNOAA's tests reproduce them.
  const SunPosition boulder = solar_position(at(2010, 6, 21, 0, 6, 0, -6), 40.0, -105.0);
  EXPECT_NEAR(boulder.elevation_deg, -25.2334819743467, 0.01);
  EXPECT_NEAR(boulder.azimuth_deg, 345.86910228316, 0.01);
  const SunPosition palo_alto = solar_position(at(2023, 9, 21, 5, 33, 0, -8), 37.4219444444444, -122.079583333333);
  EXPECT_NEAR(palo_alto.elevation_deg, -5.17796026715717, 0.01);
  EXPECT_NEAR(palo_alto.azimuth_deg, 85.1264242410581, 0.01);
}

TEST(SunPosition, EquinoxNoonAtFortyDegreesIsFiftyDegreesUp) {
  // 20 March 2023 (equinox at 21:24 UT, declination -0.1 deg at noon); on the Greenwich meridian
  // the equation of time puts solar noon at 12:07:30 UT. Geometry: 90 - 40 = 50 deg.
  const SunPosition north = solar_position(at(2023, 3, 20, 12, 7, 30, 0), 40.0, 0.0);
  EXPECT_NEAR(north.elevation_deg, 50.0, 0.5);
  EXPECT_NEAR(north.azimuth_deg, 180.0, 0.5);  // due south
  const SunPosition south = solar_position(at(2023, 3, 20, 12, 7, 30, 0), -40.0, 0.0);
  EXPECT_NEAR(south.elevation_deg, 50.0, 0.5);
  EXPECT_NEAR(std::min(south.azimuth_deg, 360.0 - south.azimuth_deg), 0.0, 0.5);  // due north
}

TEST(SunPosition, JuneSolsticeSunIsOverheadAtTheTropicOfCancer) {
  // 21 June 2023, the Tropic at 23.436 deg N, solar noon at 12:01:50 UT on the prime meridian.
  const SunPosition noon = solar_position(at(2023, 6, 21, 12, 1, 50, 0), 23.436, 0.0);
  EXPECT_NEAR(noon.elevation_deg, 90.0, 0.5);
}

TEST(SunPosition, SunriseAzimuthFollowsSphericalGeometry) {
  // NOAA's sunrise for Boulder on 21 June 2010 is 0.230045 of a day, 05:31:16 local: the sun's
  // centre 0.833 deg below the true horizon (half its disc plus refraction). From the spherical
  // triangle pole-zenith-sun, cos(azimuth) = (sin(dec) - sin(lat) cos(z)) / (cos(lat) sin(z))
  // with dec = 23.438, lat = 40, z = 90.833 gives 57.9 deg; NOAA's refraction at -0.833 deg
  // (0.397 deg) lifts the apparent elevation to -0.44 deg.
  const SunPosition sunrise = solar_position(at(2010, 6, 21, 5, 31, 16, -6), 40.0, -105.0);
  EXPECT_NEAR(sunrise.azimuth_deg, 57.9, 0.5);
  EXPECT_NEAR(sunrise.elevation_deg, -0.44, 0.5);
}

TEST(SunPosition, TheSameInstantInAnyTimeZoneGivesTheSamePosition) {
  const SunPosition utc = solar_position(at(2024, 2, 29, 3, 0, 0, 0), 35.68, 139.77);
  const SunPosition tokyo = solar_position(at(2024, 2, 29, 12, 0, 0, 9), 35.68, 139.77);
  EXPECT_NEAR(utc.elevation_deg, tokyo.elevation_deg, 1e-9);
  EXPECT_NEAR(utc.azimuth_deg, tokyo.azimuth_deg, 1e-9);
  // Tokyo's solar noon on 29 February: about 90 - 35.68 - 8.0 deg up, due south.
  EXPECT_NEAR(tokyo.elevation_deg, 46.3, 1.0);
  EXPECT_NEAR(tokyo.azimuth_deg, 180.0, 3.0);
}

TEST(SunPosition, StaysDefinedAtThePolesAndTheDateLine) {
  for (double latitude : {-90.0, 90.0})
    for (double longitude : {-180.0, 180.0}) {
      const SunPosition p = solar_position(at(2021, 12, 21, 0, 0, 0, 0), latitude, longitude);
      EXPECT_TRUE(std::isfinite(p.elevation_deg) && std::isfinite(p.azimuth_deg));
      EXPECT_GE(p.azimuth_deg, 0.0);
      EXPECT_LT(p.azimuth_deg, 360.0);
    }
  // At the south pole in December the sun circles at the declination's height, 23.4 deg.
  EXPECT_NEAR(solar_position(at(2021, 12, 21, 0, 0, 0, 0), -90.0, 0.0).elevation_deg, 23.4, 0.5);
}

TEST(SunPosition, BadInputsAreNamedWithWhatIsAllowed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    SolarTime when;
    double latitude, longitude;
    const char* expected;
  };
  const Case cases[] = {
      {at(2023, 13, 1, 12, 0, 0, 0), 0, 0, "solar time month 13 is not allowed: it must be between 1 and 12"},
      {at(2023, 2, 29, 12, 0, 0, 0), 0, 0, "solar time day 29 is not allowed: month 2 of 2023 has days 1 to 28"},
      {at(1900, 2, 29, 12, 0, 0, 0), 0, 0, "solar time day 29 is not allowed: month 2 of 1900 has days 1 to 28"},
      {at(2023, 4, 31, 12, 0, 0, 0), 0, 0, "solar time day 31 is not allowed: month 4 of 2023 has days 1 to 30"},
      {at(2023, 4, 0, 12, 0, 0, 0), 0, 0, "solar time day 0 is not allowed"},
      {at(2023, 4, 1, 24, 0, 0, 0), 0, 0, "solar time hour 24 is not allowed: it must be between 0 and 23"},
      {at(2023, 4, 1, 12, 60, 0, 0), 0, 0, "solar time minute 60 is not allowed: it must be between 0 and 59"},
      {at(2023, 4, 1, 12, 0, 60, 0), 0, 0, "solar time second 60 is not allowed: it must be at least 0 and less than 60"},
      {at(2023, 4, 1, 12, 0, nan, 0), 0, 0, "solar time second nan is not allowed"},
      {at(2023, 4, 1, 12, 0, 0, 15), 0, 0, "solar time UTC offset 15 is not allowed: it must be between -14 and 14 h"},
      {at(1500, 4, 1, 12, 0, 0, 0), 0, 0, "solar time year 1500 is not allowed: it must be between 1583 and 3000"},
      {at(2023, 4, 1, 12, 0, 0, 0), 91, 0, "latitude 91 is not allowed: it must be between -90 and 90 deg"},
      {at(2023, 4, 1, 12, 0, 0, 0), nan, 0, "latitude nan is not allowed"},
      {at(2023, 4, 1, 12, 0, 0, 0), 0, -180.5, "longitude -180.5 is not allowed: it must be between -180 and 180 deg"},
  };
  for (const Case& c : cases)
    EXPECT_THAT(test::message_of([&] { solar_position(c.when, c.latitude, c.longitude); }), HasSubstr(c.expected));
  EXPECT_NO_THROW(solar_position(at(2024, 2, 29, 23, 59, 59.999, -14), -90, 180));  // a leap day
  EXPECT_NO_THROW(solar_position(at(2000, 2, 29, 0, 0, 0, 14), 90, -180));          // 2000 is a leap year
}

// ---------------------------------------------------------------------------------------------
// The sun's colour

void expect_rgb(const Rgb& actual, double r, double g, double b, const std::string& where) {
  EXPECT_NEAR(actual.r, r, 1e-6) << where;
  EXPECT_NEAR(actual.g, g, 1e-6) << where;
  EXPECT_NEAR(actual.b, b, 1e-6) << where;
}

TEST(SunColour, IsWhiteWhenTheSunIsHigh) {
  for (double elevation : {42.0, 45.0, 60.0, 90.0}) expect_rgb(sun_colour(elevation), 1, 1, 1, std::to_string(elevation));
}

TEST(SunColour, ReddensTowardTheHorizon) {
  for (double elevation : {0.5, 2.0, 5.0, 10.0, 20.0, 30.0}) {
    const Rgb c = sun_colour(elevation);
    EXPECT_EQ(c.r, 1.0f) << elevation;
    EXPECT_GT(c.r, c.g) << elevation;
    EXPECT_GT(c.g, c.b) << elevation;
  }
  EXPECT_LT(sun_colour(3.0).g, sun_colour(15.0).g);
  EXPECT_LT(sun_colour(15.0).g, sun_colour(30.0).g);
}

TEST(SunColour, IsBlackBelowMinusPointZeroEightOfNinetyDegrees) {
  for (double elevation : {-7.21, -8.0, -12.0, -45.0, -90.0})
    for (double act : {0.0, 0.7, 1.0}) expect_rgb(sun_disc_colour(elevation, act), 0, 0, 0, std::to_string(elevation));
  EXPECT_GT(sun_colour(-7.1).r, 0.0f);
}

TEST(SunColour, PrintedRowsHoldAwayFromTheirThresholds) {
  // s = elevation / 90; Table 3 as printed (TABLES-003.md).
  expect_rgb(sun_disc_colour(0.35 * 90, 0.9), 1.0, 1.0 - 0.10, 0.8 - 1.5 * 0.10, "s 0.35");
  expect_rgb(sun_disc_colour(0.10 * 90, 0.0), 1.0, 0.8 - 2.0 * 0.15, 0.0, "s 0.10");
  expect_rgb(sun_disc_colour(-0.03 * 90, 0.3), 1.0, 1.0, 0.8, "s -0.03, core");
  expect_rgb(sun_disc_colour(-0.03 * 90, 0.8), 1.0, 1.0 - 2.5 * 0.2, 0.8 - 2.0 * 0.2, "s -0.03, act 0.8");
  expect_rgb(sun_disc_colour(-0.03 * 90, 1.0), 1.0, 0.0, 0.0, "s -0.03, rim");
  expect_rgb(sun_disc_colour(-0.065 * 90, 0.5), 0.8, 0.0, 0.0, "s -0.065, core");
  expect_rgb(sun_disc_colour(-0.065 * 90, 1.0), 0.8, 2.4 * 0.34, 0.0, "s -0.065, rim");
  // Above the horizon the colour does not depend on act.
  EXPECT_EQ(sun_disc_colour(20.0, 0.0), sun_disc_colour(20.0, 1.0));
}

TEST(SunColour, ChangesContinuouslyWithTheSunsElevation) {
  for (double act : {0.0, 0.5, 0.65, 0.8, 1.0}) {
    Rgb previous = sun_disc_colour(-90.0, act);
    for (int step = -900; step <= 900; ++step) {
      const double elevation = step * 0.1;
      const Rgb c = sun_disc_colour(elevation, act);
      const float jump = std::max({std::abs(c.r - previous.r), std::abs(c.g - previous.g), std::abs(c.b - previous.b)});
      ASSERT_LT(jump, 0.15f) << "at " << elevation << " deg, act " << act;
      previous = c;
    }
  }
}

TEST(SunDiscAlpha, IsOpaqueInTheCoreAndFadesToTheRim) {
  EXPECT_EQ(sun_disc_alpha(0.0), 1.0f);
  EXPECT_EQ(sun_disc_alpha(0.6), 1.0f);
  EXPECT_EQ(sun_disc_alpha(1.0), 0.0f);
  EXPECT_EQ(sun_disc_alpha(1.5), 0.0f);   // clamped
  EXPECT_EQ(sun_disc_alpha(-0.5), 1.0f);  // clamped
  for (double act = 0.6; act < 1.0; act += 0.01) EXPECT_GE(sun_disc_alpha(act), sun_disc_alpha(act + 0.01)) << act;
  EXPECT_NEAR(sun_disc_alpha(0.8), 0.5f, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// The sky's colour

constexpr SkyModel both_models[] = {SkyModel::table2, SkyModel::preetham};

double luminance(const Rgb& c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

Rgb sky(SkyModel model, double sun_elevation_deg, double view_elevation_deg, double view_azimuth_deg = 180.0,
        double sun_azimuth_deg = 180.0, double turbidity = 3.0) {
  return sky_colour(model, SkyInputs{sun_elevation_deg, sun_azimuth_deg, turbidity}, view_elevation_deg, view_azimuth_deg);
}

TEST(SkyModel, NamesRoundTrip) {
  for (SkyModel model : both_models) EXPECT_EQ(sky_model_from_name(sky_model_name(model)), model);
  EXPECT_EQ(sky_model_from_name("hosek"), std::nullopt);
}

TEST(SkyModel, TheEntryPointDispatchesToEachModel) {
  const SkyInputs inputs{12.0, 100.0, 4.0};
  EXPECT_EQ(sky_colour(SkyModel::table2, inputs, 20.0, 130.0), sky_colour_table2(inputs, 20.0, 130.0));
  EXPECT_EQ(sky_colour(SkyModel::preetham, inputs, 20.0, 130.0), sky_colour_preetham(inputs, 20.0, 130.0));
}

TEST(SkyModel, BadInputsAreNamedWithWhatIsAllowed) {
  EXPECT_NO_THROW(validate(SkyInputs{}));
  EXPECT_THAT(test::message_of([] {
                validate(SkyInputs{91.0, 0.0, 3.0});
              }),
              HasSubstr("sun elevation 91 is not allowed: it must be between -90 and 90 deg"));
  EXPECT_THAT(test::message_of([] {
                validate(SkyInputs{10.0, std::numeric_limits<double>::infinity(), 3.0});
              }),
              HasSubstr("sun azimuth inf is not allowed"));
  EXPECT_THAT(test::message_of([] {
                validate(SkyInputs{10.0, 0.0, 1.5});
              }),
              HasSubstr("sky turbidity 1.5 is not allowed: it must be between 2 and 10"));
}

TEST(SkyModel, ZenithIsFarDarkerAtNightThanByDay) {
  for (SkyModel model : both_models) {
    const double night = luminance(sky(model, -18.0, 90.0)), day = luminance(sky(model, 60.0, 90.0));
    EXPECT_GT(night, 0.0) << sky_model_name(model);  // dark blue, not black
    EXPECT_GT(day, 10.0 * night) << sky_model_name(model);
  }
}

TEST(SkyModel, DaySkyIsBlueAndNightSkyDarkBlue) {
  for (SkyModel model : both_models) {
    for (double view_elevation : {30.0, 60.0, 90.0}) {
      const Rgb day = sky(model, 45.0, view_elevation, 0.0);  // looking away from the sun
      EXPECT_GT(day.b, day.g) << sky_model_name(model) << " " << view_elevation;
      EXPECT_GT(day.g, day.r) << sky_model_name(model) << " " << view_elevation;
      const Rgb night = sky(model, -25.0, view_elevation, 0.0);
      EXPECT_GT(night.b, 2.0f * night.r) << sky_model_name(model) << " " << view_elevation;
      EXPECT_LT(luminance(night), 0.1) << sky_model_name(model) << " " << view_elevation;
    }
  }
}

TEST(SkyModel, HorizonTowardTheSunIsRedderAtSunsetThanAtNoon) {
  for (SkyModel model : both_models) {
    const Rgb noon = sky(model, 60.0, 2.0, 180.0);
    const double noon_ratio = noon.r / noon.b;
    for (double sun : {0.0, 1.0, 2.0, 3.0}) {
      const Rgb sunset = sky(model, sun, 2.0, 180.0);
      EXPECT_GT(sunset.r / sunset.b, 2.0 * noon_ratio) << sky_model_name(model) << " sun at " << sun;
      EXPECT_GT(sunset.r, sunset.b) << sky_model_name(model) << " sun at " << sun;
    }
  }
}

TEST(SkyModel, NoNanOrOutOfRangeValuesForAnySunAndView) {
  std::vector<double> suns = {-90.0, -45.0, -30.0};
  for (double sun = -18.0; sun <= 90.0; sun += 1.5) suns.push_back(sun);
  for (SkyModel model : both_models)
    for (double turbidity : {2.0, 3.0, 6.0, 10.0})
      for (double sun : suns)
        for (double view_elevation = -10.0; view_elevation <= 90.0; view_elevation += 5.0)
          for (double view_azimuth = 0.0; view_azimuth < 360.0; view_azimuth += 30.0) {
            const Rgb c = sky(model, sun, view_elevation, view_azimuth, 200.0, turbidity);
            for (float channel : {c.r, c.g, c.b})
              ASSERT_TRUE(channel >= 0.0f && channel <= 1.0f)
                  << sky_model_name(model) << " T " << turbidity << " sun " << sun << " view " << view_elevation << "," << view_azimuth;
          }
}

TEST(SkyModel, ColourChangesSmoothlyAsTheSunMoves) {
  struct View {
    double elevation, azimuth;
  };
  const View views[] = {{90, 0}, {0, 180}, {2, 180}, {5, 160}, {0, 0}, {30, 90}, {60, 180}};
  for (SkyModel model : both_models)
    for (const View& view : views) {
      Rgb previous = sky(model, -20.0, view.elevation, view.azimuth);
      for (int step = -199; step <= 900; ++step) {
        const double sun = step * 0.1;
        const Rgb c = sky(model, sun, view.elevation, view.azimuth);
        const float jump = std::max({std::abs(c.r - previous.r), std::abs(c.g - previous.g), std::abs(c.b - previous.b)});
        ASSERT_LT(jump, 0.05f) << sky_model_name(model) << " sun at " << sun << " view " << view.elevation << "," << view.azimuth;
        previous = c;
      }
    }
}

TEST(SkyModel, Table2PrintedStatesHoldInsideTheirBands) {
  // Values on the paper's scale divided by the table's largest value, (3 * 1.5^3 + 1) / 4, are
  // sRGB display values; the model returns them in linear light.
  const double scale = (3.0 * 3.375 + 1.0) / 4.0;
  auto linear = [&](double paper) {
    const double c = paper / scale;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  // Night (s <= -0.12) at the zenith, A = 1.5: {A^3/10, A^3/10, A^3/4}.
  expect_rgb(sky(SkyModel::table2, -15.0, 90.0), linear(0.3375), linear(0.3375), linear(0.84375), "night zenith");
  // Civil twilight (its key, s = -0.03) at the horizon away from the sun, A = 1: {0.8, 0.8, 1}.
  const Rgb civil = sky(SkyModel::table2, -2.7, 0.0, 0.0);
  EXPECT_NEAR(civil.r, linear(0.8), 1e-5);
  EXPECT_NEAR(civil.b, linear(1.0), 1e-5);
}

TEST(SkyModel, PreethamBelowTheHorizonDimsIntoTheTable2Night) {
  for (double view_elevation : {0.0, 45.0, 90.0}) {
    EXPECT_EQ(sky(SkyModel::preetham, -18.0, view_elevation), sky(SkyModel::table2, -18.0, view_elevation)) << view_elevation;
    EXPECT_GT(luminance(sky(SkyModel::preetham, -3.0, view_elevation)), luminance(sky(SkyModel::preetham, -9.0, view_elevation)));
    EXPECT_GT(luminance(sky(SkyModel::preetham, 0.0, view_elevation)), luminance(sky(SkyModel::preetham, -3.0, view_elevation)));
  }
}

TEST(SkyModel, PreethamHazeWhitensTheSky) {
  // More turbidity: a paler sky away from the sun (less blue relative to red).
  const Rgb clear = sky(SkyModel::preetham, 40.0, 30.0, 0.0, 180.0, 2.0);
  const Rgb hazy = sky(SkyModel::preetham, 40.0, 30.0, 0.0, 180.0, 8.0);
  EXPECT_GT(hazy.r / hazy.b, clear.r / clear.b);
}

}  // namespace
}  // namespace sansui::look
