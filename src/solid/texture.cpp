// Marble, wood and strata (see texture.hpp).
#include "solid/texture.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/exact_math.hpp"
#include "core/random.hpp"

namespace sansui::solid {
namespace {

constexpr double log2_e = 1.4426950408889634074;
constexpr double pi = 3.14159265358979323846;

/// e^-x for x >= 0, the same bytes everywhere (exact_exp2, not libm).
double exp_minus(double x) {
  return x > 700.0 ? 0.0 : exact_exp2(-x * log2_e);
}

/// sin and cos of an angle in degrees by their Taylor series (+, -, *, / only), for the few
/// angles a texture has; identical on every platform.
std::pair<double, double> sin_cos_deg(double degrees) {
  const double turns = degrees / 360.0;
  const double a = (turns - std::nearbyint(turns)) * 2.0 * pi;  // in [-pi, pi]
  double sine = 0.0, cosine = 0.0, term_s = a, term_c = 1.0;
  for (int k = 0; k < 30; ++k) {
    sine += term_s;
    cosine += term_c;
    term_s = -term_s * a * a / ((2 * k + 2) * (2 * k + 3));
    term_c = -term_c * a * a / ((2 * k + 1) * (2 * k + 2));
  }
  return {sine, cosine};
}

Rgb mix(const Rgb& a, const Rgb& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
Rgb scaled(const Rgb& c, float s) {
  return {c.r * s, c.g * s, c.b * s};
}
Rgb clamped(const Rgb& c) {
  return {std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f)};
}

float smoothstep(float edge0, float edge1, float v) {
  const float t = std::clamp((v - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

Rgb rgb(int r, int g, int b) {
  return {static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f, static_cast<float>(b) / 255.0f};
}

SolidTexture white_marble() {
  SolidTexture t;
  t.kind = TextureKind::marble;
  t.name = "white-marble";
  // Carrara-like: a white ground mass crossed by grey veins of several widths.
  t.marble.period = 0.32;
  t.marble.layers = {{0.03, 0.008, 70.0}, {0.12, 0.002, 110.0}, {0.2, 0.016, 30.0}, {0.27, 0.001, 150.0}};
  t.marble.strength = 0.22;
  t.marble.palette = {{{0.0f, rgb(240, 238, 233)}, {0.35f, rgb(218, 217, 214)}, {0.75f, rgb(160, 162, 166)}, {1.0f, rgb(110, 112, 118)}}};
  return t;
}

SolidTexture green_marble() {
  SolidTexture t;
  t.kind = TextureKind::marble;
  t.name = "green-marble";
  // Verde: a deep green ground with pale serpentine veins.
  t.marble.period = 0.26;
  t.marble.layers = {{0.03, 0.01, 60.0}, {0.09, 0.001, 140.0}, {0.14, 0.004, 90.0}, {0.2, 0.02, 28.0}};
  t.marble.strength = 0.26;
  t.marble.palette = {{{0.0f, rgb(18, 56, 40)}, {0.25f, rgb(34, 92, 64)}, {0.6f, rgb(120, 170, 138)}, {1.0f, rgb(226, 238, 224)}}};
  return t;
}

SolidTexture oak() {
  SolidTexture t;
  t.kind = TextureKind::wood;
  t.name = "oak";
  t.wood.axis = 1;  // the trunk runs away from the viewer: rings show on the front faces
  t.wood.centre_u = 0.18;
  t.wood.centre_v = -0.35;
  t.wood.ring_spacing = 0.032;
  t.wood.late_fraction = 0.4;
  t.wood.strength = 0.025;
  t.wood.grain = 0.07;
  t.wood.palette = {{{0.0f, rgb(206, 162, 112)}, {0.45f, rgb(176, 128, 80)}, {1.0f, rgb(120, 78, 42)}}};
  return t;
}

SolidTexture pine() {
  SolidTexture t;
  t.kind = TextureKind::wood;
  t.name = "pine";
  t.wood.axis = 1;
  t.wood.centre_u = 0.62;
  t.wood.centre_v = -0.25;
  t.wood.ring_spacing = 0.06;
  t.wood.late_fraction = 0.22;
  t.wood.strength = 0.04;
  t.wood.grain = 0.04;
  t.wood.palette = {{{0.0f, rgb(238, 208, 156)}, {0.5f, rgb(218, 168, 104)}, {1.0f, rgb(170, 98, 44)}}};
  return t;
}

SolidTexture strata() {
  SolidTexture t;
  t.kind = TextureKind::strata;
  t.name = "strata";
  t.strata.rocks = {rgb(186, 160, 122), rgb(150, 136, 118), rgb(118, 110, 104), rgb(196, 186, 162),
                    rgb(164, 112, 84),  rgb(136, 124, 100), rgb(176, 150, 110)};
  return t;
}

}  // namespace

Rgb Palette::at(float t) const {
  if (stops.empty()) return {t, t, t};
  if (!(t > stops.front().first)) return stops.front().second;
  for (std::size_t i = 1; i < stops.size(); ++i)
    if (t <= stops[i].first) {
      const float span = stops[i].first - stops[i - 1].first;
      return mix(stops[i - 1].second, stops[i].second, span > 0.0f ? (t - stops[i - 1].first) / span : 1.0f);
    }
  return stops.back().second;
}

void SolidTexture::validate() const {
  switch (kind) {
    case TextureKind::field:
      break;
    case TextureKind::marble:
      if (!(marble.period >= 0.0) || !std::isfinite(marble.period)) fail("marble period {} is not allowed: it must be >= 0", marble.period);
      if (!std::isfinite(marble.strength)) fail("marble strength {} is not a finite number", marble.strength);
      for (const auto& layer : marble.layers) {
        if (!std::isfinite(layer.centre)) fail("marble layer centre {} is not a finite number", layer.centre);
        if (!(layer.width >= 0.0) || !std::isfinite(layer.width))
          fail("marble layer width {} is not allowed: it must be >= 0", layer.width);
        if (!(layer.falloff > 0.0) || !std::isfinite(layer.falloff))
          fail("marble layer fall-off {} is not allowed: it must be > 0", layer.falloff);
      }
      break;
    case TextureKind::wood:
      if (wood.axis < 0 || wood.axis > 2) fail("wood axis {} is not allowed: it must be 0 (x), 1 (y) or 2 (z)", wood.axis);
      if (!(wood.ring_spacing > 0.0) || !std::isfinite(wood.ring_spacing))
        fail("ring spacing {} is not allowed: it must be > 0", wood.ring_spacing);
      if (!(wood.late_fraction > 0.0 && wood.late_fraction < 1.0))
        fail("late-wood fraction {} is not allowed: it must be between 0 and 1", wood.late_fraction);
      if (!std::isfinite(wood.strength) || !(wood.grain >= 0.0))
        fail("wood strength {} or grain {} is not allowed", wood.strength, wood.grain);
      break;
    case TextureKind::strata:
      if (!(strata.thickness > 0.0) || !std::isfinite(strata.thickness))
        fail("bed thickness {} is not allowed: it must be > 0", strata.thickness);
      if (!(strata.thickness_jitter >= 0.0 && strata.thickness_jitter < 0.5))
        fail("thickness jitter {} is not allowed: it must be in [0, 0.5)", strata.thickness_jitter);
      if (!(strata.dip_deg >= 0.0 && strata.dip_deg <= 60.0)) fail("dip {} degrees is not allowed: it must be 0..60", strata.dip_deg);
      if (!std::isfinite(strata.dip_azimuth_deg) || !std::isfinite(strata.strength))
        fail("dip azimuth {} or strength {} is not a finite number", strata.dip_azimuth_deg, strata.strength);
      if (strata.rocks.empty()) fail("strata need at least one rock colour");
      break;
  }
}

std::vector<std::string> texture_names() {
  return {"white-marble", "green-marble", "oak", "pine", "strata", "marble", "wood", "field"};
}

SolidTexture texture_preset(std::string_view name) {
  if (name == "white-marble" || name == "marble") return white_marble();
  if (name == "green-marble") return green_marble();
  if (name == "oak" || name == "wood") return oak();
  if (name == "pine") return pine();
  if (name == "strata") return strata();
  if (name == "field") {
    SolidTexture t;
    t.kind = TextureKind::field;
    t.name = "field";
    return t;
  }
  fail("texture '{}' is unknown: allowed are white-marble, green-marble, oak, pine, strata, marble, wood, field", name);
}

double marble_base(const MarbleParams& params, double z) {
  if (params.period > 0.0) z -= params.period * std::floor(z / params.period);
  double sum = 0.0;
  for (const auto& layer : params.layers)
    for (int copy = -1; copy <= 1; ++copy) {
      if (copy != 0 && params.period <= 0.0) continue;
      const double distance = std::abs(z - (layer.centre + copy * params.period)) - 0.5 * layer.width;  // d_i
      sum += distance > 0.0 ? exp_minus(layer.falloff * distance) : 1.0;
    }
  return sum;
}

double texture_gloss(const SolidTexture& texture) {
  switch (texture.kind) {
    case TextureKind::marble:
      return 0.35;
    case TextureKind::wood:
      return 0.12;
    default:
      return 0.04;
  }
}

TextureSampler::TextureSampler(const SolidTexture& texture) : texture_(texture) {
  texture_.validate();
  if (texture_.kind == TextureKind::strata) {
    const auto [dip_sin, dip_cos] = sin_cos_deg(texture_.strata.dip_deg);
    const auto [az_sin, az_cos] = sin_cos_deg(texture_.strata.dip_azimuth_deg);
    const double slope = dip_sin / dip_cos;
    dip_x_ = slope * az_cos;
    dip_y_ = slope * az_sin;
  }
}

Rgb TextureSampler::color(double x, double y, double z, float d) const {
  switch (texture_.kind) {
    case TextureKind::field: {
      const float grey = std::clamp(0.5f + 0.2f * d, 0.0f, 1.0f);
      return {grey, grey, grey};
    }
    case TextureKind::marble: {
      const MarbleParams& m = texture_.marble;
      const double g = marble_base(m, z + m.strength * d);  // G at P' = P + (0, 0, k D(P))
      return m.palette.at(static_cast<float>(std::min(g, 1.0)));
    }
    case TextureKind::wood: {
      const WoodParams& w = texture_.wood;
      const double p[3] = {x, y, z};
      const double u = p[w.axis == 0 ? 1 : 0] - w.centre_u;
      const double v = p[w.axis == 2 ? 1 : 2] - w.centre_v;
      const double radius = std::sqrt(u * u + v * v) + w.strength * d;
      const double rings = radius / w.ring_spacing;
      const auto t = static_cast<float>(rings - std::floor(rings));  // position within the ring
      const auto early = static_cast<float>(1.0 - w.late_fraction);
      // Early wood darkens slowly; late wood darkens fast and ends sharply at the next ring.
      float g = t < early ? 0.25f * t / early : 0.25f + 0.75f * smoothstep(0.0f, 0.35f, (t - early) / (1.0f - early));
      g *= 1.0f - smoothstep(0.97f, 1.0f, t);  // a narrow, not infinitely sharp, ring boundary
      return clamped(scaled(w.palette.at(g), 1.0f + static_cast<float>(w.grain) * d));
    }
    case TextureKind::strata:
      return strata_color(x, y, z, d);
  }
  return {};
}

/// Beds of thickness T (1 +- jitter): bed i spans [b_i, b_(i+1)), b_i = T (i + jitter (u_i - 1/2)),
/// so the bounds stay ordered. Each bed takes a rock colour and a brightness from its hash; a
/// thin darker parting marks its base and faint laminae run through it.
Rgb TextureSampler::strata_color(double x, double y, double z, float d) const {
  const StrataParams& s = texture_.strata;
  const double height = z + dip_x_ * x + dip_y_ * y + s.strength * d;
  auto bound = [&](double bed) {
    const auto index = static_cast<std::int32_t>(bed);
    return s.thickness * (bed + s.thickness_jitter * (rng::uniform(s.seed, 1, index, 0) - 0.5));
  };
  double bed = std::floor(height / s.thickness);
  if (height < bound(bed))
    bed -= 1.0;
  else if (height >= bound(bed + 1.0))
    bed += 1.0;
  const double bottom = bound(bed), top = bound(bed + 1.0);
  const auto f = static_cast<float>((height - bottom) / (top - bottom));  // 0 at the base, 1 at the top
  const auto index = static_cast<std::int32_t>(bed);
  const auto rock = static_cast<std::size_t>(rng::uniform(s.seed, 2, index, 0) * static_cast<double>(s.rocks.size()));
  const float brightness = 0.88f + 0.24f * static_cast<float>(rng::uniform(s.seed, 2, index, 1));
  const float laminae = static_cast<float>((height - bottom) / (0.17 * s.thickness));
  const float lamina = 1.0f - 0.05f * std::abs(2.0f * (laminae - std::floor(laminae)) - 1.0f);
  const float parting = 0.72f + 0.28f * smoothstep(0.0f, 0.08f, f);
  return clamped(scaled(s.rocks[std::min(rock, s.rocks.size() - 1)], brightness * lamina * parting));
}

}  // namespace sansui::solid
