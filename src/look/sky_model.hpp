// Pure CPU models of the sun and the sky (SPEC 3.4): where the sun stands for a date, time and
// place, what colour its disc is, and what colour the sky is in any direction. No OpenGL, no I/O:
// the renderer and the viewer sample these (per pixel, per vertex or into a texture).
//
// - solar_position(): NOAA's solar position calculator (the spreadsheet
//   NOAA_Solar_Calculations_day.xls of NOAA's Global Monitoring Laboratory, after J. Meeus,
//   "Astronomical Algorithms", 1991), with NOAA's refraction correction.
// - sun_colour(), sun_disc_colour(), sun_disc_alpha(): Table 3 of Oka et al. 1997 (seed 003,
//   Sec. 4.1.8), made continuous in the sun's elevation.
// - sky_colour_table2(): Table 2 of the same paper (Sec. 4.1.7), its OCR-lost terms reconstructed.
// - sky_colour_preetham(): A. J. Preetham, P. Shirley, B. Smits, "A Practical Analytic Model for
//   Daylight", SIGGRAPH 1999, extended below the horizon into twilight and night.
// docs/sky.md explains every choice; docs/images/sky-models.png compares the two sky models.
//
// Angles follow the renderer: elevation in degrees above the horizon (negative below), azimuth
// in degrees clockwise from north.
#pragma once

#include <optional>
#include <string_view>

#include "core/color.hpp"

namespace sansui::look {

using sansui::Rgb;

// ---------------------------------------------------------------------------------------------
// Where the sun is

/// A civil date and clock time at some place (proleptic Gregorian calendar).
struct SolarTime {
  /// [Range: 1583..3000] [Default: 2000]
  int year = 2000;
  /// [Range: 1..12] [Default: 1]
  int month = 1;
  /// Day of the month. [Range: 1..28, 29, 30 or 31 as the month and leap years allow] [Default: 1]
  int day = 1;
  /// Local clock time. [Range: 0..23] [Default: 12]
  int hour = 12;
  /// [Range: 0..59] [Default: 0]
  int minute = 0;
  /// [Units: s] [Range: 0 <= second < 60] [Default: 0]
  double second = 0.0;
  /// The local clock's offset from UTC (east positive: Japan +9, Colorado in winter -7; daylight
  /// saving time is part of the offset). [Units: h] [Range: -14..14] [Default: 0]
  double utc_offset_hours = 0.0;
};

struct SunPosition {
  /// Apparent height above the horizon, refraction included as NOAA computes it (about +0.5 deg
  /// at the horizon, 0 above 85 deg). [Units: deg] [Range: -90..90]
  double elevation_deg = 0.0;
  /// Compass bearing, clockwise from north. [Units: deg] [Range: 0 <= azimuth < 360]
  double azimuth_deg = 0.0;
};

/// The sun's position seen from (latitude_deg, longitude_deg) at `when`, by NOAA's solar
/// position calculator (it agrees with NOAA's spreadsheet to 0.01 deg, and with spherical
/// geometry at equinoxes, solstices and sunrise to well within 0.5 deg; tests). latitude [Units: deg, north positive] [Range: -90..90];
/// longitude [Units: deg, east positive] [Range: -180..180]. Throws InputError naming the first bad value and what is allowed.
SunPosition solar_position(const SolarTime& when, double latitude_deg, double longitude_deg);

// ---------------------------------------------------------------------------------------------
// The sun's colour (Table 3)

/// The colour of the sun's disc at its centre: Table 3 of the paper, continuous in the sun's
/// elevation. White above about 41 deg, yellow to orange-red toward the horizon, black (not
/// drawn) below -7.2 deg. Returns sRGB display values in [0, 1], as the paper's table gives them
/// (decode them with the sRGB transfer function before blending in linear light).
/// sun_elevation_deg [Units: deg] [Range: -90..90, clamped]
Rgb sun_colour(double sun_elevation_deg);

/// The colour of the sun's disc at `act`, the normalised distance from the disc's centre (0 the
/// centre, 1 the rim); Table 3's rows for the sun just below the horizon redden the rim (act >
/// 0.6) or brighten it (act > 0.66). Returns sRGB display values in [0, 1].
/// sun_elevation_deg [Units: deg] [Range: -90..90, clamped]; act [Range: 0..1, clamped]
Rgb sun_disc_colour(double sun_elevation_deg, double act);

/// Opacity of the sun's disc at `act` (0 the centre, 1 the rim): an opaque core out to act = 0.6
/// (where Table 3's rim colours start), fading smoothly to fully transparent at the rim, as the
/// paper draws the sun "more transparent the farther from its centre".
/// [Range: act 0..1, clamped; returns 0..1]
float sun_disc_alpha(double act);

// ---------------------------------------------------------------------------------------------
// The sky's colour

enum class SkyModel {
  table2,    ///< the paper's Table 2 (colour by sun elevation and by the sky point's elevation)
  preetham,  ///< Preetham, Shirley and Smits 1999, with a twilight and night extension
};

/// "table2" or "preetham"; nullopt for anything else.
std::optional<SkyModel> sky_model_from_name(std::string_view name);
/// The model's name as sky_model_from_name() reads it.
std::string_view sky_model_name(SkyModel model);

/// What the sky's colour depends on besides the direction looked in.
struct SkyInputs {
  /// The sun's height above the horizon (negative below). [Units: deg] [Range: -90..90] [Default: 32]
  double sun_elevation_deg = 32.0;
  /// The sun's compass bearing, clockwise from north. [Units: deg] [Range: any finite, modulo 360] [Default: 300]
  double sun_azimuth_deg = 300.0;
  /// Haze of the air (Preetham's turbidity T; the Table 2 model ignores it): 2 very clear,
  /// 3 a clear day, 10 hazy. [Range: 2..10] [Default: 3]
  double turbidity = 3.0;
};

/// Throws InputError naming the first bad value of `inputs` and what is allowed.
void validate(const SkyInputs& inputs);

/// The sky's colour in a direction by the paper's Table 2 (night, nautical twilight early and
/// late, civil twilight, sunrise/sunset, day), its lost terms reconstructed, blended between the
/// states so that it is continuous in the sun's elevation, plus a warm glow around the sun when
/// it is low (docs/sky.md). Returns linear RGB (sRGB primaries, D65), each channel in [0, 1].
/// view_elevation_deg [Units: deg] [Range: -90..90; below 0 the horizon's colour];
/// view_azimuth_deg [Units: deg, clockwise from north]. `inputs` out of range are clamped
/// (validate() them once first).
Rgb sky_colour_table2(const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg);

/// The sky's colour in a direction by Preetham et al. 1999 (the Perez distribution of Y, x, y
/// with the paper's turbidity fits and zenith formulas), tone-mapped so that day skies land in
/// [0, 1] (an exposure that half follows the zenith's brightness, as an eye adapts). Below the
/// horizon, where Preetham is not defined, the sky of the sun at 0 deg turns to the blue hour
/// with a reddening afterglow and dims smoothly into the Table 2 night, reached exactly at
/// -18 deg (astronomical night). Returns linear RGB (sRGB primaries, D65), each channel in
/// [0, 1]. Arguments as sky_colour_table2().
Rgb sky_colour_preetham(const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg);

/// The sky's colour by `model` (see the two functions above). Returns linear RGB in [0, 1].
Rgb sky_colour(SkyModel model, const SkyInputs& inputs, double view_elevation_deg, double view_azimuth_deg);

}  // namespace sansui::look
