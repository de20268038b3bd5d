#include "look/camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <span>

#include <glm/gtc/matrix_transform.hpp>

#include "look/colour_space.hpp"

namespace sansui::look {
namespace {

// A fitted terrain fills the frame up to this far from the centre (normalised device
// coordinates), and leaves the top for the sky.
constexpr double fit_margin = 0.94;
constexpr double fit_top = 0.55;

std::array<glm::dvec3, 8> box_corners(const TerrainFrame& frame) {
  std::array<glm::dvec3, 8> corners;
  int i = 0;
  for (double x : {0.0, frame.width_m})
    for (double y : {frame.min_y, frame.max_y})
      for (double z : {0.0, frame.depth_m}) corners[i++] = {x, y, z};
  return corners;
}

CameraMatrices top_camera(const TerrainFrame& frame, double aspect) {
  // Fit the whole terrain, north up, keeping square pixels.
  double half_width = frame.width_m / 2.0, half_height = frame.depth_m / 2.0;
  if (half_width / half_height > aspect) {
    half_height = half_width / aspect;
  } else {
    half_width = half_height * aspect;
  }
  const double margin = 0.01 * (frame.max_y - frame.min_y) + 1.0;
  CameraMatrices camera;
  camera.orthographic = true;
  camera.position = glm::vec3(frame.width_m / 2.0, frame.max_y + margin, frame.depth_m / 2.0);
  camera.forward = glm::vec3(0.0f, -1.0f, 0.0f);
  // Looking down with "up" toward -z (north) on the picture.
  camera.view = glm::lookAt(camera.position, camera.position + camera.forward, glm::vec3(0.0f, 0.0f, -1.0f));
  const double far = frame.max_y - frame.min_y + 2.0 * margin;
  camera.projection = glm::mat4(glm::ortho(-half_width, half_width, -half_height, half_height, 0.0, far));
  return camera;
}

/// A level orthographic camera (an elevation drawing), from the south (front) or the east
/// (side), the whole box in the picture with square pixels.
CameraMatrices level_camera(const TerrainFrame& frame, double aspect, bool from_east) {
  const double across = from_east ? frame.depth_m : frame.width_m;  // the picture's horizontal extent
  const double along = from_east ? frame.width_m : frame.depth_m;   // the depth the camera looks through
  const double tall = std::max(frame.max_y - frame.min_y, 1e-3 * across);
  double half_width = 0.52 * across, half_height = 0.52 * tall;
  if (half_width / half_height > aspect) {
    half_height = half_width / aspect;
  } else {
    half_width = half_height * aspect;
  }
  const double margin = 0.01 * along + 1.0;
  const double middle_y = 0.5 * (frame.min_y + frame.max_y);
  CameraMatrices camera;
  camera.orthographic = true;
  camera.position = from_east ? glm::vec3(frame.width_m + margin, middle_y, frame.depth_m / 2.0)
                              : glm::vec3(frame.width_m / 2.0, middle_y, frame.depth_m + margin);
  camera.forward = from_east ? glm::vec3(-1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, -1.0f);
  camera.view = glm::lookAt(camera.position, camera.position + camera.forward, glm::vec3(0.0f, 1.0f, 0.0f));
  camera.projection = glm::mat4(glm::ortho(-half_width, half_width, -half_height, half_height, 0.0, along + 2.0 * margin));
  return camera;
}

/// The farthest depth along `forward` from `eye` of the surroundings' corners (at sea level).
double surroundings_depth(const TerrainFrame& frame, const glm::dvec3& eye, const glm::dvec3& forward) {
  double farthest = 0.0;
  if (frame.surroundings_reach_m <= 0.0) return farthest;
  for (double sx : {-1.0, 1.0})
    for (double sz : {-1.0, 1.0}) {
      const glm::dvec3 corner(0.5 * frame.width_m + sx * frame.surroundings_reach_m, 0.0,
                              0.5 * frame.depth_m + sz * frame.surroundings_reach_m);
      farthest = std::max(farthest, glm::dot(corner - eye, forward));
    }
  return farthest;
}

/// A walker's eye: at the target, eye_height_m above the drawn ground, looking toward the
/// bearing azimuth_deg.
CameraMatrices walk_camera(const Camera& params, const TerrainFrame& frame, double aspect) {
  const double azimuth = params.azimuth_deg * degrees, elevation = params.elevation_deg * degrees;
  const glm::dvec3 eye(params.target_x * frame.width_m, frame.eye_ground_y + *params.eye_height_m, params.target_y * frame.depth_m);
  const glm::dvec3 forward(std::cos(elevation) * std::sin(azimuth), std::sin(elevation), -std::cos(elevation) * std::cos(azimuth));
  double farthest = 1.0;
  for (const glm::dvec3& corner : box_corners(frame)) farthest = std::max(farthest, glm::length(corner - eye));
  farthest = std::max(farthest, surroundings_depth(frame, eye, forward));
  // The near plane sits at half the eye height, so the ground at the walker's feet is drawn and
  // the depth buffer keeps a metre's precision kilometres away.
  const double near = std::clamp(0.5 * *params.eye_height_m, 0.05, 0.5 * farthest);
  CameraMatrices camera;
  camera.position = glm::vec3(eye);
  camera.forward = glm::vec3(forward);
  camera.nearest_m = 0.0;
  camera.walking = true;
  const glm::dvec3 up = std::abs(forward.y) > 0.999 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 1.0, 0.0);
  camera.view = glm::mat4(glm::lookAt(eye, eye + forward, up));
  camera.projection = glm::mat4(glm::perspective(params.fov_deg * degrees, aspect, near, farthest * 1.01));
  return camera;
}

/// The perspective camera at `distance` metres from the target.
CameraMatrices orbit_camera(const Camera& params, const TerrainFrame& frame, double aspect, double distance) {
  const double azimuth = params.azimuth_deg * degrees, elevation = params.elevation_deg * degrees;
  const glm::dvec3 target(params.target_x * frame.width_m, frame.target_y, params.target_y * frame.depth_m);
  // Bearing: east = sin, north = cos, and z points south.
  const glm::dvec3 toward_camera(std::cos(elevation) * std::sin(azimuth), std::sin(elevation), -std::cos(elevation) * std::cos(azimuth));
  const glm::dvec3 eye = target + distance * toward_camera;
  const glm::dvec3 forward = -toward_camera;

  // Near and far planes hug the terrain's box, so the depth buffer's precision goes where the
  // terrain is.
  double nearest = std::numeric_limits<double>::max(), farthest = 0.0, nearest_corner = nearest;
  for (const glm::dvec3& corner : box_corners(frame)) {
    const double depth = glm::dot(corner - eye, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
    nearest_corner = std::min(nearest_corner, glm::length(corner - eye));
  }
  double far = std::max(farthest * 1.01, 1.0);
  double near = std::max(nearest * 0.9, far * 1e-4);
  if (frame.surroundings_reach_m > 0.0) {
    // The ground runs on under the camera: the near plane comes down to half the eye's height
    // above the terrain's highest point (never nearer than the depth buffer can keep apart).
    far = std::max(far, surroundings_depth(frame, eye, forward) * 1.01);
    near = std::max(std::min(nearest * 0.9, 0.5 * (eye.y - frame.max_y)), far * 2e-5);
  }

  CameraMatrices camera;
  camera.position = glm::vec3(eye);
  camera.forward = glm::vec3(forward);
  camera.nearest_m = std::max(nearest_corner, 0.0);
  camera.view = glm::mat4(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0)));
  camera.projection = glm::mat4(glm::perspective(params.fov_deg * degrees, aspect, near, far));
  return camera;
}

