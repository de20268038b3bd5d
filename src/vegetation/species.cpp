// The species table and the embedded library (data/species.toml, compiled in by
// src/vegetation/CMakeLists.txt). The library is read strictly, once: an unknown key, a value
// out of its row's range or a climate naming a missing species is a programmer's error
// (std::logic_error naming the line), caught by the tests before anyone runs it.
#include "vegetation/species.hpp"

#include <map>
#include <stdexcept>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/error.hpp"
#include "core/params_toml.hpp"
#include "core/toml_nesting.hpp"
#include "vegetation/tree_mesh.hpp"

namespace sansui::vegetation {

const params::Table<Species>& parameter_table(const Species*) {
  using P = Species;
  static const auto table =
      params::Table<P>("species", "A plant species: its branching, leaves, colours and where it grows (Oka et al. 1997, Table 1)")
          .add(params::field("name", &P::name).doc("Key of the species, as scenes and `sansui tree --species` name it").grouped("species"))
          .add(params::field("title", &P::title).doc("Name in words, for pictures and docs").grouped("species"))
          .add(params::choice("form", &P::form,
                              {{"broadleaf", Form::broadleaf},
                               {"conifer", Form::conifer},
                               {"palm", Form::palm},
                               {"succulent", Form::succulent},
                               {"grass", Form::grass},
                               {"moss", Form::moss}})
                   .doc("Build: forking crown, conical whorls, stem with fronds, cactus arms, grass tuft, moss cushion")
                   .grouped("species"))
          .add(params::choice("layer", &P::layer, {{"tree", Layer::tree}, {"ground", Layer::ground}})
                   .doc("Placement layer: scattered trees, or the dense ground layer")
                   .grouped("species"))
          .add(params::field("height", &P::height_m).in(0.02, 120).units("m").doc("Typical grown height").grouped("shape"))
          .add(params::field("height_jitter", &P::height_jitter)
                   .in(0, 0.9)
                   .no_unit()
                   .doc("Each plant's height varies by up to this fraction")
                   .grouped("shape"))
          .add(params::field("trunk_radius", &P::trunk_radius)
                   .in(0.002, 0.5)
                   .no_unit()
                   .doc("Trunk radius at the ground over the height")
                   .grouped("shape"))
          .add(params::field("taper", &P::taper).in(0, 1).no_unit().doc("Radius at a branch's tip over its base").grouped("shape"))
          .add(params::field("trunk_bare", &P::trunk_bare)
                   .in(0, 0.98)
                   .no_unit()
                   .doc("Share of the trunk below its first branch")
                   .grouped("shape"))
          .add(params::field("branching", &P::branching).in(0, 12).doc("Children per branch (the paper: five)").grouped("shape"))
          .add(params::field("depth", &P::depth).in(0, 8).doc("Levels of branching").grouped("shape"))
          .add(params::field("length_ratio", &P::length_ratio)
                   .in(0.05, 1.5)
                   .no_unit()
                   .doc("A child branch's length over its parent's (trunk:branch ratio)")
                   .grouped("shape"))
          .add(params::field("branch_angle", &P::branch_angle_deg)
                   .in(0, 150)
                   .units("deg")
                   .doc("Angle between a child branch and its parent")
                   .grouped("shape"))
          .add(params::field("angle_jitter", &P::angle_jitter_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Random spread of the branch angles")
                   .grouped("shape"))
          .add(params::field("tropism", &P::tropism)
                   .in(-1, 1)
                   .no_unit()
                   .doc("Branches turn up (> 0, cactus arms) or droop (< 0) along their length")
                   .grouped("shape"))
          .add(params::choice("leaf", &P::leaf,
                              {{"none", LeafKind::none},
                               {"broad", LeafKind::broad},
                               {"needle", LeafKind::needle},
                               {"frond", LeafKind::frond},
                               {"paddle", LeafKind::paddle},
                               {"blade", LeafKind::blade}})
                   .doc("Leaf kind: none, broad cards, needle tufts, palm fronds, broad paddle leaves (banana), grass blades")
                   .grouped("leaves"))
          .add(params::field("leaf_size", &P::leaf_size_m)
                   .in(0.005, 12)
                   .units("m")
                   .doc("Length of a leaf, frond, needle tuft or blade")
                   .grouped("leaves"))
          .add(params::field("leaf_length", &P::leaf_length).in(0.2, 40).no_unit().doc("Leaf length over width").grouped("leaves"))
          .add(params::field("leaf_spread", &P::leaf_spread_deg)
                   .in(0, 180)
                   .units("deg")
                   .doc("Angle of leaves from their twig; fronds: their rise above the horizontal at the stem")
                   .grouped("leaves"))
          .add(params::field("leaves_per_twig", &P::leaves_per_twig)
                   .in(0, 64)
                   .doc("Leaves per outermost twig (fronds per palm, blades per tuft)")
                   .grouped("leaves"))
          .add(params::choice("habit", &P::habit, {{"evergreen", Habit::evergreen}, {"deciduous", Habit::deciduous}})
                   .doc("Deciduous plants colour in autumn and are bare in winter")
                   .grouped("leaves"))
          .add(params::field("flowering", &P::flowering).doc("Blossoms in spring").grouped("leaves"))
          .add(params::field("bark", &P::bark).doc("Colour of the wood (of a cactus: its skin), sRGB").grouped("colour"))
          .add(params::field("leaf_colour", &P::leaf_colour).doc("Leaves in summer, sRGB").grouped("colour"))
          .add(params::field("spring_colour", &P::spring_colour).doc("Fresh leaves in spring, sRGB").grouped("colour"))
          .add(params::field("autumn_colour", &P::autumn_colour).doc("Deciduous leaves in autumn, sRGB").grouped("colour"))
          .add(params::field("blossom", &P::blossom).doc("Blossom of flowering species in spring, sRGB").grouped("colour"))
          .add(params::field("max_slope", &P::max_slope_deg)
                   .in(0, 90)
                   .units("deg")
                   .doc("Does not grow on slopes steeper than this")
                   .grouped("species"));
  return table;
}

void Species::validate() const {
  params::validate(*this);
  bool word = !name.empty();
  for (char c : name) word = word && ((c >= 'a' && c <= 'z') || c == '_');
  if (!word) fail("species.name '{}' is not allowed: it must be lower-case letters and _", name);
}

namespace {

constexpr std::string_view table_file = "data/species.toml";

[[noreturn]] void corrupt(const toml::node& node, const std::string& what) {
  throw std::logic_error(fmt::format("{}:{}: {}", table_file, node.source().begin.line, what));
}

/// One [[species]] table, checked row by row. Throws InputError "SOURCE:LINE: ..." naming the key.
Species read_species(const toml::table& entry, std::string_view source) {
  Species species;
  const auto& table = params::table_of<Species>();
  auto bad = [&](const toml::node& node, const std::string& what) { fail("{}:{}: {}", source, node.source().begin.line, what); };
  if (!entry.contains("name")) bad(entry, "a [[species]] needs a name");
  for (const auto& [key, node] : entry) {
    const auto* row = table.find(key.str());
    if (row == nullptr) {
      std::string keys;
      for (const auto& r : table.rows) keys += (keys.empty() ? "" : ", ") + r.key;
      bad(node, fmt::format("[species] {} is not a key: allowed are {}", key.str(), keys));
    }
    const auto value = params::value_of(*row, node);
    if (!value) bad(node, fmt::format("[species] {} has the wrong type", key.str()));
    const std::string problem = params::check(*row, *value);
    if (!problem.empty())
      bad(node, fmt::format("[species] {} = {} is not allowed: it must be {}", key.str(), params::format_value(*value), problem));
    row->set(species, *value);
  }
  try {
    species.validate();
  } catch (const InputError& e) {
    bad(entry, e.what());
  }
  return species;
}

ClimateSpecies read_climate_species(const toml::node& node, const std::map<std::string, int, std::less<>>& known) {
  const auto* entry = node.as_table();
  if (entry == nullptr) corrupt(node, "a climate's plant must be a table { species = NAME, ... }");
  ClimateSpecies plant;
  for (const auto& [key, value] : *entry) {
    const std::string_view k = key.str();
    if (k == "species" && value.is_string()) {
      plant.species = *value.value<std::string>();
    } else if (k == "band" && value.is_array() && value.as_array()->size() == 2) {
      plant.band_low = value.as_array()->at(0).value<double>().value_or(-1.0);
      plant.band_high = value.as_array()->at(1).value<double>().value_or(-1.0);
      if (!(plant.band_low >= 0.0 && plant.band_low < plant.band_high && plant.band_high <= 1.0))
        corrupt(value, "band must be [low, high] with 0 <= low < high <= 1");
    } else if (k == "weight" && value.value<double>()) {
      plant.weight = *value.value<double>();
      if (!(plant.weight > 0.0)) corrupt(value, "weight must be > 0");
    } else if (k == "near_water" && value.is_boolean()) {
      plant.near_water = *value.value<bool>();
    } else if (k == "summer_only" && value.is_boolean()) {
      plant.summer_only = *value.value<bool>();
    } else {
      corrupt(value, fmt::format("unknown or mistyped key '{}' (allowed: species, band, weight, near_water, summer_only)", k));
    }
  }
  if (!known.contains(plant.species)) corrupt(node, fmt::format("unknown species '{}'", plant.species));
  return plant;
}

struct Library {
  std::vector<Species> species;
  std::map<std::string, int, std::less<>> index;
  std::map<std::string, std::vector<ClimateSpecies>, std::less<>> climates;
  std::map<std::string, double, std::less<>> ground_density;
};

Library load_library() {
  toml::table root;
  try {
    root = toml::parse(species_table_text(), table_file);
  } catch (const toml::parse_error& e) {
    throw std::logic_error(fmt::format("{}:{}: {}", table_file, e.source().begin.line, e.description()));
  }
  Library library;
  if (const auto* list = root["species"].as_array()) {
    for (const toml::node& node : *list) {
      const auto* entry = node.as_table();
      if (entry == nullptr) corrupt(node, "[[species]] must be a table");
      Species species;
      try {
        species = read_species(*entry, table_file);
      } catch (const InputError& e) {
        throw std::logic_error(e.what());
      }
      if (library.index.contains(species.name)) corrupt(node, fmt::format("species '{}' twice", species.name));
      library.index.emplace(species.name, static_cast<int>(library.species.size()));
      library.species.push_back(std::move(species));
    }
  }
  if (const auto* climates = root["climate"].as_table()) {
    for (const auto& [name, node] : *climates) {
      const auto* climate = node.as_table();
      if (climate == nullptr) corrupt(node, "[climate.NAME] must be a table");
      std::vector<ClimateSpecies>& plants = library.climates[std::string(name.str())];
      double& ground = library.ground_density[std::string(name.str())];
      for (const auto& [key, value] : *climate) {
        const std::string_view k = key.str();
        if ((k == "trees" || k == "ground") && value.is_array()) {
          const Layer wanted = k == "trees" ? Layer::tree : Layer::ground;
          for (const toml::node& element : *value.as_array()) {
            plants.push_back(read_climate_species(element, library.index));
            if (library.species[library.index.find(plants.back().species)->second].layer != wanted)
              corrupt(element, fmt::format("species '{}' is not of the {} layer", plants.back().species, k == "trees" ? "tree" : "ground"));
          }
        } else if (k == "ground_density" && value.value<double>()) {
          ground = *value.value<double>();
          if (!(ground >= 0.0 && ground <= 1.0)) corrupt(value, "ground_density must be in 0..1");
        } else {
          corrupt(value, fmt::format("unknown or mistyped climate key '{}' (allowed: trees, ground, ground_density)", k));
        }
      }
    }
  }
  for (const auto& [key, node] : root)
    if (key.str() != "species" && key.str() != "climate") corrupt(node, fmt::format("unknown top-level key '{}'", key.str()));
  return library;
}

const Library& library() {
  static const Library loaded = load_library();
  return loaded;
}

}  // namespace

const std::vector<Species>& species_library() {
  return library().species;
}

const Species& species_named(std::string_view name) {
  const auto& index = library().index;
  if (const auto found = index.find(name); found != index.end()) return library().species[found->second];
  std::string names;
  for (const Species& species : library().species) names += (names.empty() ? "" : ", ") + species.name;
  fail("species '{}' is not known: it must be one of {}", name, names);
}

std::vector<Species> read_species_file(std::string_view text, std::string_view source) {
  check_toml_nesting(text, source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    fail("{}:{}: {}", source, e.source().begin.line, e.description());
  }
  std::vector<Species> species;
  for (const auto& [key, node] : root) {
    const auto* list = node.as_array();
    if (key.str() != "species" || list == nullptr || !list->is_array_of_tables())
      fail("{}:{}: '{}' is not allowed here: a species file holds only [[species]] tables", source, node.source().begin.line, key.str());
    for (const toml::node& entry : *list) {
      species.push_back(read_species(*entry.as_table(), source));
      // A user's plant is checked here, before any work, with its file and line (build_tree
      // checks every plant again, the library's too).
      try {
        budget::check(tree_cost(species.back()));
      } catch (const InputError& e) {
        fail("{}:{}: {}", source, entry.source().begin.line, e.what());
      }
    }
  }
  if (species.empty()) fail("{}: no [[species]] table: the file defines no species", source);
  return species;
}

const std::vector<ClimateSpecies>& species_of_climate(std::string_view koppen) {
  static const std::vector<ClimateSpecies> none;
  const auto& climates = library().climates;
  const auto found = climates.find(koppen);
  return found == climates.end() ? none : found->second;
}

double ground_density_of_climate(std::string_view koppen) {
  const auto& densities = library().ground_density;
  const auto found = densities.find(koppen);
  return found == densities.end() ? 0.0 : found->second;
}

}  // namespace sansui::vegetation
