// A plant grown as a skeleton first (branches as polylines with radii, leaves as cards), then
// turned into triangles. Growing follows seed 003's recursive branching (a branch carries
// `branching` children along its length, each turned away by the branch angle and around it by
// the golden angle, shorter by the length ratio) with one grower per form: broadleaf crowns,
// conifer whorls (children longest at the bottom, so the crown is a cone), palms (an unbranched
// curved stem and a rosette of arching fronds), succulents (arms that turn upward) and ground
// plants. Random numbers come from one counter-based stream per (seed, species): the same
// arguments give the same bytes.
#include "vegetation/tree_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <fmt/format.h>

#include "core/random.hpp"

namespace sansui::vegetation {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double degrees = pi / 180.0;
constexpr double golden_angle = pi * (3.0 - 2.236067977499790);  // pi (3 - sqrt 5)
const glm::dvec3 up{0.0, 1.0, 0.0};

/// The tree's random numbers, drawn in a fixed order from one stream.
class Draws {
 public:
  Draws(std::uint64_t seed, std::string_view species) : key_(rng::stream_key(seed, hash(species))) {}
  double uniform() { return rng::to_uniform(rng::bits(key_, counter_++)); }
  double symmetric() { return 2.0 * uniform() - 1.0; }  ///< in [-1, 1)

 private:
  static std::uint64_t hash(std::string_view text) {
    std::uint64_t h = 0x7EE5;
    for (char c : text) h = rng::mix64(h ^ static_cast<unsigned char>(c));
    return h;
  }
  std::uint64_t key_;
  std::uint64_t counter_ = 0;
};

struct Branch {
  int level = 0;
  std::vector<glm::dvec3> points;
  std::vector<double> radii;  ///< metres, one per point
};

/// The outline of a strip card along its length.
enum class Outline {
  pointed,  ///< widest near the stem, to a point (blades, fern fronds)
  pinnate,  ///< a palm frond: full width along most of its length, folded along the rachis
  paddle,   ///< a banana leaf: a short stalk, then a broad oblong blade with a rounded tip, folded a little
};

struct Card {
  glm::dvec3 base, along, across;  ///< base point; along: length vector; across: half-width vector
  glm::vec3 colour;
  double bend = 0.0;  ///< fronds and blades: how far the tip droops, as a fraction of the length
  int pieces = 1;     ///< quads along the card
  Outline outline = Outline::pointed;
};

/// Quads along a palm's frond or leaf, full and simplified.
int palm_pieces(bool full) {
  return full ? 7 : 3;
}
/// Strips folded along their middle (two flat halves): four vertices a row instead of two.
bool folded(LeafKind leaf) {
  return leaf == LeafKind::frond || leaf == LeafKind::paddle;
}

struct Plant {
  std::vector<Branch> branches;
  std::vector<Card> cards;
};

glm::dvec3 perpendicular(const glm::dvec3& dir) {
  const glm::dvec3 other = std::abs(dir.y) < 0.9 ? up : glm::dvec3{1.0, 0.0, 0.0};
  return glm::normalize(glm::cross(dir, other));
}

/// `dir` turned away from itself by `tilt`, at `turn` about itself.
glm::dvec3 turned(const glm::dvec3& dir, double tilt, double turn) {
  const glm::dvec3 a = perpendicular(dir), b = glm::cross(dir, a);
  const glm::dvec3 side = std::cos(turn) * a + std::sin(turn) * b;
  return glm::normalize(std::cos(tilt) * dir + std::sin(tilt) * side);
}

glm::vec3 to_vec(const Rgb& c) {
  return {c.r, c.g, c.b};
}

class Grower {
 public:
  Grower(const Species& species, std::uint64_t seed, const TreeOptions& options)
      : s_(species), options_(options), draws_(seed, species.name), full_(options.detail == Detail::full) {}

  Plant grow() {
    switch (s_.form) {
      case Form::broadleaf:
      case Form::conifer:
        grow_woody();
        break;
      case Form::succulent:
        grow_succulent();
        break;
      case Form::palm:
        grow_palm();
        break;
      case Form::grass:
        grow_tuft();
        break;
      case Form::moss:
        break;  // a cushion, made directly as triangles (see emit_moss)
    }
    return std::move(plant_);
  }

