// The sun's position (NOAA), the sun's colour (Table 3) and the sky's colour (Table 2; Preetham et
// al. 1999) of Oka et al. 1997 (seeds/003, Sec. 4.1.7-4.1.8; TABLES-003.md). See the header for
// the sources and docs/sky.md for every choice made where the paper's tables are incomplete.
#include "look/sky_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "core/error.hpp"
#include "look/colour_space.hpp"

namespace sansui::look {
namespace {

constexpr double pi = std::numbers::pi;

double sin_deg(double angle) {
  return std::sin(angle * degrees);
}
double cos_deg(double angle) {
  return std::cos(angle * degrees);
}

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

/// A colour in doubles for the arithmetic; channels are unbounded until the end.
struct Colour {
  double r = 0.0, g = 0.0, b = 0.0;
};
Colour operator+(const Colour& p, const Colour& q) {
  return {p.r + q.r, p.g + q.g, p.b + q.b};
}
Colour operator*(const Colour& p, double k) {
  return {p.r * k, p.g * k, p.b * k};
}
Colour mix(const Colour& p, const Colour& q, double t) {
  return p * (1.0 - t) + q * t;
}
Colour tint(const Colour& c, const Colour& filter) {
  return {c.r * filter.r, c.g * filter.g, c.b * filter.b};
}
Colour max_zero(const Colour& c) {
  return {std::max(c.r, 0.0), std::max(c.g, 0.0), std::max(c.b, 0.0)};
}

Rgb to_rgb(const Colour& c) {
  auto channel = [](double value) { return static_cast<float>(std::clamp(value, 0.0, 1.0)); };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

double decode_srgb(double srgb) {
  const double c = std::clamp(srgb, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// ---------------------------------------------------------------------------------------------
// The sun's position: NOAA's spreadsheet, column by column (J. Meeus, Astronomical Algorithms).

bool is_leap_year(int year) {
  return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int days_in_month(int year, int month) {
  constexpr std::array<int, 12> days = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap_year(year) ? 29 : days[static_cast<std::size_t>(month - 1)];
}

bool within(double value, double low, double high) {
  return value >= low && value <= high;
}  // false for NaN

void validate_solar_inputs(const SolarTime& when, double latitude_deg, double longitude_deg) {
  if (when.year < 1583 || when.year > 3000)
    fail("solar time year {} is not allowed: it must be between 1583 and 3000 (Gregorian calendar)", when.year);
  if (when.month < 1 || when.month > 12) fail("solar time month {} is not allowed: it must be between 1 and 12", when.month);
  const int last_day = days_in_month(when.year, when.month);
  if (when.day < 1 || when.day > last_day)
    fail("solar time day {} is not allowed: month {} of {} has days 1 to {}", when.day, when.month, when.year, last_day);
  if (when.hour < 0 || when.hour > 23) fail("solar time hour {} is not allowed: it must be between 0 and 23", when.hour);
  if (when.minute < 0 || when.minute > 59) fail("solar time minute {} is not allowed: it must be between 0 and 59", when.minute);
  if (!(when.second >= 0.0 && when.second < 60.0))
    fail("solar time second {} is not allowed: it must be at least 0 and less than 60", when.second);
  if (!within(when.utc_offset_hours, -14.0, 14.0))
    fail("solar time UTC offset {} is not allowed: it must be between -14 and 14 h", when.utc_offset_hours);
  if (!within(latitude_deg, -90.0, 90.0)) fail("latitude {} is not allowed: it must be between -90 and 90 deg", latitude_deg);
  if (!within(longitude_deg, -180.0, 180.0)) fail("longitude {} is not allowed: it must be between -180 and 180 deg", longitude_deg);
}

/// Days from 1970-01-01 to a proleptic Gregorian date (H. Hinnant's days_from_civil), exact in
/// integers, so the Julian day needs no calendar tables.
long days_from_civil(long year, long month, long day) {
  year -= month <= 2 ? 1 : 0;
  const long era = (year >= 0 ? year : year - 399) / 400;
  const long year_of_era = year - era * 400;
  const long day_of_year = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const long day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

double local_minutes(const SolarTime& when) {
  return when.hour * 60.0 + when.minute + when.second / 60.0;
}

/// Julian day (UT) of `when`: 1970-01-01 0h UT is JD 2440587.5.
double julian_day(const SolarTime& when) {
  return 2440587.5 + static_cast<double>(days_from_civil(when.year, when.month, when.day)) + local_minutes(when) / 1440.0 -
         when.utc_offset_hours / 24.0;
}

struct SunEphemeris {
  double declination_deg = 0.0;
  double equation_of_time_min = 0.0;
};

/// Declination and equation of time for `century`, Julian centuries since J2000.0.
SunEphemeris sun_ephemeris(double century) {
  const double c = century;
  const double mean_longitude = std::fmod(280.46646 + c * (36000.76983 + c * 0.0003032), 360.0);
  const double mean_anomaly = 357.52911 + c * (35999.05029 - 0.0001537 * c);
  const double eccentricity = 0.016708634 - c * (0.000042037 + 0.0000001267 * c);
  const double equation_of_centre = sin_deg(mean_anomaly) * (1.914602 - c * (0.004817 + 0.000014 * c)) +
                                    sin_deg(2.0 * mean_anomaly) * (0.019993 - 0.000101 * c) + sin_deg(3.0 * mean_anomaly) * 0.000289;
  // Nutation and aberration, through the longitude of the Moon's ascending node.
  const double node = 125.04 - 1934.136 * c;
  const double apparent_longitude = mean_longitude + equation_of_centre - 0.00569 - 0.00478 * sin_deg(node);
  const double mean_obliquity = 23.0 + (26.0 + (21.448 - c * (46.815 + c * (0.00059 - c * 0.001813))) / 60.0) / 60.0;
  const double obliquity = mean_obliquity + 0.00256 * cos_deg(node);

  SunEphemeris out;
  out.declination_deg = std::asin(sin_deg(obliquity) * sin_deg(apparent_longitude)) / degrees;
  const double y = std::pow(std::tan(obliquity / 2.0 * degrees), 2.0);
  const double l0 = mean_longitude * degrees, m = mean_anomaly * degrees, e = eccentricity;
  const double radians = y * std::sin(2.0 * l0) - 2.0 * e * std::sin(m) + 4.0 * e * y * std::sin(m) * std::cos(2.0 * l0) -
                         0.5 * y * y * std::sin(4.0 * l0) - 1.25 * e * e * std::sin(2.0 * m);
  out.equation_of_time_min = 4.0 * radians / degrees;
  return out;
}

/// NOAA's approximate atmospheric refraction for a true elevation, in degrees (NOAA applies its
/// last branch even far below the horizon; kept, to match NOAA's published values).
double refraction_deg(double elevation_deg) {
  const double e = elevation_deg;
  double arcseconds = 0.0;
  if (e > 85.0) {
    arcseconds = 0.0;
  } else if (e > 5.0) {
    const double t = std::tan(e * degrees);
    arcseconds = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / std::pow(t, 5.0);
  } else if (e > -0.575) {
    arcseconds = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arcseconds = -20.772 / std::tan(e * degrees);
  }
  return arcseconds / 3600.0;
}

// ---------------------------------------------------------------------------------------------
// The sun's colour: Table 3, s = elevation / 90, display (sRGB) values.

// Table 3's thresholds: row i + 1 holds from thresholds[i] up; row 0 (black) below the first.
constexpr std::array<double, 5> table3_thresholds = {-0.08, -0.06, 0.0, 0.25, 0.45};
// The printed rows jump at every threshold; each row fades in over this much of s above its
// threshold (1.35 deg of elevation), so the colour is continuous and still exactly as printed
// below each threshold (black below -0.08).
constexpr double table3_fade = 0.015;

Colour table3_row(std::size_t row, double s, double act) {
  switch (row) {
    case 0:
      return {0.0, 0.0, 0.0};
    case 1:  // -0.08 ~: a red disc whose rim turns orange
      return {0.8, act > 0.66 ? 2.4 * (act - 0.66) : 0.0, 0.0};
    case 2:  // -0.06 ~: a pale yellow disc whose rim turns red
      return {1.0, act > 0.6 ? 1.0 - 2.5 * (act - 0.6) : 1.0, act > 0.6 ? 0.8 - 2.0 * (act - 0.6) : 0.8};
    case 3:  // 0.00 ~: orange-red to orange
      return {1.0, 0.8 - 2.0 * (0.25 - s), 0.0};
    case 4:  // 0.25 ~: orange-yellow to pale yellow
      return {1.0, 1.0 - (0.45 - s), 0.8 - 1.5 * (0.45 - s)};
    default:  // 0.45 ~: white
      return {1.0, 1.0, 1.0};
  }
}

Colour table3_colour(double sun_elevation_deg, double act) {
  const double s = std::clamp(sun_elevation_deg, -90.0, 90.0) / 90.0;
  const double a = std::clamp(act, 0.0, 1.0);
  std::size_t row = 0;
  while (row < table3_thresholds.size() && s >= table3_thresholds[row]) ++row;
  if (row == 0) return table3_row(0, s, a);
  const double fade_in = smoothstep(0.0, table3_fade, s - table3_thresholds[row - 1]);
  return mix(table3_row(row - 1, s, a), table3_row(row, s, a), fade_in);
}

// ---------------------------------------------------------------------------------------------
// The sky's colour: Table 2. Values "on the paper's scale" are the printed formulas; they reach
// 2.78 (late nautical twilight's zenith blue), so dividing by that maximum maps the whole table
// into [0, 1] without clipping any of its printed ratios. Those are display (sRGB) values, as a
// 1997 OpenGL program's colours were.

constexpr double table2_maximum = (3.0 * 1.5 * 1.5 * 1.5 + 1.0) / 4.0;  // (3A^3 + 1)/4 at A = 1.5

enum Table2State : std::size_t { night, nautical_early, nautical_late, civil, sunrise, day, table2_states };

// Where each state is pure, in s = sun elevation / 90: night up to its printed bound, day from
// its printed lower bound, the bands between at their middles; smoothstep blends between.
constexpr std::array<double, table2_states> table2_keys = {-0.12, -0.10, -0.07, -0.03, 0.03, 0.06};

/// State `state` of Table 2 at A = 1 + theta_i / pi, on the paper's scale. Terms marked
/// "reconstructed" were lost by the OCR (docs/sky.md has the reasons).
Colour table2_state(std::size_t state, double a) {
  const double a2 = a * a, a3 = a2 * a;
  switch (state) {
    case night:  // printed {A^3/10, A^3/10, A^3/4, 1.0}: the fourth value is alpha
      return {a3 / 10.0, a3 / 10.0, a3 / 4.0};
    case nautical_early:
      return {(0.9 * a3 + 0.1) / 5.0, (0.9 * a3 + 0.1) / 5.0, (2.0 * a3 + 0.5) / 4.0};
    case nautical_late:
      return {(1.6 * a3 + 0.4) / 5.0, (1.6 * a3 + 0.4) / 5.0, (3.0 * a3 + 1.0) / 4.0};
    case civil:
      return {(3.2 * a3 + 0.8) / 5.0, (3.2 * a3 + 0.8) / 5.0, (2.0 * a3 + 2.0) / 4.0};
    case sunrise:  // B reconstructed: R and G's pattern continued (0.6, 0.4 -> 0.2), 1 at the horizon
      return {0.6 * a3 + 0.4, 0.4 * a3 + 0.6, 0.2 * a3 + 0.8};
    default:  // day, printed {A^2, A^2, A^2}: the A^2 kept, the lost weights and offsets reconstructed
      return {0.45 * a2 + 0.15, 0.65 * a2 + 0.2, 1.0 * a2 + 0.25};
  }
}

Colour table2_blend(double s, double a) {
  if (s <= table2_keys.front()) return table2_state(night, a);
  if (s >= table2_keys.back()) return table2_state(day, a);
  std::size_t state = 0;
  while (s >= table2_keys[state + 1]) ++state;
  const double t = smoothstep(table2_keys[state], table2_keys[state + 1], s);
  return mix(table2_state(state, a), table2_state(state + 1, a), t);
}

/// Warm glow on the horizon toward a low sun, on the paper's scale: strongest from civil
/// twilight to a sun 3 deg up, gone by -7.2 deg and by 9 deg. Not in the paper, whose Table 2
/// ignores the sun's azimuth, but in every dawn and dusk photograph it was compared with.
Colour table2_glow(double s, double view_elevation_deg, double azimuth_difference_deg) {
  const double strength = smoothstep(-0.08, -0.03, s) * (1.0 - smoothstep(0.03, 0.10, s));
  if (strength <= 0.0) return {};
  const double spread = std::exp(-std::pow(azimuth_difference_deg / 45.0, 2.0)) * std::exp(-view_elevation_deg / 12.0);
  return Colour{2.0, 0.85, 0.2} * (strength * spread);
}

/// Smallest angle between two compass bearings. [Units: deg] [Range: 0..180]
double azimuth_difference(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}

/// Table 2 in linear light: the paper's display value, scaled to [0, 1] and decoded.
Colour table2_linear(const Colour& paper_scale) {
  const Colour display = paper_scale * (1.0 / table2_maximum);
  return {decode_srgb(display.r), decode_srgb(display.g), decode_srgb(display.b)};
}

Colour table2_night_linear(double view_elevation_deg) {
  const double a = 1.0 + std::max(view_elevation_deg, 0.0) * degrees / pi;
  return table2_linear(table2_state(night, a));
}

// ---------------------------------------------------------------------------------------------
// The sky's colour: Preetham, Shirley and Smits 1999.

/// Perez et al.'s sky distribution F(theta, gamma) with coefficients A..E.
struct Perez {
  double a, b, c, d, e;
  double operator()(double cos_theta, double gamma) const {
    const double cos_gamma = std::cos(gamma);
    return (1.0 + a * std::exp(b / cos_theta)) * (1.0 + c * std::exp(d * gamma) + e * cos_gamma * cos_gamma);
  }
};

// Preetham et al., Appendix A.2: the distribution coefficients, linear in turbidity T.
Perez perez_luminance(double t) {
  return {0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703};
}
Perez perez_x(double t) {
  return {-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452};
}
Perez perez_y(double t) {
  return {-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529};
}

/// [T^2 T 1] M [theta^3 theta^2 theta 1]^T, the zenith chromaticity fits of Appendix A.2.
double zenith_chromaticity(const std::array<std::array<double, 4>, 3>& m, double t, double theta) {
  const std::array<double, 4> powers = {theta * theta * theta, theta * theta, theta, 1.0};
  const std::array<double, 3> weights = {t * t, t, 1.0};
  double sum = 0.0;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 4; ++j) sum += weights[i] * m[i][j] * powers[j];
  return sum;
}

constexpr std::array<std::array<double, 4>, 3> zenith_x_fit = {{
    {0.00166, -0.00375, 0.00209, 0.0},
    {-0.02903, 0.06377, -0.03202, 0.00394},
    {0.11693, -0.21196, 0.06052, 0.25886},
}};
constexpr std::array<std::array<double, 4>, 3> zenith_y_fit = {{
    {0.00275, -0.00610, 0.00317, 0.0},
    {-0.04214, 0.08970, -0.04153, 0.00516},
    {0.15346, -0.26756, 0.06670, 0.26688},
}};

// Preetham's skies look paler than photographs of clear skies (and than the eye sees them);
// cameras raise saturation too. With 1.3 a clear zenith (T = 3, the sun at 45 deg) shows as
// about (0.56, 0.72, 1.0) in sRGB.
constexpr double preetham_saturation = 1.3;

struct Xyy {
  double x = 0.0, y = 0.0, luminance = 0.0;  // CIE chromaticity; luminance in kcd/m^2
};

/// Preetham's sky for one turbidity and sun: the Perez coefficients and the zenith's colour.
struct PreethamSky {
  double sun_zenith = 0.0;  // [Units: rad] [Range: 0..pi/2]
  Perez luminance, x, y;
  Xyy zenith;
};

PreethamSky preetham_sky(double t, double sun_elevation_deg) {
  PreethamSky sky{(90.0 - sun_elevation_deg) * degrees, perez_luminance(t), perez_x(t), perez_y(t), {}};
  const double chi = (4.0 / 9.0 - t / 120.0) * (pi - 2.0 * sky.sun_zenith);
  // Positive for every sun above the horizon when T <= 10 (2.4192 - 0.2155 T > 0 at chi = 0).
  const double zenith_luminance = (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
  sky.zenith = {zenith_chromaticity(zenith_x_fit, t, sky.sun_zenith), zenith_chromaticity(zenith_y_fit, t, sky.sun_zenith),
                std::max(zenith_luminance, 1e-3)};
  return sky;
}

/// The sky seen at zenith angle `view_zenith` (radians, 0..pi/2), `gamma` radians from the sun.
Xyy preetham_xyy(const PreethamSky& sky, double view_zenith, double gamma) {
  // At the horizon 1/cos(theta) grows without bound; the Perez terms in it have vanished by
  // cos = 0.001, so clamping there changes nothing but avoids dividing by zero.
  const double cos_view = std::max(std::cos(view_zenith), 0.001);
  auto relative = [&](const Perez& f) { return f(cos_view, gamma) / f(1.0, sky.sun_zenith); };
  return {sky.zenith.x * relative(sky.x), sky.zenith.y * relative(sky.y), sky.zenith.luminance * relative(sky.luminance)};
}

/// xyY (luminance in kcd/m^2) to tone-mapped linear sRGB, as a camera would. The luminance is
/// compressed as Y / (Y + exposure) (Reinhard), the exposure following the zenith's luminance
/// as sqrt(7 kcd/m^2 * Y_zenith), as an eye or a camera half adapts: a clear zenith shows at
/// about 0.67 with the sun overhead, 0.5 with the sun at 45 deg and 0.33 on the horizon. The
/// colour, in sRGB primaries, has its saturation raised by preetham_saturation and loses
/// out-of-gamut negatives; where a channel would exceed 1 it goes half the way toward white that
/// would bring it to 1 and is then scaled down whole: the glare around a high sun runs to white
/// as on film, and a setting sun's glow keeps its orange.
Colour tone_mapped_rgb(const Xyy& colour, double zenith_luminance) {
  const double exposure = std::sqrt(7.0 * zenith_luminance);
  const double luminance = colour.luminance / (colour.luminance + exposure);
  const double y = std::max(colour.y, 1e-6);
  const double big_x = colour.x / y * luminance, big_z = (1.0 - colour.x - colour.y) / y * luminance;
  const Colour grey{luminance, luminance, luminance};
  Colour rgb{3.2404542 * big_x - 1.5371385 * luminance - 0.4985314 * big_z, -0.9692660 * big_x + 1.8760108 * luminance + 0.0415560 * big_z,
             0.0556434 * big_x - 0.2040259 * luminance + 1.0572252 * big_z};
  rgb = max_zero(mix(grey, rgb, preetham_saturation));
  const double brightest = std::max({rgb.r, rgb.g, rgb.b});
  if (brightest <= 1.0) return rgb;
  // Half the way toward white that would bring the brightest channel to 1, then scale whole.
  rgb = mix(rgb, grey, 0.5 * (brightest - 1.0) / (brightest - luminance));
  return rgb * (1.0 / std::max({rgb.r, rgb.g, rgb.b}));
}

/// Angle between two directions given as elevation and azimuth. [Units: rad] [Range: 0..pi]
double angle_between(double elevation1_deg, double azimuth1_deg, double elevation2_deg, double azimuth2_deg) {
  const double cosine = sin_deg(elevation1_deg) * sin_deg(elevation2_deg) +
                        cos_deg(elevation1_deg) * cos_deg(elevation2_deg) * cos_deg(azimuth1_deg - azimuth2_deg);
  return std::acos(std::clamp(cosine, -1.0, 1.0));
}

/// Preetham's sky (the sun at or above the horizon) in a direction, tone-mapped linear RGB.
Colour preetham_rgb(const PreethamSky& sky, double sun_azimuth_deg, double view_elevation_deg, double view_azimuth_deg) {
  const double sun_elevation_deg = 90.0 - sky.sun_zenith / degrees;
  const double gamma = angle_between(sun_elevation_deg, sun_azimuth_deg, view_elevation_deg, view_azimuth_deg);
  return tone_mapped_rgb(preetham_xyy(sky, (90.0 - view_elevation_deg) * degrees, gamma), sky.zenith.luminance);
}

// Twilight, where Preetham is not defined: the sky of the sun on the horizon, split into the
// dome (what the side away from the sun shows at the same elevation) and the glow around the
// sun (the rest). Both dim as the sun sinks, exactly to 0 at astronomical night (-18 deg),
// while the Table 2 night fades in. The dome turns to the blue of the "blue hour" (ozone's
// Chappuis absorption colours the twilight sky; Preetham's yellowish low-sun horizon would
// otherwise dim to olive), the glow turns redder and sinks (its light crosses ever more air).

// The blue hour's colour, linear sRGB: about (60, 90, 160) on screen.
constexpr Colour blue_hour{0.045, 0.10, 0.35};
// The glow over the sun below the horizon, linear sRGB: about (255, 140, 60) at its brightest.
constexpr Colour sunset_glow{1.0, 0.26, 0.045};

/// exp(-depth / scale), shifted and scaled to run from 1 at the horizon to 0 at -18 deg.
double twilight_fade(double depth_deg, double scale_deg) {
  constexpr double night_depth_deg = 18.0;  // astronomical night
  if (depth_deg >= night_depth_deg) return 0.0;
  const double floor = std::exp(-night_depth_deg / scale_deg);
  return (std::exp(-depth_deg / scale_deg) - floor) / (1.0 - floor);
}

/// How far the twilight colours have replaced the sunset's: 0 at the horizon, rising with zero
/// slope (so the colour changes gently as the sun sets), 0.63 at 2 deg down, 0.98 at 4 deg.
double settle(double depth_deg) {
  return 1.0 - std::exp(-(depth_deg / 2.0) * (depth_deg / 2.0));
}

Colour preetham_twilight(double turbidity, double sun_elevation_deg, double sun_azimuth_deg, double view_elevation_deg,
                         double view_azimuth_deg) {
  const PreethamSky sky = preetham_sky(turbidity, 0.0);
  const Colour at_sunset = preetham_rgb(sky, sun_azimuth_deg, view_elevation_deg, view_azimuth_deg);
  const Colour dome = preetham_rgb(sky, sun_azimuth_deg, view_elevation_deg, sun_azimuth_deg + 180.0);
  const Colour glow = at_sunset + dome * -1.0;  // may be negative in places: dome + glow = at_sunset exactly
  const double depth = -sun_elevation_deg;      // degrees below the horizon, > 0

  // The dome's colour moves to the blue hour's, its brightness (channel sum) kept.
  const double dome_sum = dome.r + dome.g + dome.b, blue_sum = blue_hour.r + blue_hour.g + blue_hour.b;
  const Colour dome_blue = mix(dome, blue_hour * (dome_sum / blue_sum), settle(depth));
  // The glow keeps its shape (its brightness over the dome, raised, as the eye sees an afterglow
  // against the darkening sky) but takes the colour of a sunset glow, which reddens further as
  // the sun sinks.
  const double glow_strength = std::clamp(2.5 * (glow.r + glow.g + glow.b) / 3.0, 0.0, 1.0);
  const Colour warm = mix(glow, sunset_glow * glow_strength, settle(depth));
  const Colour redden{1.0, std::exp(-depth / 6.0), std::exp(-depth / 3.0)};
  // The glow sinks toward the horizon as the sun does: 1/e at 30 deg up with the sun 3 deg down, at
  // 8 deg up with it 6 deg down.
  const double lower = std::exp(-view_elevation_deg * depth * depth / 280.0);
  const Colour dome_now = dome_blue * twilight_fade(depth, 3.0);
  const Colour glow_now = tint(warm, redden) * (twilight_fade(depth, 6.0) * lower);
  return max_zero(dome_now + glow_now + table2_night_linear(view_elevation_deg) * (1.0 - twilight_fade(depth, 3.0)));
}

}  // namespace

// ---------------------------------------------------------------------------------------------

SunPosition solar_position(const SolarTime& when, double latitude_deg, double longitude_deg) {
  validate_solar_inputs(when, latitude_deg, longitude_deg);
  const double century = (julian_day(when) - 2451545.0) / 36525.0;
  const SunEphemeris sun = sun_ephemeris(century);

  // True solar time and the hour angle (negative in the morning).
  double true_solar_min =
      std::fmod(local_minutes(when) + sun.equation_of_time_min + 4.0 * longitude_deg - 60.0 * when.utc_offset_hours, 1440.0);
  if (true_solar_min < 0.0) true_solar_min += 1440.0;
  const double hour_angle = true_solar_min / 4.0 - 180.0;

  const double lat = latitude_deg, dec = sun.declination_deg;
  const double cos_zenith = sin_deg(lat) * sin_deg(dec) + cos_deg(lat) * cos_deg(dec) * cos_deg(hour_angle);
  const double elevation = 90.0 - std::acos(std::clamp(cos_zenith, -1.0, 1.0)) / degrees;

  // NOAA's azimuth in the atan2 form, which stays defined at the poles and at the zenith.
  const double east = sin_deg(hour_angle) * cos_deg(dec);
  const double north = cos_deg(hour_angle) * cos_deg(dec) * sin_deg(lat) - sin_deg(dec) * cos_deg(lat);
  double azimuth = std::fmod(std::atan2(east, north) / degrees + 180.0, 360.0);
  if (azimuth < 0.0) azimuth += 360.0;

  return {std::min(elevation + refraction_deg(elevation), 90.0), azimuth};
}

Rgb sun_colour(double sun_elevation_deg) {
  return sun_disc_colour(sun_elevation_deg, 0.0);
}

Rgb sun_disc_colour(double sun_elevation_deg, double act) {
  return to_rgb(table3_colour(sun_elevation_deg, act));
}

float sun_disc_alpha(double act) {
  return static_cast<float>(1.0 - smoothstep(0.6, 1.0, std::clamp(act, 0.0, 1.0)));
}

std::optional<SkyModel> sky_model_from_name(std::string_view name) {
  if (name == "table2") return SkyModel::table2;
  if (name == "preetham") return SkyModel::preetham;
  return std::nullopt;
}

std::string_view sky_model_name(SkyModel model) {
  return model == SkyModel::table2 ? "table2" : "preetham";
}

void validate(const SkyInputs& inputs) {
  if (!within(inputs.sun_elevation_deg, -90.0, 90.0))
    fail("sun elevation {} is not allowed: it must be between -90 and 90 deg", inputs.sun_elevation_deg);
  if (!std::isfinite(inputs.sun_azimuth_deg))
    fail("sun azimuth {} is not allowed: it must be a finite number of degrees", inputs.sun_azimuth_deg);
  if (!within(inputs.turbidity, 2.0, 10.0)) fail("sky turbidity {} is not allowed: it must be between 2 and 10", inputs.turbidity);
}

Rgb sky_colour_table2(const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg) {
  const double view_elevation = std::clamp(view_elevation_deg, 0.0, 90.0);
  const double s = std::clamp(inputs.sun_elevation_deg, -90.0, 90.0) / 90.0;
  const double a = 1.0 + view_elevation * degrees / pi;  // the paper's A = 1 + theta_i / pi
  const Colour paper = table2_blend(s, a) + table2_glow(s, view_elevation, azimuth_difference(view_azimuth_deg, inputs.sun_azimuth_deg));
  return to_rgb(table2_linear(paper));
}

Rgb sky_colour_preetham(const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg) {
  const double view_elevation = std::clamp(view_elevation_deg, 0.0, 90.0);
  const double sun_elevation = std::clamp(inputs.sun_elevation_deg, -90.0, 90.0);
  const double turbidity = std::clamp(inputs.turbidity, 2.0, 10.0);
  if (sun_elevation < 0.0)
    return to_rgb(preetham_twilight(turbidity, sun_elevation, inputs.sun_azimuth_deg, view_elevation, view_azimuth_deg));
  return to_rgb(preetham_rgb(preetham_sky(turbidity, sun_elevation), inputs.sun_azimuth_deg, view_elevation, view_azimuth_deg));
}

Rgb sky_colour(SkyModel model, const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg) {
  return model == SkyModel::table2 ? sky_colour_table2(inputs, view_elevation_deg, view_azimuth_deg)
                                   : sky_colour_preetham(inputs, view_elevation_deg, view_azimuth_deg);
}

}  // namespace sansui::look
