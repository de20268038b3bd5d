#include "look/sky_dome.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/parallel.hpp"
#include "core/random.hpp"
#include "look/colour_space.hpp"
#include "look/sky_model.hpp"

namespace sansui::look {
namespace {

constexpr std::uint64_t star_stream = 0x5747;  // "stars"

// The cloud layer stands one unit above the viewer and one cloud image spans this many units,
// repeated mirror-wise beyond (a midpoint-displacement image does not tile): overhead a cloud
// image sample covers about a degree, and toward the horizon the images crowd together.
constexpr double cloud_span = 6.0;

/// Mirrored repeat of a texture coordinate into 0..1.
double mirrored(double u) {
  const double f = u * 0.5 - std::floor(u * 0.5);
  return f < 0.5 ? 2.0 * f : 2.0 - 2.0 * f;
}

double elevation_of_row(int j, int height) {
  return dome_top_deg - (j + 0.5) / height * (dome_top_deg - dome_bottom_deg);
}
double azimuth_of_column(int i, int width) {
  return (i + 0.5) / width * 360.0;
}

/// The cloud image's density where a direction meets the cloud layer, faded out toward the
/// horizon where the layer is seen edge-on; 0 below the horizon.
float cloud_at(const Grid<float>& clouds, float average, double azimuth_deg, double elevation_deg) {
  if (elevation_deg <= 0.0) return 0.0f;
  const double distance = 1.0 / std::tan(elevation_deg * degrees);
  const double u = mirrored(0.5 + distance * std::sin(azimuth_deg * degrees) / cloud_span);
  const double v = mirrored(0.5 - distance * std::cos(azimuth_deg * degrees) / cloud_span);
  const double x = u * (clouds.width() - 1), y = v * (clouds.height() - 1);
  const int x0 = std::min(static_cast<int>(x), clouds.width() - 2), y0 = std::min(static_cast<int>(y), clouds.height() - 2);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float top = clouds(x0, y0) + (clouds(x0 + 1, y0) - clouds(x0, y0)) * fx;
  const float bottom = clouds(x0, y0 + 1) + (clouds(x0 + 1, y0 + 1) - clouds(x0, y0 + 1)) * fx;
  // Far toward the horizon many images fall in one texel: blend the clouds into their average,
  // a band of haze, instead of a shimmer of single texels.
  const float horizon_fade = static_cast<float>(std::clamp(elevation_deg / 12.0, 0.0, 1.0));
  const float density = std::min(top + (bottom - top) * fy, 1.0f);
  return average + (density - average) * horizon_fade;
}

/// Brightness of the stars where the sky's own light lets them show: none once the zenith is
/// brighter than a deep twilight.
float star_visibility(const glm::vec3& zenith) {
  const float luminance = 0.2126f * zenith.r + 0.7152f * zenith.g + 0.0722f * zenith.b;
  return std::clamp(1.0f - luminance / 0.02f, 0.0f, 1.0f);
}

/// The stars that show: uniform on the sphere, magnitudes from a Gaussian-shaped distribution
/// (many faint, few bright), all from (seed, star index).
std::vector<Star> visible_stars(const Sky& sky, float visibility) {
  std::vector<Star> stars;
  if (!sky.stars || visibility <= 0.0f) return stars;
  for (int k = 0; k < sky.star_count; ++k) {
    const double z = 2.0 * rng::uniform(sky.seed, star_stream, k, 0) - 1.0;
    const double elevation = std::asin(z) / degrees;
    // Near the horizon the air's long path dims the stars away (extinction); the haze there is
    // also the colour distant land fades to, which a star must not light up in one direction.
    if (elevation <= 4.0) continue;
    const double extinction = std::clamp((elevation - 4.0) / 8.0, 0.0, 1.0);
    const double azimuth = 360.0 * rng::uniform(sky.seed, star_stream, k, 1);
    const double magnitude = std::clamp(4.5 + 1.2 * rng::gaussian(sky.seed, star_stream, k, 2), 0.0, 6.5);
    const float brightness = visibility * 0.9f * static_cast<float>(extinction * std::pow(10.0, -0.4 * magnitude)) * 6.0f;
    stars.push_back({direction_of(azimuth, elevation), brightness});
  }
  return stars;
}

/// The stars baked into the dome's texels, where the clouds let them through (the sky the
/// shaders look up for the haze and the ambient light; the backdrop draws them as points).
void add_stars(SkyDome& dome, const std::vector<Star>& stars) {
  for (const Star& star : stars) {
    const double elevation = std::asin(std::clamp(static_cast<double>(star.direction.y), -1.0, 1.0)) / degrees;
    double azimuth = std::atan2(static_cast<double>(star.direction.x), -static_cast<double>(star.direction.z)) / degrees;
    if (azimuth < 0.0) azimuth += 360.0;
    const int i = std::clamp(static_cast<int>(azimuth / 360.0 * dome.width), 0, dome.width - 1);
    const int j =
        std::clamp(static_cast<int>((dome_top_deg - elevation) / (dome_top_deg - dome_bottom_deg) * dome.height), 0, dome.height - 1);
    float* texel = &dome.rgba[4 * (static_cast<std::size_t>(j) * dome.width + i)];
    const float clear = 1.0f - texel[3];  // clouds hide the stars
    // A faint blue-white, a little warmer for the faint ones.
    texel[0] += clear * star.brightness * 0.95f;
    texel[1] += clear * star.brightness * 0.97f;
    texel[2] += clear * star.brightness;
  }
}

/// Mirrored index into 0..n-1 (the sample at the border is repeated, as GL_MIRRORED_REPEAT does).
int mirrored_index(int i, int n) {
  const int period = 2 * n;
  i = ((i % period) + period) % period;
  return i < n ? i : period - 1 - i;
}

/// One pass of a box filter of half-width `radius` along x (step (1, 0)) or y (step (0, 1)).
Grid<float> box_pass(const Grid<float>& in, int radius, bool along_x) {
  Grid<float> out(in.width(), in.height(), 0.0f);
  const int n = along_x ? in.width() : in.height(), lines = along_x ? in.height() : in.width();
  const float scale = 1.0f / static_cast<float>(2 * radius + 1);
  parallel_for(0, lines, [&](int line) {
    const auto at = [&](int k) { return along_x ? in(mirrored_index(k, n), line) : in(line, mirrored_index(k, n)); };
    float sum = 0.0f;
    for (int k = -radius; k <= radius; ++k) sum += at(k);
    for (int k = 0; k < n; ++k) {
      (along_x ? out(k, line) : out(line, k)) = sum * scale;
      sum += at(k + radius + 1) - at(k - radius);
    }
  });
  return out;
}

}  // namespace

glm::vec3 direction_of(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * degrees, e = elevation_deg * degrees;
  return {static_cast<float>(std::cos(e) * std::sin(a)), static_cast<float>(std::sin(e)), static_cast<float>(-std::cos(e) * std::cos(a))};
}

Grid<float> cloud_density(const Grid<float>& image, double cover) {
  Grid<float> density(image.width(), image.height(), 0.0f);
  if (image.empty() || cover <= 0.0) return density;
  std::vector<float> sorted(image.values().begin(), image.values().end());
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double fraction) {
    const auto index = static_cast<std::size_t>(std::clamp(fraction, 0.0, 1.0) * static_cast<double>(sorted.size() - 1));
    return sorted[index];
  };
  // The threshold leaves `cover` of the image above it; the edge, centred on it, softens over a
  // tenth of the range.
  const float threshold = at(1.0 - std::min(cover, 1.0));
  const float softness = std::max(at(0.95) - at(0.05), 1e-6f) * 0.1f;
  for (std::size_t i = 0; i < image.size(); ++i)
    density.data()[i] = cover >= 1.0 ? std::clamp((image.data()[i] - at(0.5)) / softness + 2.5f, 1.0f, cloud_density_max)
                                     : std::clamp((image.data()[i] - threshold) / softness + 0.5f, 0.0f, cloud_density_max);
  return density;
}

