// The land (or sea) around the generated area, out to the horizon: a perspective picture shows
// the area inside its world instead of a block floating in the sky (issue 31). The surroundings
// are one grid whose spacing grows with the distance from the area: the same as the area's drawn
// mesh at its border, about forty times coarser at the far edge. Their heights continue the
// area's: at the border they are its edge heights, and further out a fractal of the area's own
// relief and roughness (a Hurst exponent's spectrum) takes over, around the level of the area's
// border, or open sea. Plain data, built on the CPU; render/ draws it with the terrain's program.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/grid.hpp"
#include "look/terrain_mesh.hpp"

namespace sansui::look {

/// What lies beyond the area.
enum class Beyond {
  land,  ///< the area's land goes on: its border continued by a fractal of its own relief
  sea,   ///< open sea: the land falls away to a sea floor within a fifth of the area's size
};

/// One axis of the surroundings' grid: grid index i (0..samples-1) to metres from the area's
/// north-west sample. The middle `2 * inner + 1` samples span the area evenly (its border falls
/// on samples middle - inner and middle + inner); outward the spacing grows geometrically, at the
/// same rate on the first step, up to `reach_m` from the area's centre.
struct SurroundingsAxis {
  int samples = 513;      ///< odd
  int inner = 55;         ///< samples from the middle to the area's border
  double centre_m = 0.0;  ///< the area's centre on this axis
  double half_m = 1.0;    ///< half the area's extent on this axis
  double growth = 1.0;    ///< exponent's rate past the border (1: the spacing is continuous)

  /// Metres of grid index i (fractional indices allowed).
  double position_m(double i) const;
  /// The grid index of a position (the inverse of position_m).
  double index_of(double position_m) const;
  /// Indices of the area's border samples.
  int first_inside() const { return (samples - 1) / 2 - inner; }
  int last_inside() const { return (samples - 1) / 2 + inner; }
};

/// Builds an axis reaching `reach_m` from the centre of an area `extent_m` wide on it.
SurroundingsAxis make_surroundings_axis(double extent_m, double reach_m, int samples);

struct Surroundings {
  SurroundingsAxis x_axis, z_axis;  ///< east and south
  /// Heights in metres at the grid's samples (cell_size_m is the spacing at the border; the
  /// true positions are the axes'). Inside the area they are the area's own.
  Heightfield heights;
  /// Per sample: height, dh/dx east, dh/dz south, 0, as the area's surface texture (true slopes
  /// on the uneven grid).
  std::vector<float> surface_texels;
  /// The mesh: four floats a vertex (grid u and v as fractions 0..1, height, 0), strips of rows
  /// with the area's cells left out; the area is drawn by its own mesh.
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  double reach_m = 0.0;         ///< from the area's centre to the far edge
  double mirror_reach_m = 0.0;  ///< past the area's border, its mirror image fades out over this

  bool empty() const { return heights.empty(); }
};

/// The surroundings of `area` (heights in metres; its cell size sets its extent) for a picture
/// whose sea is at `sea_level_m`; with `floor_m`, no height below it (a picture without a sea
/// keeps its land above the lowest valley). `samples` per side (odd, at least 65). The result
/// depends only on the arguments: the same area gives the same bytes. Uses the parallel seam.
Surroundings build_surroundings(const Heightfield& area, double sea_level_m, Beyond beyond, std::optional<double> floor_m = {},
                                int samples = 513);

/// The shading texture's texels for the surroundings (as TerrainRenderer's for the terrain):
/// full sun and open sky (no shadows are traced out there), and the same two band noises as
/// look::band_noise_texels() at the same places, so that band borders run on across the seam.
std::vector<std::uint8_t> surroundings_shading_texels(const Surroundings& s, double terrain_size_m);

/// How far the surroundings reach from the area's centre: twelve times its size, at least
/// 80 km (a hill 500 m high sees 80 km to the horizon), at most 2,000 km. [Units: m]
double surroundings_reach_m(double area_size_m);

}  // namespace sansui::look
