// View and projection matrices of the views (perspective orbit or walkthrough; top, front and
// side orthographic). Drawing coordinates: x east and z south in
// metres from the terrain's north-west sample, y up in metres above sea level times the
// vertical exaggeration (a right-handed frame: east x up = south).
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "look/render_params.hpp"

namespace sansui::look {

/// The box the terrain occupies in drawing coordinates.
struct TerrainFrame {
  double width_m = 1.0;   ///< extent east (x). [Units: m] [Range: > 0]
  double depth_m = 1.0;   ///< extent south (z). [Units: m] [Range: > 0]
  double min_y = 0.0;     ///< lowest drawn point (skirt base included)
  double max_y = 1.0;     ///< highest drawn point
  double target_y = 0.0;  ///< drawn height of the camera's target
  /// Points the fitted perspective camera keeps in the picture (e.g. a coarse grid of the
  /// surface and the base corners); empty: the box's corners.
  std::span<const glm::dvec3> fit_points;
  double eye_ground_y = 0.0;  ///< drawn height of the ground (or sea) under a walkthrough camera's eye
  /// Land or sea drawn around the terrain out to this far from its centre (look/surroundings.hpp):
  /// the far plane takes it in, and the near plane comes close enough for the ground between
  /// the camera and the terrain. 0: the terrain alone. [Units: m]
  double surroundings_reach_m = 0.0;

  double size_m() const { return width_m > depth_m ? width_m : depth_m; }
};

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 position{0.0f};              ///< eye position (perspective) or a point above the terrain (top)
  glm::vec3 forward{0.0f, -1.0f, 0.0f};  ///< unit view direction
  double nearest_m = 0.0;                ///< distance from the eye to the nearest corner of the terrain's box (perspective)
  bool orthographic = false;
  bool walking = false;  ///< a walkthrough eye: the sky is drawn in its true directions
};

/// The camera of `params.view` for a picture of width x height pixels.
CameraMatrices camera_matrices(const RenderParams& params, const TerrainFrame& frame, int width, int height);

}  // namespace sansui::look