 private:
  // ---- leaves' colours by season ----------------------------------------------------------
  glm::vec3 leaf_colour() {
    const double shade = 1.0 + 0.12 * draws_.symmetric();
    glm::vec3 colour = to_vec(s_.leaf_colour);
    switch (options_.season) {
      case Season::spring:
        colour = s_.flowering && draws_.uniform() < 0.6 ? to_vec(s_.blossom) : to_vec(s_.spring_colour);
        break;
      case Season::summer:
        break;
      case Season::autumn:
        if (s_.habit == Habit::deciduous)
          colour = glm::mix(to_vec(s_.leaf_colour), to_vec(s_.autumn_colour), 0.55 + 0.45 * draws_.uniform());
        break;
      case Season::winter:
        // Evergreens darken; ground plants that die back stay as dry straw.
        colour = s_.habit == Habit::deciduous ? to_vec(s_.autumn_colour) * 0.8f : to_vec(s_.leaf_colour) * 0.85f;
        break;
    }
    return glm::clamp(colour * static_cast<float>(shade), 0.0f, 1.0f);
  }

  void add_card(const glm::dvec3& base, const glm::dvec3& along, double width, double bend, int pieces) {
    const glm::dvec3 dir = glm::normalize(along);
    // Cards lie across the twig, turned a little at random, so a crown is not all edge-on.
    const glm::dvec3 across = turned(dir, pi / 2, pi * draws_.uniform());
    plant_.cards.push_back({base, along, across * (0.5 * width), leaf_colour(), bend, pieces});
  }

  // ---- branches ---------------------------------------------------------------------------
  /// One branch from `base` along `dir`: its polyline, then its children and leaves.
  void grow_branch(int level, const glm::dvec3& base, glm::dvec3 dir, double length, double radius) {
    const int last_level = s_.depth;
    const int steps = s_.form == Form::succulent ? (full_ ? 8 : 4) : (full_ ? (level == 0 ? 4 : level < 2 ? 3 : 2) : (level == 0 ? 2 : 1));
    Branch branch;
    branch.level = level;
    branch.points.push_back(base);
    branch.radii.push_back(radius);
    // Tropism bends each step toward (or away from) the vertical; cactus arms bend hard.
    const double bend = s_.tropism * (s_.form == Form::succulent ? 2.5 : 0.6) / steps;
    glm::dvec3 point = base;
    for (int k = 1; k <= steps; ++k) {
      if (level > 0) dir = glm::normalize(dir + bend * up);
      point += dir * (length / steps);
      branch.points.push_back(point);
      branch.radii.push_back(radius * (1.0 - (1.0 - s_.taper) * k / steps));
    }
    const std::size_t index = plant_.branches.size();
    plant_.branches.push_back(std::move(branch));
    top_ = std::max(top_, point.y);

    // A simplified plant stops a level early; its last branches carry the leaves.
    const int leaf_level = full_ ? last_level : std::max(0, last_level - 1);
    if (level >= leaf_level) {
      add_leaves(index, level < last_level ? s_.branching : 1);
      return;
    }
    grow_children(level, index, length);
  }

  void grow_children(int level, std::size_t parent, double parent_length) {
    const bool conifer_trunk = s_.form == Form::conifer && level == 0;
    const int whorls = conifer_trunk ? (full_ ? 11 : 7) : 1;
    const int count = s_.branching * whorls;
    const double start = level == 0 ? s_.trunk_bare : 0.3;
    const double spin = 2.0 * pi * draws_.uniform();
    for (int i = 0; i < count; ++i) {
      const int whorl = i / s_.branching, in_whorl = i % s_.branching;
      double t = conifer_trunk ? start + (1.0 - start) * (whorl + 0.35 * draws_.uniform()) / whorls
                               : start + (1.0 - start) * (i + 0.5 + 0.4 * draws_.symmetric()) / count;
      t = std::clamp(t, 0.0, 0.98);
      const double turn = conifer_trunk ? spin + 2.0 * pi * (in_whorl + 0.5 * whorl) / s_.branching + 0.2 * draws_.symmetric()
                                        : spin + golden_angle * i + s_.angle_jitter_deg * degrees * draws_.symmetric();
      const double tilt = (s_.branch_angle_deg + s_.angle_jitter_deg * draws_.symmetric()) * degrees;
      // A child's length: conifers' shrink linearly up the trunk (a cone); broadleaf crowns'
      // lower children are a little longer (a rounded crown).
      double profile = 1.0;
      if (conifer_trunk)
        profile = 1.35 * (1.0 - (t - start) / (1.0 - start)) + 0.08;
      else if (level == 0)
        profile = 1.15 - 0.35 * (t - start) / std::max(1.0 - start, 1e-6);
      const double length = parent_length * s_.length_ratio * profile * (1.0 + 0.15 * draws_.symmetric());
      const Branch& from = plant_.branches[parent];
      const auto [point, direction, radius] = along(from, t);
      const double child_radius = radius * (s_.form == Form::succulent ? 0.8 : 0.62);
      grow_branch(level + 1, point, turned(direction, tilt, turn), length, child_radius);
    }
  }

