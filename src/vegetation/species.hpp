// Plant species (seed 003, Sec. 4.1.6 and Table 1; SPEC 3.3): the parameters of a recursive
// branching tree, its leaves and colours, and where it grows. The library of species and which
// climates they belong to is data, data/species.toml, compiled into the library like
// data/climate.toml; each species is also a parameter table ([species] in a scene file
// overrides one species' values).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/color.hpp"
#include "core/params.hpp"

namespace sansui::vegetation {

/// The overall build, which picks how the generator grows the plant.
enum class Form {
  broadleaf,  ///< trunk up to a crown of forking branches (oak, beech, baobab, acacia)
  conifer,    ///< one straight leader with whorls of branches, longest at the bottom (spruce, fir)
  palm,       ///< an unbranched, slightly curved stem with a rosette of fronds (palms, banana)
  succulent,  ///< a thick stem with a few arms that turn upward (saguaro cactus)
  grass,      ///< a tuft of blades from the ground (the dense ground layer)
  moss,       ///< a low cushion (tundra ground layer)
};

enum class LeafKind {
  none,    ///< no leaves (cactus)
  broad,   ///< flat leaf cards
  needle,  ///< narrow cards in dense tufts (conifers)
  frond,   ///< long arching pinnate fronds from the stem's top, folded along the rachis (palms)
  paddle,  ///< broad oblong leaves on a short stalk, arching from the stem's top (banana)
  blade,   ///< upright narrow cards (grass)
};

enum class Habit {
  evergreen,  ///< keeps its leaves all year
  deciduous,  ///< autumn colours, bare in winter
};

/// Which layer of the placement a species belongs to.
enum class Layer {
  tree,    ///< the scattered tree layer, at the climate's tree density
  ground,  ///< the dense layer of grass and small plants
};

struct Species {
  std::string name = "oak";   ///< key, [a-z_]+ ("oak", "date_palm")
  std::string title = "oak";  ///< in words, for pictures and docs
  Form form = Form::broadleaf;
  Layer layer = Layer::tree;
  /// Typical grown height from the ground to the top. [Units: m] [Range: 0.02..120]
  double height_m = 15.0;
  /// Each plant's height varies by up to this fraction. [Range: 0..0.9]
  double height_jitter = 0.25;
  /// Trunk radius at the ground as a fraction of the height. [Range: 0.002..0.5]
  double trunk_radius = 0.025;
  /// Radius at a branch's tip relative to its base. [Range: 0..1]
  double taper = 0.5;
  /// Fraction of the trunk below its first branch (bare stem). [Range: 0..0.98]
  double trunk_bare = 0.35;
  /// Children per branch (the paper: five). [Range: 0..12]
  int branching = 5;
  /// Levels of branching. [Range: 0..8]
  int depth = 3;
  /// A child branch's length relative to its parent (trunk:branch ratio). [Range: 0.05..1.5]
  double length_ratio = 0.55;
  /// Angle between a child branch and its parent. [Units: deg] [Range: 0..150]
  double branch_angle_deg = 45.0;
  /// Random spread of that angle and of the turn about the parent. [Units: deg] [Range: 0..90]
  double angle_jitter_deg = 12.0;
  /// Tendency to turn up (> 0, cactus arms) or droop (< 0, willow) along a branch. [Range: -1..1]
  double tropism = 0.1;
  LeafKind leaf = LeafKind::broad;
  /// Leaf (or frond, needle tuft, blade) size. [Units: m] [Range: 0.005..12]
  double leaf_size_m = 0.6;
  /// Leaf length over width. [Range: 0.2..40]
  double leaf_length = 1.5;
  /// Angle of leaves from their twig (fronds: from the horizontal, drooping). [Units: deg] [Range: 0..180]
  double leaf_spread_deg = 40.0;
  /// Leaves per outermost twig. [Range: 0..64]
  int leaves_per_twig = 6;
  Habit habit = Habit::deciduous;
  /// Blossoms in spring. [Default: false]
  bool flowering = false;
  Rgb bark{0.35f, 0.27f, 0.2f};
  Rgb leaf_colour{0.22f, 0.4f, 0.12f};     ///< summer
  Rgb spring_colour{0.45f, 0.62f, 0.22f};  ///< fresh leaves
  Rgb autumn_colour{0.72f, 0.38f, 0.1f};   ///< deciduous only
  Rgb blossom{0.98f, 0.8f, 0.86f};         ///< flowering only
  /// Does not grow on slopes steeper than this. [Units: deg] [Range: 0..90]
  double max_slope_deg = 35.0;

  void validate() const;  ///< throws InputError naming the key and what is allowed
};

const params::Table<Species>& parameter_table(const Species*);

/// Every species of data/species.toml, in file order. The first call parses the embedded table
/// (a corrupt table throws std::logic_error: a programmer's error).
const std::vector<Species>& species_library();
/// The library's species called `name`; throws InputError listing the names when there is none.
const Species& species_named(std::string_view name);

/// A species as one climate grows it: where in the forest band (fractions from the coast, 0, to
/// the tree line, 1) and how common it is there.
struct ClimateSpecies {
  std::string species;       ///< a name of species_library()
  double band_low = 0.0;     ///< [Range: 0..1]
  double band_high = 1.0;    ///< [Range: 0..1], > band_low
  double weight = 1.0;       ///< relative share where bands overlap. [Range: > 0]
  bool near_water = false;   ///< only within the water's-edge band (date palms at an oasis)
  bool summer_only = false;  ///< only in summer (tundra moss)
};

/// The plants data/species.toml gives the Köppen climate `koppen` ("Cfb"), tree layer and
/// ground layer together; empty for EF and for an unknown name.
const std::vector<ClimateSpecies>& species_of_climate(std::string_view koppen);
/// Share of ground-grid cells holding grass or a small plant in the climate `koppen`; 0 for an
/// unknown name. [Range: 0..1]
double ground_density_of_climate(std::string_view koppen);

/// The [[species]] tables of a user's species file (data/species.toml's form, without climates),
/// each checked against the [species] table. Throws InputError "SOURCE:LINE: ..." naming the key
/// and what is allowed.
std::vector<Species> read_species_file(std::string_view text, std::string_view source);

/// The text of data/species.toml as compiled into the library.
std::string_view species_table_text();

}  // namespace sansui::vegetation
