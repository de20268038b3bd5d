#include "look/surroundings.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"

namespace sansui::look {
namespace {

// The fractal beyond the area: octaves from twice the area's size down to a 128th of it, each
// 2^-hurst as strong as the one before (the spectrum of a self-affine surface).
constexpr int octaves = 9;
constexpr double hurst = 0.75;
// The area's mirror image fades into the fractal over this many area sizes past its border
// (into the sea floor over the shorter one).
constexpr double border_reach = 0.6;
constexpr double sea_border_reach = 0.15;
// Land beyond continues the spectrum upward too: this many octaves above the fractal's largest
// (wavelengths 4 and 8 area sizes, each 2^hurst as strong as the one below), rising in over
// ranges_rise area sizes past the border, so that hills and ranges stand on the horizon and give
// the scene its scale, without a step where the area's mirror image ends.
constexpr int range_octaves = 2;
constexpr double ranges_rise = 2.0;

/// Bilinear sample of a heightfield at (x, z) metres from its north-west sample, clamped to it.
float bilinear(const Heightfield& h, double x_m, double z_m) {
  const double fx = std::clamp(x_m / h.cell_size_m, 0.0, static_cast<double>(h.width() - 1));
  const double fz = std::clamp(z_m / h.cell_size_m, 0.0, static_cast<double>(h.height() - 1));
  const int x0 = std::min(static_cast<int>(fx), h.width() - 2), z0 = std::min(static_cast<int>(fz), h.height() - 2);
  const double u = fx - x0, v = fz - z0;
  const double top = h(x0, z0) + (h(x0 + 1, z0) - h(x0, z0)) * u;
  const double bottom = h(x0, z0 + 1) + (h(x0 + 1, z0 + 1) - h(x0, z0 + 1)) * u;
  return static_cast<float>(top + (bottom - top) * v);
}

/// Perlin's gradient noise at (x, y) lattice units, about -1..1, eight gradient directions
/// picked by the counter-based hash (no libm: the same bytes everywhere).
double gradient_noise(std::uint64_t key, double x, double y) {
  static constexpr std::array<std::array<double, 2>, 8> gradients{{{1, 0},
                                                                   {-1, 0},
                                                                   {0, 1},
                                                                   {0, -1},
                                                                   {0.7071067811865476, 0.7071067811865476},
                                                                   {-0.7071067811865476, 0.7071067811865476},
                                                                   {0.7071067811865476, -0.7071067811865476},
                                                                   {-0.7071067811865476, -0.7071067811865476}}};
  const double fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
  const double tx = x - fx, ty = y - fy;
  auto corner = [&](std::int32_t i, std::int32_t j, double dx, double dy) {
    const auto& g = gradients[rng::bits(key, rng::pack(ix + i, iy + j)) & 7u];
    return g[0] * dx + g[1] * dy;
  };
  auto fade = [](double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); };
  const double sx = fade(tx), sy = fade(ty);
  const double top = corner(0, 0, tx, ty) + (corner(1, 0, tx - 1.0, ty) - corner(0, 0, tx, ty)) * sx;
  const double bottom = corner(0, 1, tx, ty - 1.0) + (corner(1, 1, tx - 1.0, ty - 1.0) - corner(0, 1, tx, ty - 1.0)) * sx;
  return top + (bottom - top) * sy;
}

/// The fractal at (x, z) metres, its largest wavelength twice `size_m`.
double fractal(std::uint64_t seed, double size_m, double x_m, double z_m) {
  double sum = 0.0, amplitude = 1.0, wavelength = 2.0 * size_m;
  for (int octave = 0; octave < octaves; ++octave) {
    // Each octave its own stream, and turned a little, so lattice lines do not stack up.
    const double c = 0.8, s = 0.6;
    const double rx = (octave % 2 == 0) ? x_m : c * x_m - s * z_m, rz = (octave % 2 == 0) ? z_m : s * x_m + c * z_m;
    sum += amplitude * gradient_noise(rng::stream_key(seed, static_cast<std::uint64_t>(octave)), rx / wavelength, rz / wavelength);
    amplitude *= std::pow(2.0, -hurst);
    wavelength *= 0.5;
  }
  return sum;
}

/// The octaves above fractal()'s, largest first: ranges of the same self-affine spectrum.
double ranges(std::uint64_t seed, double size_m, double x_m, double z_m) {
  double sum = 0.0;
  for (int octave = range_octaves; octave >= 1; --octave) {
    const double wavelength = 2.0 * size_m * std::pow(2.0, octave), amplitude = std::pow(2.0, hurst * octave);
    sum += amplitude * gradient_noise(rng::stream_key(seed, static_cast<std::uint64_t>(100 + octave)), x_m / wavelength, z_m / wavelength);
  }
  return sum;
}

/// A key from the area's border heights: every area its own surroundings, the same each time.
std::uint64_t seed_of(const Heightfield& area) {
  std::uint64_t seed = 0x53555252u;
  auto add = [&](float h) { seed = rng::mix64(seed ^ static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(h))); };
  for (int x = 0; x < area.width(); ++x) add(area(x, 0)), add(area(x, area.height() - 1));
  for (int z = 0; z < area.height(); ++z) add(area(0, z)), add(area(area.width() - 1, z));
  return seed;
}

