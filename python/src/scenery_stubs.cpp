// The docstrings and type stubs of the scene-parts functions (scenery.cpp): parameter_tables,
// scenery, tree, terrain_mesh. One text for both, so help() and editors say the same.
#include <fmt/format.h>

#include "scene/plants.hpp"
#include "scene/scenery.hpp"
#include "signatures.hpp"
#include "vegetation/placement.hpp"

namespace sansui::python {

namespace {

std::string section_names() {
  std::string names;
  for (const scene::Section* section : scene::scenery_sections()) names += (names.empty() ? "" : ", ") + section->name;
  return names;
}

std::string parameter_tables_doc() {
  return fmt::format(
      R"(parameter_tables() -> dict

The parameter tables as data, to build widgets from: "world", "node.KIND" for every node kind,
and each recipe section a scene's look reads ({}).

Each value is {{"title": str, "rows": [row, ...]}}; a row is a dict: key (within its table),
kind ("flag", "integer", "real", "text", "choice", "path" or "reals"), unit, help, group,
optional, default (the Python value; None: unset), default_text (as `sansui params` shows it),
allowed (in words), min, max (None: no bound), min_exclusive, max_exclusive, choices (list),
count ([min, max] numbers of a "reals" row, else None). Internal and superseded keys are left out.
)",
      section_names());
}

std::string scenery_doc() {
  return fmt::format(
      R"(scenery(recipe, progress=None) -> dict

Everything a 3-D scene needs for the recipe's terrain, made as `sansui run` makes its outputs.
recipe: a scene file's path, a dict shaped like one, or a sansui.Recipe. The arrays are the
library's own buffers (no copy); grids are (n, n), row 0 north. Returns a dict:

    heights     float32 (n, n): metres, the same bytes as Recipe.heights()
    cell        float: metres between samples
    sea_level   float: metres, the sea level the picture uses (no sea: 1 m below the lowest point)
    sea         bool: whether the scene has a sea (render.sea)
    origin      (east, north): world coordinates of sample (0, 0) in metres (add them to the frame
                below for the outputs' GeoJSON coordinates)
    colour      uint8 (n, n, 3): the ground's band colours, sRGB, one pixel a sample (the mesh
                outputs' base colour); a view of an RGBA buffer
    splat       uint8 (n, n, 4): the splat map output's weights, channels sand, grass, rock, snow;
                they sum to 255 at every sample
    water       float32 (n, n): metres of water over the ground, 0 where dry: the sea, and lakes
                and rivers where the scene draws them (render.draw_water; unset: eroded terrain)
    plants      structured array, one row a plant, as the renderer draws them (trees first, then
                the ground layer, which is left out past {:g} M ground cells):
                x, y, z (float32, metres): x east of sample (0, 0), y north of it (negative on
                the terrain: row j lies at y = -j * cell), z the ground's height under the plant;
                species (uint16, index into "species"), variant (uint16, 0..{}), scale (float32,
                times the species' typical size), rotation (float32, radians, counter-clockwise
                about z seen from above), layer (uint8: 0 tree, 1 ground plant)
    species     list[str]: the species' names
    season      str: the scene's season (give it to tree())
    plant_snow  bool: whether the scene's evergreens carry snow (give it to tree(snow=...))

progress: a callable (stage: str, fraction: float); an exception it raises cancels.
)",
      scene::max_drawn_ground_cells / 1e6, vegetation::variants_per_species - 1);
}

std::string tree_doc() {
  return fmt::format(
      R"(tree(species, variant=None, season=None, seed=None, *, snow=None) -> dict

One plant's mesh, as `sansui tree` builds it: one mesh per (species, variant) of scenery()'s
plants, to instance (scaled by each plant's scale, turned by its rotation about z).

    species  a name of scenery()["species"] (docs/species.md)
    variant  0..{}: the plants' variant (None: 0, or the seed's)
    seed     instead of variant, `sansui tree --seed` (its variant is seed % {})
    season   spring, summer, autumn or winter (default: the default date's, summer)
    snow     evergreens carry snow in winter (default True, as `sansui tree`; give
             scenery()["plant_snow"] for a scene's plants)

Returns {{"vertices": float32 (k, 3), metres, x east, y north, z up, the base at (0, 0, 0), at the
species' typical height; "faces": uint32 (m, 3); "normals": float32 (k, 3); "colours": float32
(k, 3), sRGB 0..1 per vertex}}. The same arguments give the same bytes.
)",
      vegetation::variants_per_species - 1, vegetation::variants_per_species);
}

const char* terrain_mesh_doc = R"(terrain_mesh(heights, world=None, *, cell=None, progress=None) -> (vertices, faces)

The mesh outputs' triangulation of a heightfield: one vertex a sample, two triangles a cell,
counter-clockwise seen from above.

    vertices  float32 (n * n, 3), metres: x east of sample (0, 0), y north (row j at
              y = -j * cell), z the height; vertex j * n + i is sample (row j, column i)
    faces     uint32 (2 (n - 1)^2, 3)

cell: metres between samples (default: the world's, else that of the world the array was made
on, else 10). The mesh output has no parameter table of its own: the world's cell is its key.
)";

}  // namespace

const std::map<std::string, std::string>& scenery_docstrings() {
  static const std::map<std::string, std::string> docs{
      {"parameter_tables", parameter_tables_doc()},
      {"scenery", scenery_doc()},
      {"tree", tree_doc()},
      {"terrain_mesh", terrain_mesh_doc},
  };
  return docs;
}

std::string scenery_stubs() {
  const auto& docs = scenery_docstrings();
  // A function's body: its docstring, indented (blank lines left empty), then `...`.
  const auto body = [&](const std::string& name) {
    const std::string doc = "\"\"\"" + docs.at(name) + "\"\"\"\n";
    std::string text;
    for (std::size_t start = 0, end = 0; start < doc.size(); start = end + 1) {
      end = doc.find('\n', start);
      const std::string line = doc.substr(start, end - start);
      text += (line.empty() ? "" : "    " + line) + "\n";
    }
    return text + "    ...\n\n";
  };
  return "def parameter_tables() -> Dict[str, Dict[str, Any]]:\n" + body("parameter_tables") +
         "def scenery(recipe: RecipeSource, progress: Progress = None) -> Dict[str, Any]:\n" + body("scenery") +
         "def tree(species: str, variant: Optional[int] = None, season: Optional[Literal[\"spring\", \"summer\", \"autumn\", "
         "\"winter\"]] = None,\n         seed: Optional[int] = None, *, snow: Optional[bool] = None) -> Dict[str, npt.NDArray[Any]]:\n" +
         body("tree") +
         "def terrain_mesh(heights: ArrayLike, world: Optional[World] = None, *, cell: Optional[float] = None,\n"
         "                 progress: Progress = None) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.uint32]]:\n" +
         body("terrain_mesh");
}

}  // namespace sansui::python
