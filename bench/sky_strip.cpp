// The picture docs/sky.md shows: both sky models (look/sky_model.hpp) side by side for sun
// elevations from astronomical night to noon, so that they can be judged by eye.
//
// One column per sun elevation (-18, -12, -6, -3, 0, 3, 6, 10, 20, 45, 90 deg); the Table 2 model
// above, Preetham below. Each cell looks toward the sun: across, 120 deg of azimuth centred on
// the sun's; up, the horizon (bottom) to the zenith (top). The sun's disc (Table 3, drawn at
// eight times its true size so that it shows) sits where it stands, hidden below the horizon.
//
// Run from the source tree: build/bench/sky_strip [OUTPUT.png]   (default docs/images/sky-models.png)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "core/color.hpp"
#include "io/image_io.hpp"
#include "look/sky_model.hpp"

namespace sansui::look {
namespace {

constexpr std::array<double, 11> sun_elevations_deg = {-18, -12, -6, -3, 0, 3, 6, 10, 20, 45, 90};
constexpr int cell = 112;            // pixels per cell side
constexpr int gap = 4;               // pixels between cells
constexpr double field_deg = 120.0;  // azimuth across one cell
constexpr double sun_azimuth_deg = 180.0;
constexpr double sun_radius_deg = 8.0 * 0.27;  // eight times the true angular radius

// The sRGB transfer functions (IEC 61966-2-1).
float decode_srgb(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
std::uint8_t encode_srgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  const float srgb = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(srgb * 255.0f));
}

/// The sun's disc over the sky colour `sky` (linear) at angle `distance_deg` from its centre.
Rgb with_sun(Rgb sky, double sun_elevation_deg, double distance_deg) {
  const double act = distance_deg / sun_radius_deg;
  // The panorama smears a sun near the zenith across its top row: leave it out there.
  if (act >= 1.0 || sun_elevation_deg > 85.0) return sky;
  const Rgb display = sun_disc_colour(sun_elevation_deg, act);  // Table 3 gives display values
  const Rgb sun{decode_srgb(display.r), decode_srgb(display.g), decode_srgb(display.b)};
  const float alpha = sun_disc_alpha(act) * (sun.r + sun.g + sun.b > 0.0f ? 1.0f : 0.0f);
  return {sky.r + (sun.r - sky.r) * alpha, sky.g + (sun.g - sky.g) * alpha, sky.b + (sun.b - sky.b) * alpha};
}

double angular_distance_deg(double elevation1, double azimuth1, double elevation2, double azimuth2) {
  constexpr double rad = 3.14159265358979323846 / 180.0;
  const double c = std::sin(elevation1 * rad) * std::sin(elevation2 * rad) +
                   std::cos(elevation1 * rad) * std::cos(elevation2 * rad) * std::cos((azimuth1 - azimuth2) * rad);
  return std::acos(std::clamp(c, -1.0, 1.0)) / rad;
}

void draw_cell(Image& image, int left, int top, SkyModel model, double sun_elevation_deg) {
  const SkyInputs inputs{sun_elevation_deg, sun_azimuth_deg, 3.0};
  for (int y = 0; y < cell; ++y) {
    const double elevation = 90.0 * (cell - 1 - y + 0.5) / cell;
    for (int x = 0; x < cell; ++x) {
      const double azimuth = sun_azimuth_deg + field_deg * ((x + 0.5) / cell - 0.5);
      Rgb colour = sky_colour(model, inputs, elevation, azimuth);
      colour = with_sun(colour, sun_elevation_deg, angular_distance_deg(elevation, azimuth, sun_elevation_deg, sun_azimuth_deg));
      image(left + x, top + y) = Rgba8{encode_srgb(colour.r), encode_srgb(colour.g), encode_srgb(colour.b), 255};
    }
  }
}

Image sky_strip() {
  const int columns = static_cast<int>(sun_elevations_deg.size());
  Image image(columns * cell + (columns + 1) * gap, 2 * cell + 3 * gap, Rgba8{255, 255, 255, 255});
  const std::array<SkyModel, 2> rows = {SkyModel::table2, SkyModel::preetham};
  for (int row = 0; row < 2; ++row)
    for (int column = 0; column < columns; ++column)
      draw_cell(image, gap + column * (cell + gap), gap + row * (cell + gap), rows[static_cast<std::size_t>(row)],
                sun_elevations_deg[static_cast<std::size_t>(column)]);
  return image;
}

}  // namespace
}  // namespace sansui::look

int main(int argc, char** argv) {
  const std::filesystem::path output = argc > 1 ? argv[1] : "docs/images/sky-models.png";
  try {
    sansui::io::write_png(output, sansui::look::sky_strip());
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sky_strip: %s\n", error.what());
    return 2;
  }
  std::printf("wrote %s\n", output.string().c_str());
  return 0;
}
