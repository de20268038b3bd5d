// The species library (data/species.toml): every species valid, every climate of Table 1 with
// its plants, the layers right, and bad species values rejected naming the key.
#include "vegetation/species.hpp"

#include <set>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"

namespace sansui::vegetation {
namespace {

using testing::HasSubstr;

TEST(Species, TheLibraryHoldsTable1sPlantsAndEachIsValid) {
  std::set<std::string> names;
  for (const Species& species : species_library()) {
    EXPECT_NO_THROW(species.validate()) << species.name;
    names.insert(species.name);
  }
  // Table 1 of seed 003: palm, banana, mangrove; baobab, acacia; cactus, date palm; short grass;
  // olive, cork oak, laurel; oak, maple, pine, sugi; beech, chestnut, kashiwa; spruce, fir, birch; moss.
  for (const char* name :
       {"coconut_palm", "banana", "mangrove", "baobab", "acacia", "saguaro",  "date_palm", "short_grass", "olive", "cork_oak", "laurel",
        "oak",          "maple",  "pine",     "sugi",   "beech",  "chestnut", "kashiwa",   "spruce",      "fir",   "birch",    "moss"})
    EXPECT_TRUE(names.contains(name)) << name;
}

TEST(Species, EveryClimateButTheIceCapHasPlantsAndTheTreeClimatesAboutFourTrees) {
  for (const char* koppen : {"Af", "Am", "Aw", "BW", "BS", "Cs", "Cw", "Cfa", "Cfb", "Cfc", "Df", "Dw", "ET"}) {
    int trees = 0, ground = 0;
    for (const ClimateSpecies& plant : species_of_climate(koppen)) {
      const Species& species = species_named(plant.species);
      (species.layer == Layer::tree ? trees : ground) += 1;
      EXPECT_LT(plant.band_low, plant.band_high);
    }
    EXPECT_GT(trees + ground, 0) << koppen;
    EXPECT_LE(trees, 4) << koppen;
  }
  EXPECT_TRUE(species_of_climate("EF").empty());
  EXPECT_EQ(ground_density_of_climate("EF"), 0.0);
}

TEST(Species, TundraAndSteppeHaveNoTreesAndTheDesertOnlyCactiAwayFromWater) {
  for (const char* koppen : {"ET", "BS", "EF"})
    for (const ClimateSpecies& plant : species_of_climate(koppen)) EXPECT_EQ(species_named(plant.species).layer, Layer::ground) << koppen;
  for (const ClimateSpecies& plant : species_of_climate("BW"))
    if (!plant.near_water) {
      EXPECT_EQ(species_named(plant.species).form, Form::succulent) << plant.species;
    }
  for (const ClimateSpecies& plant : species_of_climate("ET")) EXPECT_TRUE(plant.summer_only);
}

TEST(Species, AnUnknownNameListsTheKnownOnes) {
  try {
    (void)species_named("unicorn_tree");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("'unicorn_tree'"));
    EXPECT_THAT(e.what(), HasSubstr("spruce"));
  }
}

TEST(Species, BadValuesAreRejectedNamingTheKey) {
  Species deep = species_named("oak");
  deep.depth = 9;
  EXPECT_THROW(deep.validate(), InputError);
  try {
    deep.validate();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("species.depth"));
  }
  Species angle = species_named("oak");
  angle.branch_angle_deg = 200;
  EXPECT_THROW(angle.validate(), InputError);
  Species name = species_named("oak");
  name.name = "Oak Tree";
  EXPECT_THROW(name.validate(), InputError);
}

}  // namespace
}  // namespace sansui::vegetation