/// The fit points' extent in normalised device coordinates: (x_min, x_max, y_min, y_max), or
/// nullopt if a point is behind the camera.
std::optional<glm::dvec4> projected_extent(const CameraMatrices& camera, const TerrainFrame& frame) {
  const glm::dmat4 view_proj = glm::dmat4(camera.projection) * glm::dmat4(camera.view);
  const auto corners = box_corners(frame);
  const std::span<const glm::dvec3> points = frame.fit_points.empty() ? std::span<const glm::dvec3>(corners) : frame.fit_points;
  glm::dvec4 extent(1e30, -1e30, 1e30, -1e30);
  for (const glm::dvec3& point : points) {
    const glm::dvec4 clip = view_proj * glm::dvec4(point, 1.0);
    if (clip.w <= 1e-9) return std::nullopt;
    const double x = clip.x / clip.w, y = clip.y / clip.w;
    extent = {std::min(extent[0], x), std::max(extent[1], x), std::min(extent[2], y), std::max(extent[3], y)};
  }
  return extent;
}

/// How far a fitted view looking down at `elevation_deg` is centred in the picture: 0 up to 30
/// degrees (the terrain sits on the bottom margin and the sky above it has the top), 1 from 60
/// (looking down, no sky shows above the terrain: it is centred, with the same margin all round).
double centring(double elevation_deg) {
  return std::clamp((elevation_deg - 30.0) / 30.0, 0.0, 1.0);
}

/// Whether the terrain fits across the picture and in its band (between the bottom margin and
/// the sky, or the margins all round when centred), once shifted.
bool fits(const std::optional<glm::dvec4>& extent, double centred) {
  const double room = fit_top + fit_margin + centred * (fit_margin - fit_top);
  return extent && (*extent)[1] - (*extent)[0] <= 2.0 * fit_margin && (*extent)[3] - (*extent)[2] <= room;
}

CameraMatrices perspective_camera(const Camera& params, const TerrainFrame& frame, double aspect) {
  if (params.distance > 0.0) return orbit_camera(params, frame, aspect, params.distance * frame.size_m());
  // Fit: the nearest distance (to a per mille of the terrain size) at which the terrain fits,
  // then a lens shift (an off-axis projection, so verticals stay vertical) that centres it
  // across the picture and sets its lowest point on the bottom margin.
  const double centred = centring(params.elevation_deg);
  double low = 0.05 * frame.size_m(), high = 50.0 * frame.size_m();
  for (int step = 0; step < 40 && high - low > 1e-3 * frame.size_m(); ++step) {
    const double middle = 0.5 * (low + high);
    (fits(projected_extent(orbit_camera(params, frame, aspect, middle), frame), centred) ? high : low) = middle;
  }
  CameraMatrices camera = orbit_camera(params, frame, aspect, high);
  if (const auto extent = projected_extent(camera, frame)) {
    const double on_bottom = -fit_margin - (*extent)[2], in_middle = -0.5 * ((*extent)[2] + (*extent)[3]);
    const glm::dvec3 shift(-0.5 * ((*extent)[0] + (*extent)[1]), on_bottom + centred * (in_middle - on_bottom), 0.0);
    camera.projection = glm::mat4(glm::translate(glm::dmat4(1.0), shift)) * camera.projection;
  }
  return camera;
}

}  // namespace

CameraMatrices camera_matrices(const RenderParams& params, const TerrainFrame& frame, int width, int height) {
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  switch (params.view) {
    case View::top:
      return top_camera(frame, aspect);
    case View::front:
      return level_camera(frame, aspect, false);
    case View::side:
      return level_camera(frame, aspect, true);
    case View::perspective:
    case View::block:
      break;
  }
  if (params.camera.eye_height_m) return walk_camera(params.camera, frame, aspect);
  return perspective_camera(params.camera, frame, aspect);
}

}  // namespace sansui::look