  /// Point, direction and radius at fraction t of a branch's length.
  static std::tuple<glm::dvec3, glm::dvec3, double> along(const Branch& branch, double t) {
    const double x = t * static_cast<double>(branch.points.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(x), branch.points.size() - 2);
    const double f = x - static_cast<double>(k);
    const glm::dvec3 a = branch.points[k], b = branch.points[k + 1];
    return {a + (b - a) * f, glm::normalize(b - a), branch.radii[k] + (branch.radii[k + 1] - branch.radii[k]) * f};
  }

  /// Leaves along a twig. A simplified plant has no twigs: its last branches carry the leaves of
  /// their would-be children, as fewer, larger cards spread wider (about the same leaf area).
  void add_leaves(std::size_t twig, int merged) {
    if (s_.leaf == LeafKind::none || !has_leaves(s_, options_.season)) {
      if (s_.form == Form::succulent && s_.flowering && options_.season == Season::spring) add_flowers(twig);
      return;
    }
    const int cards = merged > 1 ? std::max(2, s_.leaves_per_twig * merged / 4) : s_.leaves_per_twig;
    const double size = s_.leaf_size_m * (merged > 1 ? 2.0 : 1.0);
    const double reach = merged > 1 ? s_.length_ratio : 0.0;
    for (int i = 0; i < cards; ++i) {
      const Branch& branch = plant_.branches[twig];
      const double t = 0.25 + 0.75 * draws_.uniform();
      const auto [point, direction, radius] = along(branch, t);
      const double length = glm::length(branch.points.back() - branch.points.front());
      const glm::dvec3 offset = turned(direction, pi / 2, 2 * pi * draws_.uniform()) * (reach * length * draws_.uniform());
      const double spread = (s_.leaf_spread_deg + 15.0 * draws_.symmetric()) * degrees;
      const glm::dvec3 dir = turned(direction, spread, golden_angle * i + draws_.symmetric());
      add_card(point + offset, dir * size, size / s_.leaf_length, 0.0, 1);
    }
  }

  void add_flowers(std::size_t stem) {
    const Branch& branch = plant_.branches[stem];
    const glm::dvec3 tip = branch.points.back();
    const double r = branch.radii.back();
    for (int i = 0; i < 5; ++i) {
      const double turn = 2 * pi * i / 5;
      const glm::dvec3 dir = turned(up, 0.6, turn);
      plant_.cards.push_back(
          {tip + glm::dvec3{0, r * 0.6, 0}, dir * (1.6 * r), perpendicular(dir) * (0.5 * r), to_vec(s_.blossom), 0.0, 1});
    }
  }

  void grow_woody() {
    // The trunk, slightly off the vertical; its length is scaled so the plant reaches height_m.
    const double lean = (s_.form == Form::succulent ? 2.0 : 4.0) * degrees * draws_.uniform();
    const glm::dvec3 dir = turned(up, lean, 2 * pi * draws_.uniform());
    grow_branch(0, {0, 0, 0}, dir, 1.0, s_.trunk_radius);
    // Scale to the species' height (leaves keep their sizes in metres).
    const double leaf_top = s_.leaf == LeafKind::none ? 0.0 : 0.3 * s_.leaf_size_m;
    const double scale = std::max(s_.height_m - leaf_top, 0.5 * s_.height_m) / std::max(top_, 1e-9);
    for (Branch& branch : plant_.branches) {
      for (glm::dvec3& p : branch.points) p *= scale;
      for (double& r : branch.radii) r *= s_.height_m;  // radii were fractions of the height
    }
    for (Card& card : plant_.cards) card.base *= scale;
  }

