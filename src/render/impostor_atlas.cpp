#include "render/impostor_atlas.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "core/parallel.hpp"

namespace sansui::render {
namespace {

using Layout = ImpostorLayout;

/// One texel while levels are averaged: everything weighted by coverage.
struct Texel {
  glm::vec3 colour{0.0f};  ///< linear albedo times coverage
  glm::vec3 normal{0.0f};  ///< times coverage
  float leaf = 0.0f;       ///< times coverage
  float coverage = 0.0f;
};

const std::array<float, 256>& srgb_to_linear_table() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const float c = static_cast<float>(i) / 255.0f;
      t[i] = c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    }
    return t;
  }();
  return table;
}

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}
std::uint8_t linear_to_srgb8(float c) {
  c = std::clamp(c, 0.0f, 1.0f);
  return to_byte(c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f);
}

/// The mean of 2x2 blocks.
std::vector<Texel> halve(const std::vector<Texel>& texels, int width, int height) {
  const int half_width = width / 2, half_height = height / 2;
  std::vector<Texel> out(static_cast<std::size_t>(half_width) * half_height);
  for (int y = 0; y < half_height; ++y)
    for (int x = 0; x < half_width; ++x) {
      Texel sum;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const Texel& t = texels[static_cast<std::size_t>(2 * y + dy) * width + 2 * x + dx];
          sum.colour += t.colour, sum.normal += t.normal, sum.leaf += t.leaf, sum.coverage += t.coverage;
        }
      out[static_cast<std::size_t>(y) * half_width + x] = {sum.colour * 0.25f, sum.normal * 0.25f, sum.leaf * 0.25f, sum.coverage * 0.25f};
    }
  return out;
}

/// Encodes one level; uncovered texels take the mean of their cell.
void encode(const std::vector<Texel>& texels, int level, std::vector<Rgba8>& albedo, std::vector<Rgba8>& normal) {
  const int width = Layout::layer_width >> level, height = Layout::layer_height >> level;
  const int cell = Layout::cell_width >> level;
  albedo.resize(texels.size());
  normal.resize(texels.size());
  // Cells: the side views, then the view from above (two cells wide).
  for (int first = 0; first < width;) {
    const int last = first + (first == Layout::side_views * cell ? 2 * cell : cell);
    Texel mean;
    for (int y = 0; y < height; ++y)
      for (int x = first; x < last; ++x) {
        const Texel& t = texels[static_cast<std::size_t>(y) * width + x];
        mean.colour += t.colour, mean.normal += t.normal, mean.leaf += t.leaf, mean.coverage += t.coverage;
      }
    for (int y = 0; y < height; ++y)
      for (int x = first; x < last; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        const Texel& t = texels[i].coverage > 1e-4f ? texels[i] : mean;
        const float weight = t.coverage > 1e-6f ? 1.0f / t.coverage : 0.0f;
        const glm::vec3 colour = t.colour * weight;
        glm::vec3 n = t.normal * weight;
        n = glm::length(n) > 1e-6f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
        albedo[i] = {linear_to_srgb8(colour.r), linear_to_srgb8(colour.g), linear_to_srgb8(colour.b), to_byte(texels[i].coverage)};
        normal[i] = {to_byte(n.x * 0.5f + 0.5f), to_byte(n.y * 0.5f + 0.5f), to_byte(n.z * 0.5f + 0.5f), to_byte(t.leaf * weight)};
      }
    first = last;
  }
}

/// The orthographic projection times view of one capture: side view `view` or the top view
/// (view == side_views), at the plant's scale 1.
glm::mat4 capture_matrix(int view, const look::PlantBounds& bounds) {
  const double radius = std::max(static_cast<double>(bounds.radius), 1e-3);
  const double bottom = bounds.bottom, top = std::max(static_cast<double>(bounds.top), bottom + 1e-3);
  if (view == Layout::side_views) {
    const glm::dvec3 eye(0.0, top + 1.0, 0.0);
    const glm::dmat4 look = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 0.0, -1.0));
    return glm::mat4(glm::ortho(-radius, radius, -radius, radius, 0.0, top - bottom + 2.0) * look);
  }
  const double angle = 2.0 * std::numbers::pi * view / Layout::side_views;
  const double distance = radius + 1.0;
  const glm::dvec3 eye(std::sin(angle) * distance, 0.0, std::cos(angle) * distance);
  const glm::dmat4 look = glm::lookAt(eye, glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  return glm::mat4(glm::ortho(-radius, radius, bottom, top, 0.0, 2.0 * distance) * look);
}

}  // namespace

ImpostorLevels impostor_levels(std::span<const Rgba8> albedo, std::span<const Rgba8> normal) {
  constexpr int width = Layout::layer_width * Layout::supersample;
  const std::array<float, 256>& linear = srgb_to_linear_table();
  // One captured texel, everything weighted by its coverage.
  auto texel = [&](std::size_t i) {
    const float coverage = static_cast<float>(albedo[i].a) / 255.0f;
    const glm::vec3 n(static_cast<float>(normal[i].r), static_cast<float>(normal[i].g), static_cast<float>(normal[i].b));
    return Texel{glm::vec3(linear[albedo[i].r], linear[albedo[i].g], linear[albedo[i].b]) * coverage, (n / 127.5f - 1.0f) * coverage,
                 static_cast<float>(normal[i].a) / 255.0f * coverage, coverage};
  };
  static_assert(Layout::supersample == 2, "one halving from the capture to level 0");
  // Level 0 straight from the capture: the mean of 2x2 blocks, summed in halve()'s order.
  int level_width = Layout::layer_width, level_height = Layout::layer_height;
  std::vector<Texel> texels(static_cast<std::size_t>(level_width) * level_height);
  for (int y = 0; y < level_height; ++y)
    for (int x = 0; x < level_width; ++x) {
      Texel sum;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const Texel t = texel(static_cast<std::size_t>(2 * y + dy) * width + 2 * x + dx);
          sum.colour += t.colour, sum.normal += t.normal, sum.leaf += t.leaf, sum.coverage += t.coverage;
        }
      texels[static_cast<std::size_t>(y) * level_width + x] = {sum.colour * 0.25f, sum.normal * 0.25f, sum.leaf * 0.25f,
                                                               sum.coverage * 0.25f};
    }
  ImpostorLevels levels;
  levels.albedo.resize(Layout::levels);
  levels.normal.resize(Layout::levels);
  for (int level = 0; level < Layout::levels; ++level) {
    if (level > 0) {
      texels = halve(texels, level_width, level_height);
      level_width /= 2, level_height /= 2;
    }
    encode(texels, level, levels.albedo[level], levels.normal[level]);
  }
  return levels;
}

