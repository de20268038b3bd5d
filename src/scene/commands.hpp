// The commands of the CLI as data: which source each runs, which recipe sections its options
// come from (and the prefix of their option names), its positional arguments and its output
// options. apps/cli builds its subcommands from this list, so a command is its recipe and
// `--save-recipe` writes exactly what the command line said.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/recipe.hpp"

namespace sansui::scene {

/// The options of one recipe section, named "--" + prefix + key.
struct SectionUse {
  std::string section;
  std::string prefix;
  std::string group;  ///< heading in --help
};

/// A positional argument that sets one recipe key (a file name).
struct Positional {
  std::string name;  ///< shown in --help
  std::string key;   ///< "file.path"
};

/// An output option: each file it names becomes an output of this kind (unset: by extension).
struct OutputOption {
  std::string names;  ///< "-o,--out"
  std::optional<OutputKind> kind;
  bool repeatable = false;
  std::string help;
};

struct CommandSpec {
  std::string name;
  std::string help;
  SourceKind source = SourceKind::none;
  std::vector<SectionUse> sections;
  bool stage_step = false;  ///< one [[shape]] stage step, its options unprefixed
  std::vector<Positional> positionals;
  std::vector<OutputOption> outputs;
  std::vector<Output> fixed_outputs;  ///< outputs every run has (compare: the printed table)
  /// `--erode`: an erode step (with stage_step, the stage step is one unless `--no-erode`: `--stage` is then
  /// the erosion time), its options unprefixed.
  bool erode_option = false;
};

/// terrain, render, contour, compare, solid, subdivide, tree.
const std::vector<CommandSpec>& command_specs();

}  // namespace sansui::scene