  /// A columnar cactus (saguaro): a straight, thick stem and arms that leave it about
  /// horizontally between a third and two thirds of its height, bend up in an elbow and rise
  /// parallel to it. Every arm is `branching` long tubes of `steps` segments, as tree_size counts.
  void grow_succulent() {
    const int steps = full_ ? 8 : 4;
    const double height = s_.height_m, trunk_radius = s_.trunk_radius * height;
    const double lean = 2.0 * degrees * draws_.uniform();
    const glm::dvec3 dir = turned(up, lean, 2 * pi * draws_.uniform());
    const double stem_length = height - trunk_radius;  // the domed cap adds the rest
    Branch trunk;
    for (int k = 0; k <= steps; ++k) {
      trunk.points.push_back(dir * (stem_length * k / steps));
      trunk.radii.push_back(trunk_radius * (1.0 - (1.0 - s_.taper) * k / steps));
    }
    plant_.branches.push_back(std::move(trunk));
    const double spin = 2 * pi * draws_.uniform();
    const int elbow_steps = steps / 2, rise_steps = steps - elbow_steps;
    for (int a = 0; a < s_.branching; ++a) {
      // Arms spread around the stem and up it, the lowest longest.
      const double t = s_.trunk_bare + (0.62 - s_.trunk_bare) * (a + 0.8 * draws_.uniform()) / std::max(s_.branching, 1);
      const double turn = spin + 2 * pi * a / std::max(s_.branching, 1) + 0.6 * draws_.symmetric();
      const glm::dvec3 out{std::cos(turn), 0.0, std::sin(turn)};
      const glm::dvec3 base = dir * (stem_length * t);
      const double arm_radius = trunk_radius * (0.68 + 0.1 * draws_.uniform());
      const double elbow = arm_radius * (3.0 + 2.0 * draws_.uniform());  // radius of the bend up
      const double top = height * (0.72 + 0.2 * draws_.uniform()) - arm_radius;
      const double rise = std::max(top - base.y - elbow, 2.0 * arm_radius);
      Branch arm;
      arm.level = 1;
      for (int k = 0; k <= elbow_steps; ++k) {
        const double angle = (pi / 2) * k / elbow_steps;
        arm.points.push_back(base + out * (elbow * std::sin(angle)) + up * (elbow * (1.0 - std::cos(angle))));
        arm.radii.push_back(arm_radius);
      }
      const glm::dvec3 bend_end = arm.points.back();
      for (int k = 1; k <= rise_steps; ++k) {
        arm.points.push_back(bend_end + up * (rise * k / rise_steps));
        arm.radii.push_back(arm_radius * (1.0 - 0.15 * k / rise_steps));
      }
      plant_.branches.push_back(std::move(arm));
    }
    if (s_.flowering && options_.season == Season::spring)
      for (std::size_t b = 0; b < plant_.branches.size(); ++b) add_flowers(b);
  }

  void grow_palm() {
    const bool paddle = s_.leaf == LeafKind::paddle;
    const int steps = full_ ? 8 : 3;
    // Fronds rise above the stem's top: a banana's leaves stand high over its short pseudostem.
    const double rise_share = paddle ? 0.7 : 0.3;
    const double stem_height = s_.height_m - rise_share * s_.leaf_size_m * std::sin(std::max(s_.leaf_spread_deg, 10.0) * degrees);
    // A curved stem: leaning out at the foot by the tropism, turning back up toward the top.
    const double lean = (-s_.tropism * 60.0 + 6.0 * draws_.uniform()) * degrees;
    glm::dvec3 dir = turned(up, lean, 2 * pi * draws_.uniform());
    Branch stem;
    glm::dvec3 point{0, 0, 0};
    const double step = std::max(stem_height, 0.3) / steps;
    for (int k = 0; k <= steps; ++k) {
      stem.points.push_back(point);
      const double radius = s_.trunk_radius * s_.height_m * (1.0 - (1.0 - s_.taper) * k / steps) * (k == 0 ? 1.3 : 1.0);
      stem.radii.push_back(radius);
      point += dir * step;
      dir = glm::normalize(dir + up * (0.12 / steps * 8));
    }
    const glm::dvec3 top = stem.points.back();
    const double top_radius = stem.radii.back();
    plant_.branches.push_back(std::move(stem));
    if (!has_leaves(s_, options_.season)) return;
    // The rosette: younger fronds rise steeply, older ones spread and hang. Pinnate fronds are
    // full width along most of their length and folded along the rachis (leaflets hang down on
    // both sides), so they read as fronds from the side as well as from above; a banana's
    // leaves are broad paddles on short stalks.
    const int fronds = full_ ? s_.leaves_per_twig : std::max(3, s_.leaves_per_twig * 2 / 3);
    const double spin = 2 * pi * draws_.uniform();
    const Outline outline = paddle ? Outline::paddle : s_.leaf == LeafKind::frond ? Outline::pinnate : Outline::pointed;
    for (int i = 0; i < fronds; ++i) {
      const double age = fronds > 1 ? static_cast<double>(i) / (fronds - 1) : 0.5;
      // Pinnate fronds fan from nearly upright (the youngest) to hanging (the oldest).
      const double fan = outline == Outline::pinnate ? 60.0 : 35.0;
      const double rise = (s_.leaf_spread_deg + fan * (0.5 - age) + 8.0 * draws_.symmetric()) * degrees;
      const double turn = spin + golden_angle * i;
      const glm::dvec3 out{std::cos(turn), 0.0, std::sin(turn)};
      const glm::dvec3 frond_axis = glm::normalize(out * std::cos(rise) + up * std::sin(rise));
      const double size = s_.leaf_size_m * (0.8 + 0.3 * draws_.uniform());
      const double width = size / s_.leaf_length * 1.6;
      // Fronds lie flat-ish: their width is horizontal, across the frond.
      const glm::dvec3 side = glm::normalize(glm::cross(up, out)) * (0.5 * width);
      const double droop = paddle ? 0.35 + 0.55 * age : 0.55 + 0.9 * age * (1.0 - s_.leaf_spread_deg / 90.0);
      plant_.cards.push_back({top + up * (0.3 * top_radius), frond_axis * size, side, leaf_colour(), droop, palm_pieces(full_), outline});
    }
  }

