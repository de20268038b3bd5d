// Solid textures of Okada, Taga, Yokoi, Toriwaki (1990; seeds/002, Sec. 3; SPEC 2): a regular
// base function G describes the material's structure, and a textured point P shows G at
// P' = F(P, D(P)), i.e. the structure displaced by the fractal field D.
//  - marble: G(P) = sum_i g_i(z), g_i(z) = exp(-alpha_i d_i) for d_i > 0 else 1,
//    d_i = |z - c_i| - w_i / 2 (eq. 6), with F = P + (0, 0, k D(P)) (eq. 7);
//  - wood: rings around an axis, the radius displaced by k D(P) (mentioned in Sec. 3-2);
//  - strata: sedimentary beds of varying thickness and rock, with a gentle dip, the bedding
//    displaced by k D(P) (our addition, for cliffs on terrain).
// G maps to colour through a palette. Positions are in block units: the field's block is
// [0, 1]^3 whatever its number of levels, so a texture looks the same at every resolution.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sansui::solid {

/// A colour, components in [0, 1] (sRGB).
struct Rgb {
  float r = 0.0f, g = 0.0f, b = 0.0f;
};

/// Colour stops (t, colour) with t ascending: linear between stops, the end colours outside.
struct Palette {
  std::vector<std::pair<float, Rgb>> stops;
  Rgb at(float t) const;
};

/// One layer of marble (eq. 6).
struct MarbleLayer {
  double centre = 0.5;    ///< c_i: where the layer is centred along z. [Units: block]
  double width = 0.02;    ///< w_i: full width of the layer's core. [Units: block] [Range: >= 0]
  double falloff = 50.0;  ///< alpha_i: how fast the layer fades beyond its core. [Units: 1/block] [Range: > 0]
};

struct MarbleParams {
  /// The layers, summed (eq. 6). [Default: one layer at 0.5]
  std::vector<MarbleLayer> layers{MarbleLayer{}};
  /// The layers repeat every `period` along z; 0: only the listed layers. [Units: block] [Range: >= 0] [Default: 0]
  double period = 0.0;
  /// k of eq. 7: z is displaced by k * D(P). [Units: block per unit of D] [Default: 0.1]
  double strength = 0.1;
  /// Colour of G: 0 the ground mass, 1 the core of a vein.
  Palette palette;
};

struct WoodParams {
  /// Axis of the trunk: 0 along x, 1 along y, 2 along z. [Default: 2]
  int axis = 2;
  /// Where the trunk's axis crosses the plane of the two other axes (in axis order). [Units: block]
  double centre_u = 0.5, centre_v = 0.5;
  /// Distance between growth rings. [Units: block] [Range: > 0] [Default: 0.05]
  double ring_spacing = 0.05;
  /// Fraction of each ring that is dark late wood. [Range: 0 < f < 1] [Default: 0.3]
  double late_fraction = 0.3;
  /// k: the radius is displaced by k * D(P). [Units: block per unit of D] [Default: 0.03]
  double strength = 0.03;
  /// Brightness varies by grain * D(P): the figure of the wood. [Range: >= 0] [Default: 0.05]
  double grain = 0.05;
  /// Colour of G: 0 early wood, 1 late wood.
  Palette palette;
};

struct StrataParams {
  /// Mean thickness of a bed. [Units: block] [Range: > 0] [Default: 0.03]
  double thickness = 0.03;
  /// Beds vary in thickness by up to this fraction either way. [Range: 0 <= j < 0.5] [Default: 0.35]
  double thickness_jitter = 0.35;
  /// Tilt of the bedding planes. [Units: degrees] [Range: 0..60] [Default: 8]
  double dip_deg = 8.0;
  /// Direction the beds dip towards, from +x towards +y. [Units: degrees] [Default: 30]
  double dip_azimuth_deg = 30.0;
  /// k: the bedding is displaced by k * D(P). [Units: block per unit of D] [Default: 0.01]
  double strength = 0.01;
  /// Rock colours the beds choose from (by a hash of the bed's index). [Range: not empty]
  std::vector<Rgb> rocks;
  /// Seed of the beds' thicknesses and rocks. [Default: 1]
  std::uint64_t seed = 1;
};

enum class TextureKind {
  field,  ///< D itself in grey: 0.5 + 0.2 D
  marble,
  wood,
  strata,
};

struct SolidTexture {
  TextureKind kind = TextureKind::marble;
  std::string name;
  MarbleParams marble;
  WoodParams wood;
  StrataParams strata;

  /// Throws InputError naming the first bad parameter.
  void validate() const;
};

/// Presets: white-marble, green-marble, oak, pine, strata; aliases marble (white-marble) and wood
/// (oak); and field (D in grey). Throws InputError listing the names for anything else.
SolidTexture texture_preset(std::string_view name);
/// The names texture_preset accepts.
std::vector<std::string> texture_names();

/// G of marble at height z (eq. 6), before displacement; not clamped (overlapping layers add).
double marble_base(const MarbleParams& params, double z);

/// Colours of one texture, with what does not depend on the point worked out once.
class TextureSampler {
 public:
  /// Throws InputError for bad parameters (see SolidTexture::validate).
  explicit TextureSampler(const SolidTexture& texture);
  /// The colour at block point (x, y, z) where the field's value is d.
  Rgb color(double x, double y, double z, float d) const;
  const SolidTexture& texture() const { return texture_; }

 private:
  Rgb strata_color(double x, double y, double z, float d) const;
  SolidTexture texture_;
  double dip_x_ = 0.0, dip_y_ = 0.0;  // rise of the bedding per block unit along x and y
};

/// How shiny the material is (polished marble more than wood or rock), for shading.
double texture_gloss(const SolidTexture& texture);

}  // namespace sansui::solid
