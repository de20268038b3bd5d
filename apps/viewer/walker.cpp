#include "viewer/walker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sansui::viewer {
namespace {

constexpr double degrees = std::numbers::pi / 180.0;
constexpr double max_pitch_deg = 85.0;

}  // namespace

void walk(Walker& walker, double forward_m, double right_m, double width_m, double depth_m) {
  const double bearing = walker.bearing_deg * degrees;
  // Bearing: east = sin, north = cos; z points south.
  walker.x_m += forward_m * std::sin(bearing) + right_m * std::cos(bearing);
  walker.z_m += -forward_m * std::cos(bearing) + right_m * std::sin(bearing);
  walker.x_m = std::clamp(walker.x_m, 0.0, width_m);
  walker.z_m = std::clamp(walker.z_m, 0.0, depth_m);
}

void look(Walker& walker, double yaw_deg, double pitch_deg) {
  walker.bearing_deg = std::fmod(walker.bearing_deg + yaw_deg + 360.0, 360.0);
  walker.pitch_deg = std::clamp(walker.pitch_deg + pitch_deg, -max_pitch_deg, max_pitch_deg);
}

look::Camera walker_camera(const Walker& walker, double width_m, double depth_m, double fov_deg, double extra_eye_m) {
  look::Camera camera;
  camera.azimuth_deg = walker.bearing_deg;
  camera.elevation_deg = walker.pitch_deg;
  camera.target_x = width_m > 0.0 ? std::clamp(walker.x_m / width_m, 0.0, 1.0) : 0.5;
  camera.target_y = depth_m > 0.0 ? std::clamp(walker.z_m / depth_m, 0.0, 1.0) : 0.5;
  camera.eye_height_m = walker.eye_height_m + std::max(extra_eye_m, 0.0);
  camera.fov_deg = fov_deg;
  return camera;
}

}  // namespace sansui::viewer