  void grow_tuft() {
    const int blades = full_ ? s_.leaves_per_twig : std::max(2, s_.leaves_per_twig / 2);
    const bool frond = s_.leaf == LeafKind::frond;
    for (int i = 0; i < blades; ++i) {
      const double turn = golden_angle * i + draws_.symmetric();
      const double tilt = s_.leaf_spread_deg * (frond ? 1.0 : draws_.uniform()) * degrees;
      const glm::dvec3 out{std::cos(turn), 0.0, std::sin(turn)};
      const glm::dvec3 dir = glm::normalize(up * std::cos(tilt) + out * std::sin(tilt));
      const double size = s_.height_m * (0.7 + 0.3 * draws_.uniform()) / std::max(std::cos(tilt), 0.3);
      const glm::dvec3 base = out * (0.08 * s_.height_m * draws_.uniform());
      const glm::dvec3 side = glm::normalize(glm::cross(up, out)) * (0.5 * size / s_.leaf_length * (frond ? 2.0 : 1.0));
      plant_.cards.push_back({base, dir * size, side, leaf_colour(), frond ? 0.5 : 0.25, full_ ? 3 : 2});
    }
  }

  const Species& s_;
  const TreeOptions& options_;
  Draws draws_;
  bool full_;
  Plant plant_;
  double top_ = 0.0;
};

// ---- triangles --------------------------------------------------------------------------

class MeshWriter {
 public:
  MeshWriter(const Species& species, const TreeOptions& options) : s_(species), options_(options) {}