Grid<float> cloud_thickness(const Grid<float>& density, int radius) {
  if (density.empty()) return density;
  radius = std::max(radius, 1);
  // Two box passes each way approach a Gaussian (a tent), smooth enough that the shading does
  // not show the filter's square.
  Grid<float> blurred = density;
  for (int pass = 0; pass < 2; ++pass) blurred = box_pass(box_pass(blurred, radius, true), radius, false);
  for (std::size_t i = 0; i < blurred.size(); ++i)
    blurred.data()[i] = std::clamp(blurred.data()[i] / cloud_density_max * std::min(density.data()[i], 1.0f), 0.0f, 1.0f);
  return blurred;
}

SkyDome bake_sky_dome(const RenderParams& params, const Grid<float>* clouds, int width, int height, const Context& context) {
  const Sky& sky = params.sky;
  SkyDome dome;
  dome.width = width;
  dome.height = height;
  dome.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
  dome.clear.assign(dome.rgba.size(), 0.0f);
  const SkyInputs inputs{*params.sun_elevation_deg, *params.sun_azimuth_deg, *sky.turbidity};
  const glm::vec3 sunlight = linear(*sky.sunlight) * static_cast<float>(*sky.sun_strength);
  const float sun_up = static_cast<float>(std::clamp((*params.sun_elevation_deg + 2.0) / 6.0, 0.0, 1.0));
  const glm::vec3 sun_dir = direction_of(*params.sun_azimuth_deg, *params.sun_elevation_deg);
  const float cover = static_cast<float>(*sky.cloud_cover);
  float cloud_average = 0.0f;
  if (clouds != nullptr && !clouds->empty()) {
    double sum = 0.0;
    for (float d : clouds->values()) sum += std::min(d, 1.0f);
    cloud_average = static_cast<float>(sum / static_cast<double>(clouds->size()));
  }
  context.report("render: sky", 0.0);

  // The clear sky, and over it the clouds, lit by the sun's colour (brighter toward the sun,
  // darker where thick) and by the sky around them. Overcast skies are grey whatever the model.
  parallel_for(0, height, [&](int j) {
    const double elevation = elevation_of_row(j, height);
    for (int i = 0; i < width; ++i) {
      const double azimuth = azimuth_of_column(i, width);
      const Rgb clear = sky_colour(sky.model, inputs, std::max(elevation, 0.0), azimuth);
      // A little darker below the horizon.
      const float dim = elevation < 0.0 ? static_cast<float>(1.0 + elevation / 40.0) : 1.0f;
      glm::vec3 colour = glm::vec3(clear.r, clear.g, clear.b) * dim;
      float alpha = 0.0f;
      if (clouds != nullptr && !clouds->empty()) {
        const float density = cloud_at(*clouds, cloud_average, azimuth, elevation);
        if (density > 0.0f) {
          const float toward_sun = std::max(glm::dot(direction_of(azimuth, elevation), sun_dir), 0.0f);
          // Clouds are grey in the sky's light (its brightness, not its blue) and white in the sun's.
          const float sky_luminance = 0.2126f * colour.r + 0.7152f * colour.g + 0.0722f * colour.b;
          const glm::vec3 ambient = glm::vec3(0.8f * sky_luminance + 0.03f) + colour * 0.15f;
          const glm::vec3 lit = sunlight * sun_up * (0.55f + 0.45f * toward_sun * toward_sun) * (1.0f - 0.45f * density);
          const glm::vec3 cloud = (ambient + lit) * (1.0f - 0.35f * cover);
          alpha = std::clamp(density, 0.0f, 1.0f);
          colour = colour + (cloud - colour) * alpha;
        }
      }
      float* texel = &dome.rgba[4 * (static_cast<std::size_t>(j) * width + i)];
      texel[0] = colour.r, texel[1] = colour.g, texel[2] = colour.b, texel[3] = alpha;
      float* clear_texel = &dome.clear[4 * (static_cast<std::size_t>(j) * width + i)];
      clear_texel[0] = clear.r * dim, clear_texel[1] = clear.g * dim, clear_texel[2] = clear.b * dim;
    }
  });
  context.check_cancelled();

  const Rgb zenith = sky_colour(sky.model, inputs, 90.0, 0.0);
  dome.stars = visible_stars(sky, star_visibility({zenith.r, zenith.g, zenith.b}));
  add_stars(dome, dome.stars);

  // The cloud field for the renderer: density and optical depth (thick over about a
  // fortieth of the image, a cumulus' width).
  if (clouds != nullptr && !clouds->empty() && clouds->width() == clouds->height()) {
    const Grid<float> thickness = cloud_thickness(*clouds, std::max(clouds->width() / 80, 1));
    dome.clouds_size = clouds->width();
    dome.clouds.resize(clouds->size() * 2);
    for (std::size_t i = 0; i < clouds->size(); ++i) {
      dome.clouds[2 * i] = std::min(clouds->data()[i], 1.0f);
      dome.clouds[2 * i + 1] = thickness.data()[i];
    }
    dome.cloud_cover = cover;
    dome.cloud_sunlight = sunlight * sun_up;
  }

  // The sky's light on the ground: the upper hemisphere, cosine-weighted.
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (int j = 0; j < height; ++j) {
    const double elevation = elevation_of_row(j, height);
    if (elevation <= 0.0) continue;
    const double w = std::sin(elevation * degrees) * std::cos(elevation * degrees);  // cosine lobe times the row's solid angle
    for (int i = 0; i < width; ++i) {
      const float* texel = &dome.rgba[4 * (static_cast<std::size_t>(j) * width + i)];
      sum += glm::dvec3(texel[0], texel[1], texel[2]) * w;
      weight += w;
    }
  }
  dome.sky_light = weight > 0.0 ? glm::vec3(sum / weight) : glm::vec3(0.0f);
  context.report("render: sky", 1.0);
  return dome;
}

