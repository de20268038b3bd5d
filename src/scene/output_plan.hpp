// The output plan: every file a run of a recipe would write (each output, its sidecar, and the
// files some kinds write beside it), checked as a whole before any work (issue 30). No two are
// the same file; none is an input, an input's sidecar or the recipe file itself; none has a
// control character in its name; none is a device, FIFO, socket or (unless allowed) a symbolic
// link; and a recipe read from a file writes only inside its folder (Recipe::output_rules).
// A refusal is one InputError naming the outputs; nothing is written.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/recipe.hpp"

namespace sansui::scene {

/// What a planned file is to its output.
enum class PlannedRole {
  output,       ///< the output itself
  sidecar,      ///< NAME.EXT.json, the recipe that rebuilds it (io::sidecar_path)
  envi_header,  ///< NAME.r32.hdr beside a raw heightmap (io::envi_header_path)
  material,     ///< STEM.mtl beside a textured OBJ mesh
  texture,      ///< STEM_basecolor.png beside a textured OBJ mesh
  world_file,   ///< NAME.pgw beside a 16-bit PNG heightmap (io::png_world_file_path)
  aux_xml,      ///< NAME.png.aux.xml beside a 16-bit PNG heightmap (io::png_aux_xml_path)
};

struct PlannedFile {
  std::filesystem::path path;  ///< as the run writes it (relative names resolved against the recipe's base_dir)
  std::size_t output = 0;      ///< index into Recipe::outputs
  PlannedRole role = PlannedRole::output;
};

struct OutputPlan {
  std::vector<PlannedFile> files;     ///< in the order of the outputs: each output, then its sidecar and extras
  std::vector<std::string> warnings;  ///< names that differ only in case, one line each
};

/// The names alone, before any message quotes them: throws InputError for an output name with a
/// control character (a NUL would cut it: "a.png\0.tif" would be written as a.png) or, when
/// `recipe.output_rules.confined_to` is set, for one that leaves that directory.
void check_output_names(const Recipe& recipe);

/// The files the run of `recipe` writes, checked as a whole (see above). Needs the outputs'
/// kinds known (check_outputs checks them first). Throws InputError naming the first problem.
OutputPlan plan_outputs(const Recipe& recipe);

}  // namespace sansui::scene
