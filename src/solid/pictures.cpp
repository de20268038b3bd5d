// Slice, sphere and cube pictures (see pictures.hpp).
//
// Rows are independent tasks; each thread clones the evaluator once and walks its rows left to
// right, so Types III/IV see coherent queries. A pixel's colour depends only on its position,
// so the picture is the same for any thread count and evaluator type.
#include "solid/pictures.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::solid {
namespace {

using glm::dvec3;

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}
Rgba8 to_rgba(const Rgb& c) {
  return {to_byte(c.r), to_byte(c.g), to_byte(c.b), 255};
}

void check_size(int size_px) {
  if (size_px < 8 || size_px > max_picture_px) fail("picture size {} px is not allowed: it must be 8..{}", size_px, max_picture_px);
}

/// Fills every pixel with shade(evaluator, x, y), rows in parallel, one evaluator per thread.
Image render_rows(const FieldEvaluator& field, int size_px, const Context& context, std::string_view stage,
                  const std::function<Rgba8(FieldEvaluator&, int, int)>& shade) {
  Image image = Image::uninitialized(size_px, size_px);
  ThreadLocal<std::unique_ptr<FieldEvaluator>> evaluators([&] { return field.clone(); });
  std::atomic<int> rows_done{0};
  parallel_for(0, size_px, [&](int y) {
    context.check_cancelled();
    FieldEvaluator& evaluator = *evaluators.local();
    for (int x = 0; x < size_px; ++x) image(x, y) = shade(evaluator, x, y);
    context.report(stage, static_cast<double>(++rows_done) / size_px);
  });
  return image;
}

/// The field at block point p (block units, clamped to the block).
float field_at(FieldEvaluator& evaluator, const dvec3& p) {
  const double last = evaluator.last();
  return evaluator.sample_inside(p.x * last, p.y * last, p.z * last);
}

/// An orthographic camera looking along `forward`, with the picture spanning `half_extent`
/// block units either side of `centre`.
struct Camera {
  dvec3 centre, forward, right, up;
  double half_extent;
  Camera(const dvec3& look_at, const dvec3& from_direction, double half) : centre(look_at), half_extent(half) {
    forward = glm::normalize(-from_direction);
    right = glm::normalize(glm::cross(forward, dvec3(0, 0, 1)));
    up = glm::cross(right, forward);
  }
  /// The point of the picture plane through `centre` at pixel position (px, py), fractional.
  dvec3 plane_point(double px, double py, int size_px) const {
    const double u = (2.0 * px / size_px - 1.0) * half_extent;
    const double v = (1.0 - 2.0 * py / size_px) * half_extent;
    return centre + u * right + v * up;
  }
};

/// Light from the upper left and front; ambient fill; Blinn-Phong highlight for gloss.
const dvec3 light_direction = glm::normalize(dvec3(-0.55, -0.75, 0.85));

Rgb shade(const Rgb& albedo, const dvec3& normal, const dvec3& to_viewer, double gloss) {
  const double diffuse = std::max(0.0, glm::dot(normal, light_direction));
  const dvec3 half_vector = glm::normalize(light_direction + to_viewer);
  double highlight = std::max(0.0, glm::dot(normal, half_vector));
  for (int i = 0; i < 6; ++i) highlight *= highlight;  // ^64
  const double light = 0.28 + 0.8 * diffuse;
  const double spec = gloss * highlight;
  // Lighting in linear light with gamma 2 (square and square root: exact everywhere).
  auto channel = [&](float c) { return static_cast<float>(std::sqrt(c * c * light + spec)); };
  return {channel(albedo.r), channel(albedo.g), channel(albedo.b)};
}

/// Background: a soft vertical gradient of dark grey.
Rgb background(int y, int size_px) {
  const auto t = static_cast<float>(y) / static_cast<float>(size_px);
  const float grey = 0.20f - 0.08f * t;
  return {grey, grey, grey * 1.05f};
}

Rgb blend(const Rgb& a, const Rgb& b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

/// Fraction of a pixel covered by a shape, from 4x4 sub-samples.
float coverage(double px, double py, const std::function<bool(double, double)>& inside) {
  int hits = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) hits += inside(px + (i + 0.5) / 4.0, py + (j + 0.5) / 4.0) ? 1 : 0;
  return static_cast<float>(hits) / 16.0f;
}

/// Where the ray through picture point `start` along `forward` first meets the unit block, with
/// the face's outward normal; nullopt if it misses.
std::optional<std::pair<dvec3, dvec3>> hit_block(const dvec3& start, const dvec3& forward) {
  double t_near = -1e30, t_far = 1e30;
  int near_axis = 0;
  double near_sign = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(forward[a]) < 1e-12) {
      if (start[a] < 0.0 || start[a] > 1.0) return std::nullopt;
      continue;
    }
    double t0 = (0.0 - start[a]) / forward[a], t1 = (1.0 - start[a]) / forward[a];
    double sign = -1.0;  // entering through the face at 0
    if (t0 > t1) {
      std::swap(t0, t1);
      sign = 1.0;
    }
    if (t0 > t_near) {
      t_near = t0;
      near_axis = a;
      near_sign = sign;
    }
    t_far = std::min(t_far, t1);
  }
  if (t_near > t_far) return std::nullopt;
  dvec3 normal(0.0);
  normal[near_axis] = near_sign;
  return std::make_pair(start + t_near * forward, normal);
}

}  // namespace

