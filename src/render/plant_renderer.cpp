#include "render/plant_renderer.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"
#include "look/plant_models.hpp"
#include "render/impostor_atlas.hpp"
#include "render/plant_shaders.hpp"
#include "render/shaders.hpp"

namespace sansui::render {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr GLsizei instance_stride = sizeof(look::PlantInstance);
// Impostors in texture units above the terrain's (0-5, terrain_renderer.cpp).
constexpr int albedo_unit = 6, normal_unit = 7;

/// GL takes a byte offset into a bound buffer as a pointer.
const void* byte_offset(std::uintptr_t bytes) {
  return reinterpret_cast<const void*>(bytes);  // NOLINT(performance-no-int-to-ptr)
}

/// Attributes 0-2 of look::PlantVertex from the bound array buffer.
void set_vertex_attributes() {
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(look::PlantVertex), byte_offset(offsetof(look::PlantVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_BYTE, GL_TRUE, sizeof(look::PlantVertex), byte_offset(offsetof(look::PlantVertex, normal_x)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_SHORT, GL_TRUE, sizeof(look::PlantVertex), byte_offset(offsetof(look::PlantVertex, red)));
}

/// The true height of the drawn terrain mesh at a point, for both of its triangulations
/// (look/terrain_mesh.cpp: strips of rows cut each cell from (x, y + 1) to (x + 1, y), strips
/// of columns from (x, y) to (x + 1, y + 1)), and its steepness.
struct Ground {
  float rows_m, columns_m, slope, gradient_x, gradient_z;
};
Ground ground_at(const Heightfield& mesh, double x_m, double z_m, double width_m, double depth_m) {
  const int columns = mesh.width(), rows = mesh.height();
  const double gx = x_m / width_m * (columns - 1), gy = z_m / depth_m * (rows - 1);
  const int ix = std::clamp(static_cast<int>(gx), 0, columns - 2), iy = std::clamp(static_cast<int>(gy), 0, rows - 2);
  const double fx = std::clamp(gx - ix, 0.0, 1.0), fy = std::clamp(gy - iy, 0.0, 1.0);
  const double h00 = mesh(ix, iy), h10 = mesh(ix + 1, iy), h01 = mesh(ix, iy + 1), h11 = mesh(ix + 1, iy + 1);
  const double by_rows =
      fx + fy <= 1.0 ? h00 + fx * (h10 - h00) + fy * (h01 - h00) : h11 + (1.0 - fx) * (h01 - h11) + (1.0 - fy) * (h10 - h11);
  const double by_columns = fx >= fy ? h00 + fx * (h10 - h00) + fy * (h11 - h10) : h00 + fy * (h01 - h00) + fx * (h11 - h01);
  const double cell_x = width_m / (columns - 1), cell_z = depth_m / (rows - 1);
  const double gradient_x = 0.5 * (h10 - h00 + h11 - h01) / cell_x, gradient_z = 0.5 * (h01 - h00 + h11 - h10) / cell_z;
  const double slope = std::abs(gradient_x) + std::abs(gradient_z);
  return {static_cast<float>(by_rows), static_cast<float>(by_columns), static_cast<float>(slope), static_cast<float>(gradient_x),
          static_cast<float>(gradient_z)};
}

}  // namespace

PlantRenderer::PlantRenderer() {
  mesh_program_ = make_program(link_program("plant mesh", {shaders::common, shaders::plant_common, shaders::plant_mesh_vertex},
                                            {shaders::common, shaders::plant_common, shaders::plant_mesh_fragment}));
  impostor_program_ = make_program(
      link_program("plant impostor", {shaders::common, shaders::plant_common, shaders::plant_impostor_vertex},
                   {shaders::common, shaders::plant_common, shaders::plant_impostor_shading, shaders::plant_impostor_fragment}));
  sprite_program_ =
      make_program(link_program("plant sprite", {shaders::common, shaders::plant_common, shaders::plant_sprite_vertex},
                                {shaders::common, shaders::plant_common, shaders::plant_impostor_shading, shaders::plant_sprite_fragment}));
  shadow_program_ = make_program(
      link_program("plant shadow", {shaders::common, shaders::plant_shadow_vertex}, {shaders::common, shaders::plant_shadow_fragment}));
  capture_program_ = make_program(
      link_program("plant capture", {shaders::common, shaders::plant_capture_vertex}, {shaders::common, shaders::plant_capture_fragment}));
  mesh_array_ = make_vertex_array();
  capture_array_ = make_vertex_array();
  impostor_array_ = make_vertex_array();
  sprite_array_ = make_vertex_array();
  shadow_array_ = make_vertex_array();
  shadow_vertices_ = make_buffer();
  vertices_ = make_buffer();
  indices_ = make_buffer();
  corners_ = make_buffer();
  instances_ = make_buffer();
  impostor_albedo_ = make_texture();
  impostor_normal_ = make_texture();

  // The impostor card: a strip over the unit square.
  const float corners[] = {0, 0, 1, 0, 0, 1, 1, 1};
  glBindVertexArray(impostor_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, corners_.id());
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
  glEnableVertexAttribArray(7);
  glVertexAttribPointer(7, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  // The shadows: look::ShadowVertex, position, the corner in crown radii, and the shape.
  glBindVertexArray(shadow_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, shadow_vertices_.id());
  constexpr GLsizei shadow_stride = sizeof(look::ShadowVertex);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, shadow_stride, byte_offset(offsetof(look::ShadowVertex, x)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, shadow_stride, byte_offset(offsetof(look::ShadowVertex, along)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, shadow_stride, byte_offset(offsetof(look::ShadowVertex, reach)));
  glBindVertexArray(0);
  check_gl("creating the plant renderer");
}

PlantRenderer::~PlantRenderer() = default;

void PlantRenderer::upload_kinds(const look::PlantKinds& plant_kinds) {
  const std::vector<std::uint32_t>& keys = plant_kinds.keys;
  const std::vector<look::PlantModel>& models = plant_kinds.models;
  const std::uint32_t variants = plant_kinds.variants;
  const auto upload_start = Clock::now();
  std::vector<look::PlantVertex> vertices;
  std::vector<std::uint32_t> indices;
  kinds_.assign(keys.size(), {});
  kind_info_.assign(keys.size(), {});
  std::vector<ImpostorSource> sources(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    Kind& kind = kinds_[k];
    kind.species = static_cast<std::uint16_t>(keys[k] / variants);
    kind.variant = static_cast<std::uint16_t>(keys[k] % variants);
    for (int detail = 0; detail < 2; ++detail) {
      const look::PlantModel& model = models[2 * k + detail];
      const auto base = static_cast<std::uint32_t>(vertices.size());
      const auto first = static_cast<std::int64_t>(indices.size());
      vertices.insert(vertices.end(), model.vertices.begin(), model.vertices.end());
      for (std::uint32_t index : model.indices) indices.push_back(base + index);
      const auto count = static_cast<std::int64_t>(model.indices.size());
      (detail == 0 ? kind.full_first : kind.simplified_first) = first;
      (detail == 0 ? kind.full_count : kind.simplified_count) = count;
      (detail == 0 ? kind_info_[k].full_triangles : kind_info_[k].simplified_triangles) = count / 3;
    }
    // The full mesh's bounds serve all three levels, so that the impostor covers what it replaces.
    kind_info_[k].bounds = models[2 * k].bounds;
    sources[k] = {kind.full_first, kind.full_count, kind_info_[k].bounds};
  }
  // (The element buffer binding belongs to a vertex array: one is bound to upload it.)
  glBindVertexArray(capture_array_.id());
  glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(look::PlantVertex)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(), GL_STATIC_DRAW);
  // The meshes' vertex array also takes the instance attributes (bind_instances); the capture's
  // has the vertices only.
  for (GLuint array : {mesh_array_.id(), capture_array_.id()}) {
    glBindVertexArray(array);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    set_vertex_attributes();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  }
  glBindVertexArray(0);
  check_gl("uploading the plant meshes");
  stats_.upload_s = seconds_since(upload_start);

  const auto atlas_start = Clock::now();
  build_impostor_atlas(capture_program_.id(), capture_array_.id(), sources, impostor_albedo_.id(), impostor_normal_.id());
  stats_.atlas_s = seconds_since(atlas_start);
}

void PlantRenderer::set_plants(const look::PlantsToDraw& plants, const Heightfield& mesh_heights, double width_m, double depth_m,
                               const Context& context) {
  context.report("render: plants", 0.0);
  stats_ = {};
  if (plants.kinds && plants.kinds != kinds_upload_ && !plants.kinds->keys.empty()) {
    upload_kinds(*plants.kinds);
    kinds_upload_ = plants.kinds;
  }
  context.check_cancelled();
  context.report("render: plants", 0.8);
  const std::vector<std::uint32_t> no_keys;
  const std::vector<std::uint32_t>& keys = kinds_upload_ ? kinds_upload_->keys : no_keys;
  const std::uint32_t variants = kinds_upload_ ? kinds_upload_->variants : 1;

  const auto start = Clock::now();
  std::vector<int> kind_of(keys.empty() ? 0 : keys.back() + 1, -1);
  for (std::size_t k = 0; k < keys.size(); ++k) kind_of[keys[k]] = static_cast<int>(k);
  spots_.clear();
  const std::vector<PlacedPlant> none;
  for (const auto* layer : {plants.trees != nullptr ? plants.trees : &none, plants.ground != nullptr ? plants.ground : &none}) {
    const bool ground_layer = layer == plants.ground;
    const std::uint64_t stream = rng::stream_key(0x504C414E54ull, ground_layer ? 1 : 0);
    // Filled in parallel, then the plants off the drawn terrain squeezed out, in order.
    const std::size_t first = spots_.size();
    spots_.resize(first + layer->size());
    std::vector<char> kept(layer->size(), 0);
    parallel_for_ranges<std::size_t>(0, layer->size(), 4096, [&](std::size_t range_begin, std::size_t range_end) {
      for (std::size_t i = range_begin; i != range_end; ++i) {
        const PlacedPlant& plant = (*layer)[i];
        const double x = plant.x_m - mesh_heights.origin_x_m, z = plant.y_m - mesh_heights.origin_y_m;
        if (!(x >= 0.0 && x <= width_m && z >= 0.0 && z <= depth_m)) continue;
        const std::size_t key = static_cast<std::size_t>(plant.species) * variants + plant.variant;
        if (key >= kind_of.size() || kind_of[key] < 0) continue;  // a kind without models (none were given)
        const Ground ground = ground_at(mesh_heights, x, z, width_m, depth_m);
        // Random bits from the plant's world position: the same plant thins alike in a tile
        // and in the whole world.
        const std::uint64_t where = rng::pack(std::bit_cast<std::int32_t>(plant.x_m), std::bit_cast<std::int32_t>(plant.y_m));
        spots_[first + i] = {static_cast<float>(x),
                             static_cast<float>(z),
                             ground.rows_m,
                             ground.columns_m,
                             ground.slope,
                             plant.scale,
                             std::cos(plant.rotation_rad),
                             std::sin(plant.rotation_rad),
                             static_cast<std::uint16_t>(kind_of[key]),
                             ground_layer,
                             static_cast<std::uint32_t>(rng::bits(stream, where)),
                             ground.gradient_x,
                             ground.gradient_z};
        kept[i] = 1;
      }
    });
    std::size_t end = first;
    for (std::size_t i = 0; i < layer->size(); ++i)
      if (kept[i] != 0) spots_[end++] = spots_[first + i];
    spots_.resize(end);
  }
  tree_grid_ = look::tree_grid(spots_, static_cast<float>(width_m), static_cast<float>(depth_m));
  stats_.kinds = static_cast<int>(kinds_.size());
  stats_.plants = count();
  stats_.upload_s += seconds_since(start);
  context.report("render: plants", 1.0);
}

void PlantRenderer::clear() {
  spots_.clear();
  tree_grid_ = {};
  stats_ = {};
}

double PlantRenderer::highest_y(double sea_level_m, double exaggeration) const {
  double highest = -1e300;
  for (const look::PlantSpot& spot : spots_) {
    const double ground = std::max(spot.ground_rows_m, spot.ground_columns_m);
    highest = std::max(highest, (ground - sea_level_m) * exaggeration + kind_info_[spot.kind].bounds.top * spot.scale);
  }
  return highest;
}

void PlantRenderer::add_fit_points(std::vector<glm::dvec3>& points, double sea_level_m, double exaggeration) const {
  for (const look::PlantSpot& spot : spots_) {
    const look::PlantBounds& bounds = kind_info_[spot.kind].bounds;
    const double ground = (std::max(spot.ground_rows_m, spot.ground_columns_m) - sea_level_m) * exaggeration;
    const double middle = ground + 0.5 * (bounds.bottom + bounds.top) * spot.scale, radius = bounds.radius * spot.scale;
    points.emplace_back(spot.x_m, ground + bounds.top * spot.scale, spot.z_m);
    for (const auto& [dx, dz] : {std::pair{-1.0, 0.0}, std::pair{1.0, 0.0}, std::pair{0.0, -1.0}, std::pair{0.0, 1.0}})
      points.emplace_back(spot.x_m + dx * radius, middle, spot.z_m + dz * radius);
  }
}

void PlantRenderer::bind_instances(GLuint vertex_array, std::int64_t first, GLuint divisor) const {
  glBindVertexArray(vertex_array);
  glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
  const auto base = static_cast<std::uintptr_t>(first) * sizeof(look::PlantInstance);
  for (GLuint attribute = 3; attribute <= 6; ++attribute) {
    glEnableVertexAttribArray(attribute);
    glVertexAttribPointer(attribute, 4, GL_FLOAT, GL_FALSE, instance_stride, byte_offset(base + (attribute - 3) * 4 * sizeof(float)));
    glVertexAttribDivisor(attribute, divisor);
  }
}

namespace {

float luminance(const glm::vec3& c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

}  // namespace

void PlantRenderer::draw_shadows(const std::vector<look::ShadowVertex>& shadows, const glm::mat4& view_proj) {
  if (shadows.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, shadow_vertices_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(shadows.size() * sizeof(look::ShadowVertex)), shadows.data(), GL_STREAM_DRAW);
  // Multiplies the terrain's colour: no depth written, pulled a little toward the eye so that
  // the ground's own triangles do not hide it.
  glEnable(GL_BLEND);
  glBlendFunc(GL_ZERO, GL_SRC_COLOR);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -8.0f);
  const Uniforms u(shadow_program_.id());
  u.set("u_view_proj", view_proj);
  glBindVertexArray(shadow_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(shadows.size()));
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
}

namespace {

/// The uniforms of the light and the camera that every plant program reads.
void set_plant_light(const Uniforms& u, const glm::mat4& view_proj, const PlantLight& light) {
  u.set("u_view_proj", view_proj);
  u.set("u_sun_dir", light.sun_dir);
  u.set("u_sun_light", light.sun_light);
  u.set("u_sky_light", light.sky_light);
}

}  // namespace

void PlantRenderer::count_drawn(const look::PlantDrawList& list) {
  stats_.full = static_cast<std::int64_t>(list.full.size());
  stats_.simplified = static_cast<std::int64_t>(list.simplified.size());
  stats_.impostors = static_cast<std::int64_t>(list.impostors.size());
  stats_.sprites = static_cast<std::int64_t>(list.sprites.size());
  stats_.culled = list.culled;
  stats_.thinned = list.thinned;
  stats_.triangles = list.full_triangles + list.simplified_triangles + 2 * stats_.impostors;
}

void PlantRenderer::upload_instances(const look::PlantDrawList& list, std::size_t total) {
  glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(total * sizeof(look::PlantInstance)), nullptr, GL_STREAM_DRAW);
  std::size_t offset = 0;
  for (const auto* part : {&list.full, &list.simplified, &list.impostors, &list.sprites}) {
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(offset * sizeof(look::PlantInstance)),
                    static_cast<GLsizeiptr>(part->size() * sizeof(look::PlantInstance)), part->data());
    offset += part->size();
  }
}

void PlantRenderer::draw_meshes(const look::PlantDrawList& list, const glm::mat4& view_proj, const PlantLight& light) {
  const Uniforms u(mesh_program_.id());
  set_plant_light(u, view_proj, light);
  for (int level = 0; level < 2; ++level) {
    const std::vector<int>& first = level == 0 ? list.full_first : list.simplified_first;
    const std::int64_t base = level == 0 ? 0 : static_cast<std::int64_t>(list.full.size());
    for (std::size_t k = 0; k < kinds_.size(); ++k) {
      const int count = first[k + 1] - first[k];
      if (count == 0) continue;
      bind_instances(mesh_array_.id(), base + first[k], 1);
      const Kind& kind = kinds_[k];
      const std::int64_t index_first = level == 0 ? kind.full_first : kind.simplified_first;
      const std::int64_t index_count = level == 0 ? kind.full_count : kind.simplified_count;
      glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(index_count), GL_UNSIGNED_INT,
                              byte_offset(static_cast<std::uintptr_t>(index_first) * sizeof(std::uint32_t)), count);
    }
  }
}

