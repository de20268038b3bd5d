#include "tests/fuzz/fuzz_readers.hpp"

#include <fstream>
#include <stdexcept>

#include "apps/cli/run_cli.hpp"
#include "core/error.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/heightmap_io.hpp"
#include "io/hypsometry_csv.hpp"
#include "io/image_io.hpp"
#include "io/mesh_io.hpp"
#include "io/plant_instances.hpp"
#include "io/sketch_geojson.hpp"
#include "io/vertex_locks.hpp"
#include "scene/contour_geojson.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/recipe_file.hpp"
#include "scene/seed_files.hpp"
#include "tests/fuzz/structured_mutator.hpp"
#include "vegetation/placement.hpp"
#include "vegetation/species.hpp"
#include "vegetation/tree_mesh.hpp"

namespace sansui::test {
namespace {

void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("fuzz harness: cannot write " + path.string());
}

/// The file part of an input with an optional sidecar (see sidecar_separator).
std::string_view file_part(std::string_view bytes) {
  const auto at = bytes.find(sidecar_separator);
  return at == std::string_view::npos ? bytes : bytes.substr(at + sidecar_separator.size());
}

void read_heightmap_input(std::string_view, const std::filesystem::path& file) {
  (void)io::read_heightmap(file);
}

void read_seed(std::string_view bytes, io::SeedFormat format) {
  (void)scene::parse_seed(bytes, format, "fuzz-seed", 1.0);
}

/// Vertex locks come from OBJ, .glb or .gltf files: the input's first bytes choose which.
void read_vertex_locks(std::string_view bytes, const std::filesystem::path& file) {
  const auto first = bytes.find_first_not_of(" \t\r\n");
  const bool glb = bytes.starts_with("glTF"), gltf = !glb && first != std::string_view::npos && bytes[first] == '{';
  std::filesystem::path path = file;
  if (glb || gltf) {
    path.replace_extension(glb ? ".glb" : ".gltf");
    write_bytes(path, bytes);
  }
  (void)io::read_locked_positions(path);
}

void read_argv(std::string_view bytes) {
  std::vector<std::string> arguments = split_arguments(bytes);
  arguments.insert(arguments.begin(), "sansui");
  std::vector<char*> argv;
  argv.reserve(arguments.size() + 1);
  for (auto& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  const int code = cli::run_cli(static_cast<int>(arguments.size()), argv.data(), cli::RecipeMode::check_only);
  if (code == 1) throw std::logic_error("internal error from the option parser");
}

/// A recipe, loaded and checked but not run: a sidecar when it starts with '{' (written beside
/// `file` with a sidecar's name), else a scene file (`file`).
void read_recipe(std::string_view bytes, const std::filesystem::path& file) {
  std::filesystem::path path = file;
  if (looks_like_json(bytes)) {
    path = file.parent_path() / "input.r32.json";
    write_bytes(path, bytes);
  }
  scene::check_recipe(scene::load_recipe(path).recipe);
}

/// Every species of a species file (the first four) built into its tree mesh, in one of its
/// shapes, seasons and levels of detail, chosen by the input's length.
void build_species_trees(std::string_view bytes) {
  const std::vector<vegetation::Species> species = vegetation::read_species_file(bytes, "fuzz-species.toml");
  for (std::size_t i = 0; i < species.size() && i < 4; ++i) {
    const std::size_t n = bytes.size() + i;
    const vegetation::TreeOptions options{static_cast<Season>(n % 4), n % 3 == 0,
                                          n % 5 == 0 ? vegetation::Detail::simplified : vegetation::Detail::full};
    (void)vegetation::build_tree(
        species[i], vegetation::variant_seed(static_cast<int>(i), static_cast<int>(n % vegetation::variants_per_species)), options);
  }
}

}  // namespace

const std::vector<FuzzReader>& fuzz_readers() {
  using P = const std::filesystem::path&;
  static const std::vector<FuzzReader> readers{
      {"png16", "input.png", [](std::string_view b, P f) { read_heightmap_input(b, f); }, {"compare", "INPUT", "INPUT"}},
      {"raw16", "input.raw", [](std::string_view b, P f) { read_heightmap_input(b, f); }, {"compare", "INPUT", "INPUT"}},
      {"r32", "input.r32", [](std::string_view b, P f) { read_heightmap_input(b, f); }, {"compare", "INPUT", "INPUT"}},
      {"geotiff", "input.tif", [](std::string_view b, P f) { read_heightmap_input(b, f); }, {"compare", "INPUT", "INPUT"}},
      {"gdal_asc", "input.asc", [](std::string_view b, P f) { read_heightmap_input(b, f); }, {"compare", "INPUT", "INPUT"}},
      {"image_png", "input.png", [](std::string_view, P f) { (void)io::read_png(f); }, {}},
      {"sidecar",
       "input.r32.json",
       [](std::string_view, P f) { scene::check_recipe(scene::load_recipe(f).recipe); },
       {"run", "INPUT", "--explain"}},
      {"scene_toml",
       "",
       [](std::string_view b, P) { scene::check_recipe(scene::parse_recipe_toml(b, "fuzz.toml", ".").recipe); },
       {"run", "INPUT", "--explain"}},
      {"seed_csv",
       "input.csv",  // named so that the binary, which goes by the extension, reads it as this format
       [](std::string_view b, P) { read_seed(b, io::SeedFormat::csv); },
       {"contour", "INPUT", "--max-levels", "3", "--dem-size", "33", "--dem", "OUTPUT.r32"}},
      {"seed_geojson",
       "input.geojson",  // named so that the binary, which goes by the extension, reads it as this format
       [](std::string_view b, P) { read_seed(b, io::SeedFormat::geojson); },
       {"contour", "INPUT", "--max-levels", "3", "--dem-size", "33", "--dem", "OUTPUT.r32"}},
      {"seed_svg",
       "input.svg",  // named so that the binary, which goes by the extension, reads it as this format
       [](std::string_view b, P) { read_seed(b, io::SeedFormat::svg); },
       {"contour", "INPUT", "--max-levels", "3", "--dem-size", "33", "--dem", "OUTPUT.r32"}},
      {"hypsometry", "", [](std::string_view b, P) { (void)io::parse_hypsometry(b, "fuzz-hypsometry.csv"); }, {}},
      {"contours_geojson", "", [](std::string_view b, P) { (void)scene::contours_from_geojson(b, "fuzz-contours.geojson"); }, {}},
      {"obj", "input.obj", [](std::string_view, P f) { (void)io::read_mesh(f); }, {"subdivide", "INPUT", "-o", "OUTPUT.glb"}},
      {"glb", "input.glb", [](std::string_view, P f) { (void)io::read_mesh(f); }, {"subdivide", "INPUT", "-o", "OUTPUT.glb"}},
      {"gltf", "input.gltf", [](std::string_view, P f) { (void)io::read_mesh(f); }, {"subdivide", "INPUT", "-o", "OUTPUT.glb"}},
      {"vertex_locks", "input.obj", read_vertex_locks, {"subdivide", "INPUT", "-o", "OUTPUT.glb"}},
      {"contour_map",
       "input.geojson",
       [](std::string_view b, P) { (void)io::parse_contour_map(b, "fuzz-map.geojson", "", true); },
       {"contour-dem", "INPUT", "--dem-size", "33", "--dem", "OUTPUT.r32"}},
      {"species",
       "input.toml",
       [](std::string_view b, P) { (void)vegetation::read_species_file(b, "fuzz-species.toml"); },
       {"tree", "--species-file", "INPUT", "-o", "OUTPUT.glb"}},
      {"sketch",
       "input.geojson",
       [](std::string_view b, P) { (void)io::parse_sketch_geojson(b, "fuzz-sketch.geojson"); },
       {"subdivide", "--sketch", "INPUT", "--steps", "1", "-o", "OUTPUT.glb"}},
      {"plants_csv", "input.csv", [](std::string_view, P f) { (void)scene::read_plant_instances(f); }, {}},
      {"plants_json", "input.json", [](std::string_view, P f) { (void)scene::read_plant_instances(f); }, {}},
      {"argv", "", [](std::string_view b, P) { read_argv(b); }, {}},
      // Structured targets (fuzz_structured.cpp): no command, as a recipe may be either format
      // and `sansui tree` builds one species only (the scene_toml, sidecar and species readers
      // replay through the binary).
      {"recipe", "input.toml", [](std::string_view b, P f) { read_recipe(b, f); }, {}},
      {"species_tree", "", [](std::string_view b, P) { build_species_trees(b); }, {}},
  };
  return readers;
}

const FuzzReader& fuzz_reader(std::string_view name) {
  for (const auto& reader : fuzz_readers())
    if (reader.name == name) return reader;
  throw std::logic_error("no fuzz reader named " + std::string(name));
}

std::filesystem::path write_fuzz_input(const FuzzReader& reader, std::string_view bytes, const std::filesystem::path& scratch) {
  auto file = scratch / (reader.file_name.empty() ? std::string("input.txt") : std::string(reader.file_name));
  std::error_code ignored;
  std::filesystem::remove(io::sidecar_path(file), ignored);
  const auto at = bytes.find(sidecar_separator);
  if (at != std::string_view::npos && !reader.file_name.empty()) write_bytes(io::sidecar_path(file), bytes.substr(0, at));
  write_bytes(file, file_part(bytes));
  return file;
}

bool read_fuzz_input(const FuzzReader& reader, std::string_view bytes, const std::filesystem::path& scratch, std::string* refusal) {
  const auto file = reader.file_name.empty() ? std::filesystem::path() : write_fuzz_input(reader, bytes, scratch);
  try {
    reader.read(file_part(bytes), file);
    return true;
  } catch (const InputError& e) {
    if (refusal) *refusal = e.what();
    return false;
  }
}

std::vector<std::string> split_arguments(std::string_view bytes) {
  std::vector<std::string> arguments;
  while (!bytes.empty() && arguments.size() < 64) {
    const auto end = bytes.find('\0');
    arguments.emplace_back(bytes.substr(0, end));
    if (end == std::string_view::npos) break;
    bytes.remove_prefix(end + 1);
  }
  return arguments;
}

}  // namespace sansui::test
