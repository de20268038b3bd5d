// Shadows and ambient occlusion traced over the heightfield on the CPU, uploaded as a texture.
//
// Why not a GPU shadow map: a shadow map of a million-triangle terrain seen in perspective
// needs cascades and depth biases to avoid acne, peter-panning and stair-stepped edges, and
// costs an extra pass on a software rasteriser (llvmpipe in CI). A horizon sweep over the
// grid is exact at the grid's resolution, has no bias to tune, gives soft penumbrae for the
// price of a few passes, makes the same picture on every GPU, and costs O(samples) per pass
// (about 20 ms for 1025^2). The viewer recomputes it when the sun moves.
//
// Ambient occlusion is horizon-based: for a horizontal surface whose horizon stands at
// elevation a all around, the cosine-weighted fraction of open sky is cos^2 a, so each
// sample's sky visibility is 1 - mean over 8 directions of sin^2(horizon elevation).
#pragma once

#include "core/grid.hpp"

namespace sansui::look {

struct SunShadowParams {
  /// Compass bearing of the sun, clockwise from north. [Units: degrees] [Default: 300]
  double azimuth_deg = 300.0;
  /// Sun height above the horizon. [Units: degrees] [Range: 0..90] [Default: 32]
  double elevation_deg = 32.0;
  /// Multiplies every height first (the renderer's vertical exaggeration). [Range: > 0] [Default: 1]
  double vertical_scale = 1.0;
  /// Half the angle over which the shadow edge fades (the sun's disc, widened so that the edge
  /// looks soft at the grid's resolution). [Units: degrees] [Range: 0..10] [Default: 1.2]
  double penumbra_deg = 1.2;
};

/// Fraction of the sun seen from each sample, in [0, 1] (1: fully lit, 0: in shadow); the same
/// size as `heights`. Slopes facing away from the sun are also 0 (they shade themselves).
/// Grid y points south, x east; the sun is at the given compass bearing.
Grid<float> sun_visibility(const Heightfield& heights, const SunShadowParams& params);

struct AmbientOcclusionParams {
  /// Multiplies every height first. [Range: > 0] [Default: 1]
  double vertical_scale = 1.0;
  /// How far to look for the horizon. [Units: samples] [Range: >= 1] [Default: 64]
  int radius_samples = 64;
};

/// Cosine-weighted fraction of open sky above each sample, in [0, 1] (1: flat open ground).
Grid<float> ambient_occlusion(const Heightfield& heights, const AmbientOcclusionParams& params);

}  // namespace sansui::look
