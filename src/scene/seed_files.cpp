#include "scene/seed_files.hpp"

#include <utility>

#include <fmt/format.h>

#include "core/error.hpp"

namespace sansui::scene {

SeedContours parse_seeds(std::string_view text, io::SeedFormat format, std::string_view source, double metres_per_unit) {
  io::SeedOutlines outlines = io::read_seed_outlines(text, format, source, metres_per_unit);
  SeedContours seeds{{}, std::move(outlines.notes)};
  for (io::SeedOutline& outline : outlines.outlines) {
    contour::SeedContour seed = contour::normalise_seed(std::move(outline.ring), outline.closed, outline.name);
    seeds.rings.push_back(std::move(seed.ring));
    seeds.notes.insert(seeds.notes.end(), seed.notes.begin(), seed.notes.end());
  }
  contour::check_seeds_apart(seeds.rings, source);
  if (seeds.rings.size() > 1)
    seeds.notes.push_back(fmt::format("{}: {} seed contours: one mountain from each, grown side by side", source, seeds.rings.size()));
  return seeds;
}

contour::SeedContour parse_seed(std::string_view text, io::SeedFormat format, std::string_view source, double metres_per_unit) {
  SeedContours seeds = parse_seeds(text, format, source, metres_per_unit);
  if (seeds.rings.size() != 1)
    fail("{}: it holds {} seed contours where one is expected: give a file with a single polygon", source, seeds.rings.size());
  return {std::move(seeds.rings.front()), std::move(seeds.notes)};
}

}  // namespace sansui::scene
