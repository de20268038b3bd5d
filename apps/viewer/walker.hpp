// The walkthrough camera's state and motion (WASD + mouse): a walker on the terrain whose eye
// follows the ground at eye height. Pure arithmetic; the viewer supplies the ground.
#pragma once

#include "look/render_params.hpp"

namespace sansui::viewer {

struct Walker {
  double x_m = 0.0, z_m = 0.0;  ///< metres east and south of the terrain's north-west corner
  double bearing_deg = 0.0;     ///< compass bearing looked toward
  double pitch_deg = 0.0;       ///< above the horizon; negative looks down
  double eye_height_m = 1.7;    ///< above the ground (drawn metres)
  double speed_m_s = 20.0;      ///< walking speed; Shift runs at ten times this
};

/// Moves `forward_m` along the bearing and `right_m` to its right, kept inside the extent.
void walk(Walker& walker, double forward_m, double right_m, double width_m, double depth_m);
/// Turns by `yaw_deg` (clockwise) and tilts by `pitch_deg`, the pitch kept within -85..85.
void look(Walker& walker, double yaw_deg, double pitch_deg);
/// The renderer's walkthrough camera for the walker; `extra_eye_m` lifts the eye above the
/// renderer's own ground (where the full-resolution terrain stands higher than the drawn mesh).
look::Camera walker_camera(const Walker& walker, double width_m, double depth_m, double fov_deg, double extra_eye_m);

}  // namespace sansui::viewer
