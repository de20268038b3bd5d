// The plant-instance reader (io/plant_instances.hpp) against thousands of mutated CSV and JSON
// files: every one ends in a placement or an InputError, never a crash or another exception.
#include <fstream>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/plant_instances.hpp"
#include "scene/plants.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/fuzz/mutate.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

vegetation::Placement sample() {
  vegetation::Placement placement;
  for (int i = 0; i < 6; ++i) {
    vegetation::Instance plant;
    plant.x_m = 10.5f * static_cast<float>(i);
    plant.y_m = -3.25f * static_cast<float>(i);
    plant.height_m = 100.0f + static_cast<float>(i);
    plant.scale = 0.9f + 0.05f * static_cast<float>(i);
    plant.rotation_rad = 0.5f * static_cast<float>(i);
    plant.species = static_cast<std::uint16_t>(i % 3);
    plant.variant = static_cast<std::uint16_t>(i % 4);
    (i % 2 == 0 ? placement.trees : placement.ground).push_back(plant);
  }
  return placement;
}

TEST(PlantInstancesFuzz, MutatedListsEndInPlantsOrAClearError) {
  TempDir dir("plants-fuzz");
  int accepted = 0, runs = 0;
  for (const char* extension : {".csv", ".json"}) {
    const auto original = dir / (std::string("plants") + extension);
    scene::write_plant_instances(original, sample());
    const std::string seed = read_text(original);
    const auto scratch = dir / (std::string("mutated") + extension);
    for (std::uint64_t n = 0; n < 1500; ++n) {
      std::string text = mutate(seed, n);
      if (n % 3 == 0) text = mutate(text, n + 100000);
      std::ofstream(scratch, std::ios::binary | std::ios::trunc) << text;
      try {
        (void)scene::read_plant_instances(scratch);
        ++accepted;
      } catch (const InputError&) {
      } catch (const std::exception& e) {
        FAIL() << "not an InputError: " << e.what() << "\ninput:\n" << text;
      }
      ++runs;
    }
  }
  EXPECT_EQ(runs, 3000);
  EXPECT_GT(accepted, 30);  // some mutations still read (the reader is strict): it was really exercised
}

}  // namespace
}  // namespace sansui::test
