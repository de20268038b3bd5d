// The file source: a heightmap read from disk (io/heightmap_io.hpp).
#include "io/heightmap_io.hpp"
#include "scene/sources.hpp"

namespace sansui::scene::detail {

Heightfield read_heightmap_with_notes(const std::filesystem::path& path, const Context& context, const io::HeightmapReadOptions& options) {
  io::HeightmapAssumptions assumed;
  Heightfield heights = io::read_heightmap(path, options, &assumed);
  if (assumed.any()) context.note(io::assumptions_note(path, assumed));
  for (const auto& note : assumed.notes) context.note(note);  // non-square cells resampled
  return heights;
}

Produced run_file_source(Recipe& recipe, const Context& context) {
  io::HeightmapReadOptions options;
  options.cell_size_m = recipe.file.cell_m;
  if (recipe.file.range_m) options.range = io::HeightRange{(*recipe.file.range_m)[0], (*recipe.file.range_m)[1]};
  Produced produced;
  const auto path = resolve(recipe, recipe.file.path);
  produced.heights = read_heightmap_with_notes(path, context, options);
  return produced;
}

}  // namespace sansui::scene::detail