void PlantRenderer::draw_cards(const look::PlantDrawList& list, const look::PlantView& view, const PlantLight& light) {
  const auto first_card = static_cast<std::int64_t>(list.full.size() + list.simplified.size());
  const auto first_sprite = first_card + static_cast<std::int64_t>(list.impostors.size());
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  // The cards' axes: across the view, and up leaning back by half the camera's pitch. The
  // same for every card (plants in one picture are seen from nearly the same elevation), so
  // vertices need no trigonometry.
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const glm::vec3 across = glm::cross(view.camera_forward, up);
  const glm::vec3 right = glm::length(across) > 1e-4f ? glm::normalize(across) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 card_up = glm::normalize(up + glm::normalize(glm::cross(right, view.camera_forward)));
  auto set_impostor = [&](const Uniforms& u) {
    set_plant_light(u, view.view_proj, light);
    u.set("u_card_right", right);
    u.set("u_card_up", card_up);
    u.set("u_side_views", ImpostorLayout::side_views);
    u.set("u_impostor_albedo", albedo_unit);
    u.set("u_impostor_normal", normal_unit);
    u.set("u_alpha_to_coverage", samples > 1 ? 1 : 0);
  };
  if (samples > 1) glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  glActiveTexture(GL_TEXTURE0 + albedo_unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, impostor_albedo_.id());
  glActiveTexture(GL_TEXTURE0 + normal_unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, impostor_normal_.id());
  glActiveTexture(GL_TEXTURE0);
  if (!list.impostors.empty()) {
    const Uniforms u(impostor_program_.id());
    set_impostor(u);
    bind_instances(impostor_array_.id(), first_card, 1);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(list.impostors.size()));
  }
  if (!list.sprites.empty()) {
    const Uniforms u(sprite_program_.id());
    set_impostor(u);
    u.set("u_pixels_per_unit", view.pixels_per_unit);
    u.set("u_cell_texels", glm::vec2(ImpostorLayout::cell_width, ImpostorLayout::cell_height));
    u.set("u_orthographic", view.orthographic ? 1 : 0);
    glEnable(GL_PROGRAM_POINT_SIZE);
    bind_instances(sprite_array_.id(), first_sprite, 0);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(list.sprites.size()));
    glDisable(GL_PROGRAM_POINT_SIZE);
  }
  glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
}

