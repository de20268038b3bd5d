#include "tests/fuzz/fuzz_readers.hpp"

#include <array>
#include <fstream>
#include <stdexcept>

#include <sys/inotify.h>
#include <unistd.h>

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

/// The folder around a VRT input: SCRATCH/case holds the input beside rasters (tile.asc,
/// sub/tile.asc); SCRATCH/bait/secret.asc lies outside it, and no input may make Sansui open it.
void lay_out_rasters(const std::filesystem::path& scratch) {
  if (std::filesystem::exists(scratch / "bait" / "secret.asc")) return;
  const std::string grid = "ncols 4\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 10\n1 2 3 4\n5 6 7 8\n9 8 7 6\n5 4 3 2\n";
  std::filesystem::create_directories(scratch / "bait");
  std::filesystem::create_directories(scratch / "case" / "sub");
  write_bytes(scratch / "bait" / "secret.asc", grid);
  write_bytes(scratch / "case" / "tile.asc", grid);
  write_bytes(scratch / "case" / "sub" / "tile.asc", grid);
}

/// A DEM's VRT (or, by its first byte, the same bytes under another GDAL extension), read with
/// an eye on the bait outside its folder: any open of it (inotify) is a bug, as a connection
/// would be (the fuzz target forbids sockets outright: fuzz_target.cpp).
void read_gdal_vrt(std::string_view bytes, const std::filesystem::path& file) {
  const std::filesystem::path scratch = file.parent_path();
  lay_out_rasters(scratch);
  std::filesystem::path path = scratch / "case" / "dem.vrt";
  static constexpr std::array<const char*, 4> other = {".asc", ".img", ".bil", ".grd"};
  if (!bytes.empty() && static_cast<unsigned char>(bytes.front()) % 8 == 7)
    path.replace_extension(other[static_cast<unsigned char>(bytes.back()) % other.size()]);
  write_bytes(path, bytes);
  const int watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (watch < 0 || ::inotify_add_watch(watch, (scratch / "bait").c_str(), IN_OPEN | IN_ACCESS) < 0)
    throw std::runtime_error("fuzz harness: inotify");
  const auto check_bait = [&] {
    std::array<char, 4096> events{};
    const bool opened = ::read(watch, events.data(), events.size()) > 0;
    ::close(watch);
    if (opened) throw std::logic_error("a raster made Sansui open a file outside its folder");
  };
  try {
    (void)io::read_heightmap(path);
  } catch (const InputError&) {
    check_bait();
    throw;
  }
  check_bait();
}

/// A recipe made small enough to run in a moment: a world of at most 65 samples (129 for a tiled
/// one, in tiles of 33 or 65), its outputs a heightmap in the scratch folder (and, for a tiled
/// world, its flow map and rivers), confined there.
scene::Recipe small_recipe(std::string_view bytes, const std::filesystem::path& file) {
  std::filesystem::path path = file;
  if (looks_like_json(bytes)) {
    path = file.parent_path() / "input.r32.json";
    write_bytes(path, bytes);
  }
  scene::Recipe recipe = scene::load_recipe(path).recipe;
  recipe.world.size = recipe.world.size > 33 ? 65 : 33;
  recipe.world.world_size.reset();
  recipe.world.tile.reset();
  recipe.outputs.clear();
  recipe.output_rules.confined_to = file.parent_path();
  return recipe;
}

/// A graph recipe, run: every node kind on a small world, with its files and masks.
void run_graph(std::string_view bytes, const std::filesystem::path& file) {
  scene::Recipe recipe = small_recipe(bytes, file);
  if (recipe.nodes.empty() || recipe.world.tiled) return;  // the recipe target checks the rest
  scene::Output heights;
  heights.file = (file.parent_path() / "out.r32").string();
  recipe.outputs.push_back(heights);
  (void)scene::run_recipe(recipe, {}, quiet_context());
}

/// A tiled world, run in one process: a world of 129 samples in tiles, its heights, flow and rivers.
void run_tiled_world(std::string_view bytes, const std::filesystem::path& file) {
  scene::Recipe recipe = small_recipe(bytes, file);
  recipe.world.tiled = true;
  recipe.world.world_size = 129;
  recipe.world.tile_size = recipe.world.tile_size > 33 ? 65 : 33;
  recipe.world.lod = 0;
  for (const auto& [name, kind] : {std::pair{"h.vrt", scene::OutputKind::heightmap}, std::pair{"f.vrt", scene::OutputKind::flow_map},
                                   std::pair{"r.geojson", scene::OutputKind::rivers}}) {
    scene::Output output;
    output.file = (file.parent_path() / name).string();
    output.kind = kind;
    recipe.outputs.push_back(output);
  }
  (void)scene::run_recipe(recipe, {}, quiet_context());
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
      {"gdal_vrt", "dem.vrt", read_gdal_vrt, {"render", "INPUT", "--width", "64", "--height", "48", "-o", "OUTPUT.png"}},
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
      {"graph", "input.toml", [](std::string_view b, P f) { run_graph(b, f); }, {}},
      {"tiled_world", "input.toml", [](std::string_view b, P f) { run_tiled_world(b, f); }, {}},
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