struct BorderStatistics {
  double mean = 0.0, deviation = 0.0;
};

BorderStatistics border_statistics(const Heightfield& area) {
  double sum = 0.0, squares = 0.0;
  long long count = 0;
  auto add = [&](float h) {
    sum += h;
    squares += static_cast<double>(h) * h;
    ++count;
  };
  for (int x = 0; x < area.width(); ++x) add(area(x, 0)), add(area(x, area.height() - 1));
  for (int z = 1; z + 1 < area.height(); ++z) add(area(0, z)), add(area(area.width() - 1, z));
  const double mean = sum / static_cast<double>(count);
  return {mean, std::sqrt(std::max(squares / static_cast<double>(count) - mean * mean, 0.0))};
}

double deviation_of(const Heightfield& area) {
  double sum = 0.0, squares = 0.0;
  for (float h : area.values()) sum += h, squares += static_cast<double>(h) * h;
  const double n = static_cast<double>(area.size()), mean = sum / n;
  return std::sqrt(std::max(squares / n - mean * mean, 0.0));
}

void build_mesh(Surroundings& s) {
  const int columns = s.x_axis.samples, rows = s.z_axis.samples;
  s.vertices.reserve(static_cast<std::size_t>(columns) * rows * 4);
  for (int z = 0; z < rows; ++z)
    for (int x = 0; x < columns; ++x)
      s.vertices.insert(s.vertices.end(), {static_cast<float>(x) / static_cast<float>(columns - 1),
                                           static_cast<float>(z) / static_cast<float>(rows - 1), s.heights(x, z), 0.0f});
  auto index_of = [&](int x, int z) { return static_cast<std::uint32_t>(z * columns + x); };
  // Strips of rows; a row through the area is cut in two around it (the area draws itself).
  const int hole_x0 = s.x_axis.first_inside(), hole_x1 = s.x_axis.last_inside();
  const int hole_z0 = s.z_axis.first_inside(), hole_z1 = s.z_axis.last_inside();
  auto strip = [&](int z, int x_from, int x_to) {
    for (int x = x_from; x <= x_to; ++x) s.indices.insert(s.indices.end(), {index_of(x, z), index_of(x, z + 1)});
    s.indices.push_back(strip_restart);
  };
  for (int z = 0; z + 1 < rows; ++z) {
    if (z >= hole_z0 && z < hole_z1) {
      strip(z, 0, hole_x0);
      strip(z, hole_x1, columns - 1);
    } else {
      strip(z, 0, columns - 1);
    }
  }
}

void build_texels(Surroundings& s) {
  const int columns = s.x_axis.samples, rows = s.z_axis.samples;
  s.surface_texels.assign(static_cast<std::size_t>(columns) * rows * 4, 0.0f);
  parallel_for(0, rows, [&](int z) {
    const int north = std::max(z - 1, 0), south = std::min(z + 1, rows - 1);
    for (int x = 0; x < columns; ++x) {
      const int west = std::max(x - 1, 0), east = std::min(x + 1, columns - 1);
      float* texel = &s.surface_texels[(static_cast<std::size_t>(z) * columns + x) * 4];
      texel[0] = s.heights(x, z);
      texel[1] = static_cast<float>((s.heights(east, z) - s.heights(west, z)) / (s.x_axis.position_m(east) - s.x_axis.position_m(west)));
      texel[2] =
          static_cast<float>((s.heights(x, south) - s.heights(x, north)) / (s.z_axis.position_m(south) - s.z_axis.position_m(north)));
    }
  });
}

}  // namespace

double SurroundingsAxis::position_m(double i) const {
  const double middle = 0.5 * (samples - 1);
  const double s = (i - middle) / middle, s0 = inner / middle;
  const double a = std::abs(s);
  const double distance = a <= s0 ? a / s0 : std::exp(growth * (a - s0) / s0);
  return centre_m + (s < 0.0 ? -half_m : half_m) * distance;
}

double SurroundingsAxis::index_of(double position) const {
  const double middle = 0.5 * (samples - 1), s0 = inner / middle;
  const double d = (position - centre_m) / half_m, a = std::abs(d);
  const double s = a <= 1.0 ? a * s0 : s0 * (1.0 + std::log(a) / growth);
  return middle + (d < 0.0 ? -s : s) * middle;
}

SurroundingsAxis make_surroundings_axis(double extent_m, double reach_m, int samples) {
  assert(samples >= 65 && samples % 2 == 1 && extent_m > 0.0 && reach_m > extent_m);
  SurroundingsAxis axis;
  axis.samples = samples;
  axis.centre_m = 0.5 * extent_m;
  axis.half_m = 0.5 * extent_m;
  const double middle = 0.5 * (samples - 1), ratio = std::log(reach_m / axis.half_m);
  // The border where the spacing past it, growing by `growth`, starts at the inside's spacing.
  axis.inner = std::clamp(static_cast<int>(std::lround(middle / (1.0 + ratio))), 2, static_cast<int>(middle) - 2);
  const double s0 = axis.inner / middle;
  axis.growth = ratio * s0 / (1.0 - s0);
  return axis;
}