void PlantRenderer::draw(const look::PlantView& plant_view, const PlantLight& light) {
  // Tree shadows darken the ground by the sun's share of its light (a flat ground's).
  look::PlantView view = plant_view;
  const float sun_on_ground = luminance(light.sun_light) * std::max(light.sun_dir.y, 0.0f);
  view.sun_dir = light.sun_dir;
  view.shadow_strength = 0.75f * sun_on_ground / std::max(sun_on_ground + luminance(light.sky_light), 1e-6f);
  stats_.full = stats_.simplified = stats_.impostors = stats_.sprites = stats_.culled = stats_.thinned = stats_.triangles = 0;
  stats_.select_s = stats_.draw_s = 0.0;
  if (spots_.empty()) return;
  // Timed: the terrain finishes first, so that its rasterising does not count as the plants'.
  if (timing_) glFinish();
  const auto start = Clock::now();
  const look::PlantDrawList list = look::select_plants(spots_, kind_info_, view, limits_, &tree_grid_);
  stats_.select_s = seconds_since(start);
  count_drawn(list);
  if (timing_) glFinish();
  const auto draw_start = Clock::now();

  // All instances in one buffer: full meshes, simplified meshes, impostor cards, sprites.
  const std::size_t total = list.full.size() + list.simplified.size() + list.impostors.size() + list.sprites.size();
  if (total == 0) return;
  stats_.shadows = static_cast<std::int64_t>(list.shadows.size() / 6);
  upload_instances(list, total);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  // Shadows first: they darken the ground only, and the plants drawn next cover them.
  draw_shadows(list.shadows, view.view_proj);
  draw_meshes(list, view.view_proj, light);
  if (!list.impostors.empty() || !list.sprites.empty()) draw_cards(list, view, light);
  glBindVertexArray(0);
  glUseProgram(0);
  check_gl("drawing the plants");
  if (timing_) {
    glFinish();
    stats_.draw_s = seconds_since(draw_start);
  }
}

}  // namespace sansui::render