  void tube(const Branch& branch, int sides) {
    const glm::vec3 bark = to_vec(s_.bark);
    const std::size_t n = branch.points.size();
    // One frame per point, carried along so the tube does not twist.
    glm::dvec3 dir = glm::normalize(branch.points[1] - branch.points[0]);
    glm::dvec3 a = perpendicular(dir);
    const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) dir = glm::normalize(branch.points[k] - branch.points[k - 1]);
      if (k + 1 < n && k > 0) dir = glm::normalize(branch.points[k + 1] - branch.points[k - 1]);
      a = glm::normalize(a - dir * glm::dot(a, dir));
      const glm::dvec3 b = glm::cross(dir, a);
      for (int j = 0; j < sides; ++j) {
        const double angle = 2 * pi * j / sides;
        const glm::dvec3 normal = std::cos(angle) * a + std::sin(angle) * b;
        vertex(branch.points[k] + normal * branch.radii[k], normal, snowy(bark, normal));
      }
    }
    for (std::size_t k = 0; k + 1 < n; ++k)
      for (int j = 0; j < sides; ++j) {
        const auto i0 = first + static_cast<std::uint32_t>(k * sides + j);
        const auto i1 = first + static_cast<std::uint32_t>(k * sides + (j + 1) % sides);
        quad(i0, i1, i1 + sides, i0 + sides);
      }
    // Caps close both ends (a cactus's top is domed).
    cap(branch.points.front(), -glm::normalize(branch.points[1] - branch.points[0]), first, sides, false, 0.0);
    const double dome = s_.form == Form::succulent ? branch.radii.back() : 0.0;
    cap(branch.points.back(), glm::normalize(branch.points[n - 1] - branch.points[n - 2]),
        first + static_cast<std::uint32_t>((n - 1) * sides), sides, true, dome);
  }

  void card(const Card& c) {
    const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
    glm::dvec3 normal = glm::normalize(glm::cross(c.across, c.along));
    if (normal.y < 0.0) normal = -normal;  // double-sided: lit as facing up
    const glm::vec3 colour = snowy(c.colour, normal);
    if (c.pieces == 1 && s_.leaf == LeafKind::needle) {
      // A tuft of needles: a fan from the twig with two points and a notch between them, so a
      // conifer's outline is spiky, for the same two triangles as a leaf.
      vertex(c.base, normal, colour);
      vertex(c.base + c.along * 0.9 - c.across * 0.85, normal, colour);
      vertex(c.base + c.along * 0.62, normal, colour);
      vertex(c.base + c.along * 0.9 + c.across * 0.85, normal, colour);
      quad(first, first + 1, first + 2, first + 3);
      return;
    }
    if (c.pieces == 1) {  // a leaf: a diamond, widest a third of the way out
      vertex(c.base, normal, colour);
      vertex(c.base + c.along * 0.35 - c.across, normal, colour);
      vertex(c.base + c.along, normal, colour);
      vertex(c.base + c.along * 0.35 + c.across, normal, colour);
      quad(first, first + 1, first + 2, first + 3);
      return;
    }
    // Fronds and blades: a strip drooping by `bend`, its width following the outline. Fronds
    // and paddles are folded along the middle: two flat halves whose outer edges hang lower, so
    // a frond seen edge-on is still a shape and each half keeps one normal (a leaf to
    // look/plant_models.cpp).
    const double length = glm::length(c.along);
    const bool fold = c.outline != Outline::pointed;
    const glm::dvec3 half_dir = glm::normalize(c.across);
    const double fold_depth = c.outline == Outline::pinnate ? 0.55 : 0.2;  // edge drop over half-width
    glm::dvec3 left_normal = normal, right_normal = normal;
    if (fold) {
      left_normal = glm::normalize(normal - half_dir * fold_depth);
      right_normal = glm::normalize(normal + half_dir * fold_depth);
    }
    const glm::vec3 left_colour = snowy(c.colour, left_normal), right_colour = snowy(c.colour, right_normal);
    glm::dvec3 point = c.base, dir = glm::normalize(c.along);
    for (int k = 0; k <= c.pieces; ++k) {
      const double width = outline_width(c.outline, static_cast<double>(k) / c.pieces);
      const glm::dvec3 drop = fold ? -glm::dvec3(normal) * (fold_depth * glm::length(c.across) * width) : glm::dvec3(0.0);
      if (fold) {
        vertex(point - c.across * width + drop, left_normal, left_colour);
        vertex(point, left_normal, left_colour);
        vertex(point, right_normal, right_colour);
        vertex(point + c.across * width + drop, right_normal, right_colour);
      } else {
        vertex(point - c.across * width, normal, colour);
        vertex(point + c.across * width, normal, colour);
      }
      point += dir * (length / c.pieces);
      dir = glm::normalize(dir - up * (c.bend * 2.0 / c.pieces));
    }
    const std::uint32_t row = fold ? 4 : 2;
    for (int k = 0; k < c.pieces; ++k) {
      const auto i = first + static_cast<std::uint32_t>(row * k);
      quad(i, i + 1, i + row + 1, i + row);
      if (fold) quad(i + 2, i + 3, i + row + 3, i + row + 2);
    }
  }

  /// Half-width of a strip at fraction f of its length, as a fraction of the card's.
  static double outline_width(Outline outline, double f) {
    switch (outline) {
      case Outline::pinnate:
        // Leaflets start a little way up the stalk and shorten toward the tip.
        return std::clamp(f / 0.12, 0.15, 1.0) * (1.0 - f * f * f);
      case Outline::paddle: {
        // A short stalk, then an oblong blade with a rounded tip.
        const double q = (f - 0.56) / 0.46, q2 = q * q, q8 = q2 * q2 * q2 * q2;
        const double blade = std::clamp((f - 0.06) / 0.14, 0.0, 1.0);
        return 0.06 + 0.94 * blade * std::sqrt(std::max(0.0, 1.0 - q8));
      }
      case Outline::pointed:
        break;
    }
    return (1.0 - f) * std::min(1.0, 4.0 * f + 0.3);
  }

  void moss() {
    // A low cushion: a squashed dome of 3 rings.
    constexpr int around = 8, rings = 3;
    const double radius = 2.5 * s_.height_m, height = s_.height_m;
    glm::vec3 colour = to_vec(s_.leaf_colour);
    const auto first = static_cast<std::uint32_t>(mesh_.positions.size());
    for (int r = 0; r < rings; ++r) {
      const double phi = (pi / 2) * r / rings;
      for (int j = 0; j < around; ++j) {
        const double a = 2 * pi * j / around;
        const glm::dvec3 normal = glm::normalize(glm::dvec3{std::cos(phi) * std::cos(a), std::sin(phi) * 2.0, std::cos(phi) * std::sin(a)});
        vertex({radius * std::cos(phi) * std::cos(a), height * std::sin(phi), radius * std::cos(phi) * std::sin(a)}, normal,
               snowy(colour, normal));
      }
    }
    vertex({0, height, 0}, up, snowy(colour, up));
    for (int r = 0; r + 1 < rings; ++r)
      for (int j = 0; j < around; ++j) {
        const auto i0 = first + static_cast<std::uint32_t>(r * around + j),
                   i1 = first + static_cast<std::uint32_t>(r * around + (j + 1) % around);
        quad(i0, i1, i1 + around, i0 + around);
      }
    const auto top = static_cast<std::uint32_t>(mesh_.positions.size() - 1);
    for (int j = 0; j < around; ++j)
      triangle(first + static_cast<std::uint32_t>((rings - 1) * around + j),
               first + static_cast<std::uint32_t>((rings - 1) * around + (j + 1) % around), top);
  }

  TriangleMesh take() { return std::move(mesh_); }

 private:
  /// Snow settles on upward faces of evergreens in a snowy winter.
  glm::vec3 snowy(const glm::vec3& colour, const glm::dvec3& normal) const {
    if (!options_.snow || options_.season != Season::winter) return colour;
    const auto cover = static_cast<float>(std::clamp((normal.y - 0.2) / 0.5, 0.0, 1.0) * 0.85);
    return glm::mix(colour, glm::vec3{0.93f, 0.95f, 0.98f}, cover);
  }

  void cap(const glm::dvec3& centre, const glm::dvec3& outward, std::uint32_t ring, int sides, bool end, double dome) {
    const auto middle = static_cast<std::uint32_t>(mesh_.positions.size());
    vertex(centre + outward * dome, outward, snowy(to_vec(s_.bark), outward));
    for (int j = 0; j < sides; ++j) {
      const auto a = ring + static_cast<std::uint32_t>(j), b = ring + static_cast<std::uint32_t>((j + 1) % sides);
      if (end)
        triangle(a, b, middle);
      else
        triangle(b, a, middle);
    }
  }

  void vertex(const glm::dvec3& p, const glm::dvec3& n, const glm::vec3& colour) {
    mesh_.positions.emplace_back(p);
    mesh_.normals.emplace_back(glm::normalize(n));
    mesh_.colors.push_back(colour);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) { mesh_.indices.insert(mesh_.indices.end(), {a, b, c}); }
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }

  const Species& s_;
  const TreeOptions& options_;
  TriangleMesh mesh_;
};

}  // namespace