std::vector<std::uint8_t> surroundings_shading_texels(const Surroundings& s, double terrain_size_m) {
  // The band noises at the terrain's scales (look::band_noise_texels(): the borders wander about
  // once a terrain size, patches seven times), from the fractal rather than the terrain's
  // repeating tile, which tens of terrain sizes away would show as a grid.
  const int columns = s.x_axis.samples, rows = s.z_axis.samples;
  const std::uint64_t seed = rng::mix64(0x42414E44u);
  const auto byte = [](double noise) { return static_cast<std::uint8_t>(std::lround(std::clamp(0.5 + 0.6 * noise, 0.0, 1.0) * 255.0)); };
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(columns) * rows * 4);
  parallel_for(0, rows, [&](int z) {
    const double pz = s.z_axis.position_m(z);
    for (int x = 0; x < columns; ++x) {
      const double px = s.x_axis.position_m(x);
      std::uint8_t* texel = &texels[(static_cast<std::size_t>(z) * columns + x) * 4];
      texel[0] = 255;
      texel[1] = 255;
      texel[2] = byte(fractal(seed, 0.5 * terrain_size_m, px, pz));
      texel[3] = byte(fractal(seed + 1, terrain_size_m / 14.0, px, pz));
    }
  });
  return texels;
}

double surroundings_reach_m(double area_size_m) {
  return std::clamp(12.0 * area_size_m, 80e3, 2e6);
}

Surroundings build_surroundings(const Heightfield& area, double sea_level_m, Beyond beyond, std::optional<double> floor_m, int samples) {
  if (area.width() < 2 || area.height() < 2 || !(area.cell_size_m > 0.0))
    fail("the land around a {}x{} area cannot be made: it needs at least 2x2 samples and a cell size above 0", area.width(), area.height());
  Surroundings s;
  const double width = (area.width() - 1) * area.cell_size_m, depth = (area.height() - 1) * area.cell_size_m;
  const double size = std::max(width, depth);
  s.reach_m = surroundings_reach_m(size);
  s.x_axis = make_surroundings_axis(width, s.reach_m, samples);
  s.z_axis = make_surroundings_axis(depth, s.reach_m, samples);

  // Near the area its land runs on as its mirror image across the border: continuous in height
  // and with the same roughness (a valley cut by the edge goes on as a valley). Further out a
  // fractal of the border's own level and roughness takes over (an island's border is sea, a
  // range's border mountains), or the sea floor.
  const BorderStatistics border = border_statistics(area);
  const double relief = deviation_of(area);
  const bool sea = beyond == Beyond::sea;
  const double level = sea ? std::min(border.mean, sea_level_m - std::max(0.5 * relief, 10.0)) : border.mean;
  const double roughness = sea ? 0.1 * relief : std::max(border.deviation, relief);
  const double mirror_reach = (sea ? sea_border_reach : border_reach) * size;
  s.mirror_reach_m = mirror_reach;
  const std::uint64_t seed = seed_of(area);
  const auto reflect = [](double p, double extent) {
    const double t = std::fmod(std::abs(p), 2.0 * extent);
    return t <= extent ? t : 2.0 * extent - t;
  };

  s.heights = Heightfield(s.x_axis.samples, s.z_axis.samples, 0.0f);
  s.heights.cell_size_m = width / (2.0 * s.x_axis.inner);
  parallel_for(0, s.z_axis.samples, [&](int zi) {
    const double z = s.z_axis.position_m(zi);
    for (int xi = 0; xi < s.x_axis.samples; ++xi) {
      const double x = s.x_axis.position_m(xi);
      const double mirrored = bilinear(area, reflect(x, width), reflect(z, depth));
      const double d = std::hypot(x - std::clamp(x, 0.0, width), z - std::clamp(z, 0.0, depth));
      if (d == 0.0) {
        s.heights(xi, zi) = static_cast<float>(mirrored);
        continue;
      }
      // The mirror image fades into the fractal smoothly, fully gone at mirror_reach.
      const double t = std::min(d / mirror_reach, 1.0);
      const double keep = 1.0 - t * t * (3.0 - 2.0 * t);
      const double rise = sea ? 0.0 : std::min(d / (ranges_rise * size), 1.0);
      const double far = roughness * (fractal(seed, size, x, z) + rise * rise * ranges(seed, size, x, z));
      const double h = keep * mirrored + (1.0 - keep) * (level + far);
      s.heights(xi, zi) = static_cast<float>(floor_m ? std::max(h, *floor_m) : h);
    }
  });
  build_texels(s);
  build_mesh(s);
  return s;
}

}  // namespace sansui::look