void build_impostor_atlas(GLuint program, GLuint vertex_array, std::span<const ImpostorSource> sources, GLuint albedo_texture,
                          GLuint normal_texture) {
  constexpr int width = Layout::layer_width * Layout::supersample, height = Layout::layer_height * Layout::supersample;
  // Sources are drawn in batches, each into the layers of two capture arrays with no wait
  // between them (the rasteriser works on one while the next is set up), read back at once, and
  // their levels made in parallel. Each layer is drawn as it would be alone: the same bytes.
  constexpr std::size_t batch = 16;
  GLint previous_framebuffer = 0;
  std::array<GLint, 4> previous_viewport{};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_framebuffer);
  glGetIntegerv(GL_VIEWPORT, previous_viewport.data());

  const auto batch_layers = static_cast<GLsizei>(std::min(batch, sources.size()));
  const GlName colour = make_texture(), normals = make_texture(), depth = make_renderbuffer();
  for (GLuint texture : {colour.id(), normals.id()}) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, width, height, batch_layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  const GlName framebuffer = make_framebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  const std::array<GLenum, 2> buffers{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers.data());

  std::vector<std::vector<Rgba8>> albedo_levels(Layout::levels), normal_levels(Layout::levels);
  for (int level = 0; level < Layout::levels; ++level) {
    const std::size_t size = static_cast<std::size_t>(Layout::layer_width >> level) * (Layout::layer_height >> level) * sources.size();
    albedo_levels[level].reserve(size);
    normal_levels[level].reserve(size);
  }
  const std::size_t layer_texels = static_cast<std::size_t>(width) * height;
  std::vector<Rgba8> albedo(layer_texels * static_cast<std::size_t>(batch_layers)), normal(albedo.size());
  std::vector<ImpostorLevels> levels(static_cast<std::size_t>(batch_layers));
  const Uniforms u(program);
  glBindVertexArray(vertex_array);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (std::size_t first = 0; first < sources.size(); first += batch) {
    const std::size_t count = std::min(batch, sources.size() - first);
    for (std::size_t k = 0; k < count; ++k) {
      const ImpostorSource& source = sources[first + k];
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, colour.id(), 0, static_cast<GLint>(k));
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, normals.id(), 0, static_cast<GLint>(k));
      if (k == 0 && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the impostor capture framebuffer is incomplete");
      glViewport(0, 0, width, height);
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClearDepth(1.0);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      for (int view = 0; view <= Layout::side_views; ++view) {
        const int cell = Layout::cell_width * Layout::supersample;
        glViewport(view * cell, 0, view == Layout::side_views ? 2 * cell : cell, height);
        u.set("u_capture", capture_matrix(view, source.bounds));
        // GL takes a byte offset into the bound index buffer as a pointer.
        const auto offset = static_cast<std::uintptr_t>(source.first_index) * sizeof(std::uint32_t);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(source.index_count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(offset));  // NOLINT(performance-no-int-to-ptr)
      }
    }
    // Every layer of the batch at once (a partly filled last batch reads its unused layers too).
    glBindTexture(GL_TEXTURE_2D_ARRAY, colour.id());
    glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_UNSIGNED_BYTE, albedo.data());
    glBindTexture(GL_TEXTURE_2D_ARRAY, normals.id());
    glGetTexImage(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA, GL_UNSIGNED_BYTE, normal.data());
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    parallel_for<std::size_t>(0, count, [&](std::size_t k) {
      levels[k] = impostor_levels(std::span(albedo).subspan(k * layer_texels, layer_texels),
                                  std::span(normal).subspan(k * layer_texels, layer_texels));
    });
    for (std::size_t k = 0; k < count; ++k)
      for (int level = 0; level < Layout::levels; ++level) {
        albedo_levels[level].insert(albedo_levels[level].end(), levels[k].albedo[level].begin(), levels[k].albedo[level].end());
        normal_levels[level].insert(normal_levels[level].end(), levels[k].normal[level].begin(), levels[k].normal[level].end());
      }
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);

  // Upload: all layers of a level at once.
  const auto layers = static_cast<GLsizei>(sources.size());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (const auto& [texture, format, texels] :
       {std::tuple{albedo_texture, GL_SRGB8_ALPHA8, &albedo_levels}, std::tuple{normal_texture, GL_RGBA8, &normal_levels}}) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
    for (int level = 0; level < Layout::levels; ++level)
      glTexImage3D(GL_TEXTURE_2D_ARRAY, level, static_cast<GLint>(format), Layout::layer_width >> level, Layout::layer_height >> level,
                   layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, (*texels)[level].data());
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, Layout::levels - 1);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  check_gl("building the impostor atlas");
}

}  // namespace sansui::render