Image render_slice(const FieldEvaluator& field, const SolidTexture& texture, int axis, double position, int size_px,
                   const Context& context) {
  check_size(size_px);
  if (axis < 0 || axis > 2) fail("slice axis {} is not allowed: it must be x, y or z", axis);
  if (!(position >= 0.0 && position <= field.last()))
    fail("slice position {} is outside the block: it must be in [0, {}]", position, field.last());
  const TextureSampler sampler(texture);
  const int right_axis = axis == 0 ? 1 : 0;
  const int up_axis = axis == 2 ? 1 : 2;
  const double last = field.last();
  const double step = last / (size_px - 1);
  return render_rows(field, size_px, context, "slice", [&](FieldEvaluator& evaluator, int x, int y) {
    double lattice[3];
    lattice[axis] = position;
    lattice[right_axis] = std::min(x * step, last);
    lattice[up_axis] = std::min((size_px - 1 - y) * step, last);
    const float d = evaluator.sample_inside(lattice[0], lattice[1], lattice[2]);
    return to_rgba(sampler.color(lattice[0] / last, lattice[1] / last, lattice[2] / last, d));
  });
}

Image render_sphere(const FieldEvaluator& field, const SolidTexture& texture, int size_px, const Context& context) {
  check_size(size_px);
  const TextureSampler sampler(texture);
  const double gloss = texture_gloss(texture);
  const dvec3 centre(0.5);
  const double radius = 0.5;
  const Camera camera(centre, dvec3(0.35, -1.0, 0.5), 0.56);
  const double pixel = 2.0 * camera.half_extent / size_px;
  auto offset2 = [&](double px, double py) {
    const dvec3 q = camera.plane_point(px, py, size_px) - centre;
    return glm::dot(q, q);
  };
  return render_rows(field, size_px, context, "sphere", [&](FieldEvaluator& evaluator, int x, int y) {
    const Rgb ground = background(y, size_px);
    const double cx = x + 0.5, cy = y + 0.5;
    // Pixels well outside the disc skip the sub-samples.
    if (offset2(cx, cy) > (radius + 2.0 * pixel) * (radius + 2.0 * pixel)) return to_rgba(ground);
    const float covered = coverage(x, y, [&](double px, double py) { return offset2(px, py) <= radius * radius; });
    if (covered == 0.0f) return to_rgba(ground);
    // The visible point under the pixel centre (pulled onto the rim for edge pixels).
    dvec3 q = camera.plane_point(cx, cy, size_px) - centre;
    const double r2 = glm::dot(q, q);
    if (r2 > radius * radius) q *= radius / std::sqrt(r2) * (1.0 - 1e-9);
    const double depth = std::sqrt(std::max(0.0, radius * radius - glm::dot(q, q)));
    const dvec3 point = centre + q - camera.forward * depth;
    const dvec3 normal = (point - centre) / radius;
    const Rgb albedo = sampler.color(point.x, point.y, point.z, field_at(evaluator, point));
    const Rgb lit = shade(albedo, normal, -camera.forward, gloss);
    return to_rgba(blend(ground, lit, covered));
  });
}

Image render_cube(const FieldEvaluator& field, const SolidTexture& texture, int size_px, const Context& context) {
  check_size(size_px);
  const TextureSampler sampler(texture);
  const double gloss = texture_gloss(texture);
  const Camera camera(dvec3(0.5), dvec3(1.0, -1.35, 1.05), 0.92);
  auto start_of = [&](double px, double py) { return camera.plane_point(px, py, size_px) - 3.0 * camera.forward; };
  return render_rows(field, size_px, context, "cube", [&](FieldEvaluator& evaluator, int x, int y) {
    const Rgb ground = background(y, size_px);
    const float covered = coverage(x, y, [&](double px, double py) { return hit_block(start_of(px, py), camera.forward).has_value(); });
    if (covered == 0.0f) return to_rgba(ground);
    // The face under the pixel centre, or under the nearest covered sub-sample at an edge.
    auto hit = hit_block(start_of(x + 0.5, y + 0.5), camera.forward);
    for (int j = 0; j < 4 && !hit; ++j)
      for (int i = 0; i < 4 && !hit; ++i) hit = hit_block(start_of(x + (i + 0.5) / 4.0, y + (j + 0.5) / 4.0), camera.forward);
    const dvec3 point = glm::clamp(hit->first, dvec3(0.0), dvec3(1.0));
    const Rgb albedo = sampler.color(point.x, point.y, point.z, field_at(evaluator, point));
    const Rgb lit = shade(albedo, hit->second, -camera.forward, gloss);
    return to_rgba(blend(ground, lit, covered));
  });
}

}  // namespace sansui::solid