bool has_leaves(const Species& species, Season season) {
  if (species.leaf == LeafKind::none) return false;
  // Ground plants that die back stay as straw through the winter; trees stand bare.
  return !(species.habit == Habit::deciduous && season == Season::winter && species.layer == Layer::tree);
}

TreeSize tree_size(const Species& species, const TreeOptions& options) {
  // The counts follow Grower and MeshWriter above: keep them in step.
  const bool full = options.detail == Detail::full;
  TreeSize size;
  auto add_tube = [&](double count, int steps, int sides) {
    size.branches += count;
    size.points += count * (steps + 1);
    size.vertices += count * ((steps + 1) * sides + 2);
    size.triangles += count * (2 * steps * sides + 2 * sides);
  };
  auto add_cards = [&](double count, int pieces) {
    size.cards += count;
    size.vertices += count * (pieces == 1 ? 4 : 2 * (pieces + 1));
    size.triangles += count * 2 * pieces;
  };
  switch (species.form) {
    case Form::succulent: {
      // grow_succulent: the stem and `branching` arms, each of `steps` segments; flowers on every tip.
      const int steps = full ? 8 : 4;
      add_tube(1.0 + species.branching, steps, full ? 10 : 5);
      if (species.flowering && options.season == Season::spring) add_cards(5.0 * (1.0 + species.branching), 1);
      break;
    }
    case Form::broadleaf:
    case Form::conifer: {
      const int leaf_level = full ? species.depth : std::max(0, species.depth - 1);
      const int sides = species.form == Form::succulent ? (full ? 10 : 5) : (full ? 6 : 3);
      double count = 1.0;  // branches of this level
      for (int level = 0; level <= leaf_level; ++level) {
        const int steps = species.form == Form::succulent ? (full ? 8 : 4)
                                                          : (full ? (level == 0  ? 4
                                                                     : level < 2 ? 3
                                                                                 : 2)
                                                                  : (level == 0 ? 2 : 1));
        add_tube(count, steps, level >= 2 && level == species.depth ? 3 : sides);
        if (level == leaf_level) break;
        const int whorls = species.form == Form::conifer && level == 0 ? (full ? 11 : 7) : 1;
        count *= static_cast<double>(species.branching) * whorls;
      }
      // The twigs' leaves (merged into fewer cards on a simplified plant), or a cactus's flowers.
      const int merged = leaf_level < species.depth ? species.branching : 1;
      const int leaves = merged > 1 ? std::max(2, species.leaves_per_twig * merged / 4) : species.leaves_per_twig;
      const bool leafy = has_leaves(species, options.season);
      const bool flowers = !leafy && species.form == Form::succulent && species.flowering && options.season == Season::spring;
      add_cards(count * (leafy ? leaves : flowers ? 5 : 0), 1);
      break;
    }
    case Form::palm:
      add_tube(1.0, full ? 8 : 3, full ? 6 : 3);
      if (has_leaves(species, options.season)) {
        const double fronds = full ? species.leaves_per_twig : std::max(3, species.leaves_per_twig * 2 / 3);
        const int pieces = palm_pieces(full);
        if (folded(species.leaf)) {  // four vertices a row, two quads a piece
          size.cards += fronds;
          size.vertices += fronds * 4 * (pieces + 1);
          size.triangles += fronds * 4 * pieces;
        } else {
          add_cards(fronds, pieces);
        }
      }
      break;
    case Form::grass:
      add_cards(full ? species.leaves_per_twig : std::max(2, species.leaves_per_twig / 2), full ? 3 : 2);
      break;
    case Form::moss:
      size.vertices += 25.0;
      size.triangles += 40.0;
      break;
  }
  return size;
}

