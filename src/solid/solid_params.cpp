// Parameter tables of the solid-texture subsystem (see core/params.hpp).
#include "core/params.hpp"
#include "solid/field.hpp"
#include "solid/rock_albedo.hpp"
#include "solid/texture.hpp"

namespace sansui::solid {

const params::Table<FieldParams>& parameter_table(const FieldParams*) {
  using P = FieldParams;
  static const auto table = params::Table<P>("solid_field", "The 3-D random fractal field D (Okada, Taga, Yokoi and Toriwaki 1990)")
                                .add(params::field("seed", &P::seed).doc("Random seed: the same seed gives the same field, bit for bit"))
                                .add(params::field("levels", &P::levels)
                                         .in(1, max_levels)
                                         .alias("-R")
                                         .doc("Recursion levels R: the lattice is {0..2^R}^3 (Types I and II as memory allows)"))
                                .add(params::field("beta", &P::beta)
                                         .at_most(100)
                                         .above(0)
                                         .no_unit()
                                         .doc("Decay constant: level n displaces by g exp(-(n-1) beta); larger is smoother"))
                                .add(params::field("corners", &P::corners).no_unit().doc("The 8 corner values, corner x + 2y + 4z"));
  return table;
}

void FieldParams::validate() const {
  params::validate(*this);
}

std::vector<std::string> rock_texture_names() {
  std::vector<std::string> names{"none"};
  for (const auto& name : texture_names())
    if (name != "field") names.push_back(name);
  return names;
}

const params::Table<RockParams>& parameter_table(const RockParams*) {
  using P = RockParams;
  static const auto table =
      params::Table<P>("rock", "Rock on cliffs: a solid texture evaluated at every surface point (Okada et al. 1990, Type IV)")
          .add(params::choice("texture", &P::texture, rock_texture_names())
                   .alias("--rock")
                   .doc("Cliffs and bare rock show this solid texture (strata: sedimentary beds); none: the palette's cliff colour"))
          .add(params::field("seed", &P::seed).doc("Seed of the field and of the beds"))
          .add(params::field("levels", &P::levels).in(1, max_levels).doc("Field levels R: 2^R cells along the terrain's largest extent"))
          .add(params::field("r2", &P::r2).at_most(30).at_least(0).doc("Type IV's array levels (at most `levels`)"))
          .add(params::field("beta", &P::beta).at_most(100).above(0).no_unit().doc("Field decay constant beta"))
          .add(params::field("field_cell", &P::field_cell_m)
                   .at_most(1e7)
                   .at_least(0)
                   .units("m")
                   .doc("Metres per field cell, anchoring the field to world coordinates so tiles join; 0: fit the terrain"))
          .add(params::field("scale", &P::texture_size_m)
                   .at_most(1e7)
                   .above(0)
                   .units("m")
                   .doc("Metres one texture block spans: strata beds are about 3 % of it"));
  return table;
}

}  // namespace sansui::solid
