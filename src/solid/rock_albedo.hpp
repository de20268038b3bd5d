// Rock on terrain: the colour of a solid texture (Okada et al. 1990; seeds/002, Sec. 3; SPEC 2)
// at every surface point of a heightfield, for the renderer to use on steep cliffs, so cliffs
// show layered rock that continues around corners and across ridges as real strata do. The
// field is evaluated with Type IV (a small Type I array for the upper levels, ancestors below),
// so a fine field over a whole terrain needs no huge array.
#pragma once

#include <cstdint>
#include <string>

#include "core/color.hpp"
#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"

namespace sansui::solid {

/// Table: solid_params.cpp (section [rock]).
struct RockParams {
  /// Texture preset: strata (sedimentary beds), white-marble, green-marble, ..., or none (no
  /// rock: the renderer keeps its cliff colour). [Default: none]
  std::string texture = "none";
  /// Seed of the field and of the beds. [Default: 1]
  std::uint64_t seed = 1;
  /// Field levels R; the field has 2^R cells along the terrain's largest extent. [Range: 1..20] [Default: 11]
  int levels = 11;
  /// Type IV's array levels. [Range: 0..levels] [Default: 6]
  int r2 = 6;
  /// Field decay constant beta. [Range: > 0] [Default: 0.6]
  double beta = 0.6;
  /// Metres per field cell; 0: the terrain's largest extent (east, south or relief) / 2^R, with
  /// the block at the heightfield's origin and lowest point. Give a value to anchor the field to
  /// world coordinates (x / cell, y / cell, height / cell + 2^(R-1)), so tiles of one world join.
  /// [Units: m] [Range: >= 0] [Default: 0]
  double field_cell_m = 0.0;
  /// One texture block spans this many metres: the preset's sizes (bed thickness, vein spacing,
  /// displacement) are fractions of it. [Units: m] [Range: > 0] [Default: 1000]
  double texture_size_m = 1000.0;

  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<RockParams>& parameter_table(const RockParams*);

/// The texture's colour at each sample's surface point (east, south, height), same size as
/// `heights`. Every sample is computed (the renderer blends it in by slope); rows in parallel,
/// the same bytes for any thread count. Throws InputError for bad parameters or a heightfield
/// with NaN heights. Texture "none" gives an empty image.
Image rock_albedo(const Heightfield& heights, const RockParams& params, const Context& context = quiet_context());

}  // namespace sansui::solid