budget::Cost tree_cost(const Species& species, const TreeOptions& options) {
  const TreeSize size = tree_size(species, options);
  budget::Cost cost;
  // The skeleton (a Branch of two vectors a branch, a Card a card) and the mesh (36 bytes a
  // vertex, 12 a triangle) are held at once. Measured against the peak resident memory of
  // `sansui tree ... -o x.glb`: tests/cli/budget_cli_test.cpp.
  // Lists grown by doubling hold about 1.4 times their contents at the peak.
  cost.bytes = 1.4 * (120.0 * size.branches + 32.0 * size.points + static_cast<double>(sizeof(Card)) * size.cards + 36.0 * size.vertices +
                      12.0 * size.triangles);
  cost.seconds = 0.7e-6 * size.triangles;
  cost.what = fmt::format("the plant '{}' (branching {}, depth {}, {} leaves per twig: {:.3g} branches, {:.3g} triangles)", species.name,
                          species.branching, species.depth, species.leaves_per_twig, size.branches, size.triangles);
  cost.smaller = "lower its branching, depth or leaves_per_twig";
  cost.force.clear();  // a plant has no force: over ten minutes it is far over any memory too
  return cost;
}

TriangleMesh build_tree(const Species& species, std::uint64_t seed, const TreeOptions& options) {
  species.validate();
  budget::check(tree_cost(species, options));
  const Plant plant = Grower(species, seed, options).grow();
  MeshWriter writer(species, options);
  const bool full = options.detail == Detail::full;
  const int sides = species.form == Form::succulent ? (full ? 10 : 5) : (full ? 6 : 3);
  // Twigs of finely branched plants are thin: three sides are enough.
  for (const Branch& branch : plant.branches) writer.tube(branch, branch.level >= 2 && branch.level == species.depth ? 3 : sides);
  for (const Card& card : plant.cards) writer.card(card);
  if (species.form == Form::moss) writer.moss();
  return writer.take();
}

}  // namespace sansui::vegetation