std::vector<glm::vec3> horizon_haze(const SkyDome& dome) {
  const auto width = static_cast<std::size_t>(std::max(dome.width, 0));
  std::vector<glm::vec3> row(width, glm::vec3(0.0f));
  if (width == 0 || dome.height <= 0 || dome.rgba.size() < width * static_cast<std::size_t>(dome.height) * 4) return row;
  const double at = (dome_top_deg - haze_elevation_deg) / (dome_top_deg - dome_bottom_deg) * dome.height - 0.5;
  const int row0 = std::clamp(static_cast<int>(std::floor(at)), 0, dome.height - 1), row1 = std::min(row0 + 1, dome.height - 1);
  const auto between = static_cast<float>(std::clamp(at - row0, 0.0, 1.0));
  for (std::size_t i = 0; i < width; ++i) {
    const auto texel = [&](int y) {
      const std::size_t texel_at = (static_cast<std::size_t>(y) * width + i) * 4;
      return glm::vec3(dome.rgba[texel_at], dome.rgba[texel_at + 1], dome.rgba[texel_at + 2]);
    };
    row[i] = texel(row0) + (texel(row1) - texel(row0)) * between;
  }
  // Twice a box of 10 degrees each side, round the horizon: a smooth average of the clouds there.
  const std::size_t reach = width / 36;
  for (int pass = 0; pass < 2 && reach > 0; ++pass) {
    std::vector<glm::vec3> averaged(width);
    for (std::size_t i = 0; i < width; ++i) {
      glm::vec3 sum(0.0f);
      for (std::size_t k = 0; k <= 2 * reach; ++k) sum += row[(i + width - reach + k) % width];
      averaged[i] = sum / static_cast<float>(2 * reach + 1);
    }
    row = std::move(averaged);
  }
  return row;
}

}  // namespace sansui::look
