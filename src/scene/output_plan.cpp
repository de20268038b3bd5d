#include "scene/output_plan.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>

#include <sys/stat.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/envi_header.hpp"
#include "io/extension.hpp"
#include "io/heightmap_io.hpp"
#include "io/png_georeference.hpp"
#include "scene/node_kinds.hpp"
#include "scene/recipe_file.hpp"
#include "scene/sources.hpp"

namespace sansui::scene {
namespace {

/// A name as a message shows it: control bytes escaped (\x00), so that a NUL neither cuts the
/// message nor hides the rest of the name.
std::string escaped_name(std::string_view name) {
  std::string out;
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f)
      out += fmt::format("\\x{:02x}", byte);
    else
      out += c;
  }
  return out;
}

std::filesystem::path absolute_normal(const std::filesystem::path& path) {
  std::filesystem::path normal = std::filesystem::absolute(path).lexically_normal();
  if (normal.has_relative_path() && normal.filename().empty()) normal = normal.parent_path();  // "dir/" -> "dir"
  return normal;
}

/// `file` lies in `folder` or below (both absolute and normal): lexically, no link followed.
bool lies_inside(const std::filesystem::path& file, const std::filesystem::path& folder) {
  const std::filesystem::path relative = file.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != ".." && relative != ".";
}

/// The files an output writes: itself, its sidecar, and what its kind writes beside it
/// (io::write_heightmap's ENVI header beside raw heightmaps, io::write_mesh's material and
/// texture beside a textured OBJ; the scene's meshes are textured, its trees are not).
void add_planned_files(const Recipe& recipe, std::size_t index, std::vector<PlannedFile>& files) {
  const Output& output = recipe.outputs[index];
  if (output.file.empty()) return;  // printed only
  const std::filesystem::path path = detail::resolve(recipe, output.file);
  files.push_back({path, index, PlannedRole::output});
  files.push_back({io::sidecar_path(path), index, PlannedRole::sidecar});
  const std::optional<OutputKind> kind = resolved_kind(output);
  const std::string extension = io::lower_extension(output.file);
  // A header may be left out (rows south first); planned anyway: a name that is not written
  // only makes the checks stricter, and no output can have the extension .hdr.
  const bool raw = extension == ".r32" || extension == ".r16" || extension == ".raw";
  if (raw && kind != OutputKind::volume) files.push_back({io::envi_header_path(path), index, PlannedRole::envi_header});
  // Grids written through io::write_heightmap as 16-bit PNG (not a splat map, a picture or a map).
  const bool png_grid = kind == OutputKind::heightmap || kind == OutputKind::flow_map || kind == OutputKind::erosion_map ||
                        kind == OutputKind::deposition_map || kind == OutputKind::wetness_map || kind == OutputKind::water_depth_map;
  if (extension == ".png" && png_grid) {
    files.push_back({io::png_world_file_path(path), index, PlannedRole::world_file});
    files.push_back({io::png_aux_xml_path(path), index, PlannedRole::aux_xml});
  }
  if (kind == OutputKind::mesh && extension == ".obj") {
    const std::string stem = path.stem().string();
    files.push_back({path.parent_path() / (stem + ".mtl"), index, PlannedRole::material});
    files.push_back({path.parent_path() / (stem + "_basecolor.png"), index, PlannedRole::texture});
  }
}

/// How a message names a planned file.
std::string planned_phrase(const Recipe& recipe, const PlannedFile& file) {
  std::string name = escaped_name(recipe.outputs[file.output].file);
  switch (file.role) {
    case PlannedRole::output:
      return "output " + name;
    case PlannedRole::sidecar:
      return fmt::format("the sidecar of output {} (which rebuilds it)", name);
    case PlannedRole::envi_header:
      return fmt::format("the ENVI header of output {} (which GDAL opens it with)", name);
    case PlannedRole::material:
      return fmt::format("the material file of output {}", name);
    case PlannedRole::texture:
      return fmt::format("the base-colour texture of output {}", name);
    case PlannedRole::world_file:
      return fmt::format("the world file of output {} (which places it in GIS tools)", name);
    case PlannedRole::aux_xml:
      return fmt::format("the .aux.xml of output {} (its CRS and metres, for GDAL)", name);
  }
  return name;
}

/// What identifies a file: its normal absolute name, and for a file that exists, its device and
/// inode (the same file under another spelling, through a link, or a hard link).
struct FileIdentity {
  std::string name;
  std::optional<std::pair<dev_t, ino_t>> inode;
};

FileIdentity planned_identity(const std::filesystem::path& path) {
  FileIdentity identity{absolute_normal(path).string(), std::nullopt};
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0) identity.inode = std::pair{info.st_dev, info.st_ino};
  return identity;
}

/// Files looked up by identity.
class FilesByIdentity {
 public:
  /// The index given with an earlier file of the same identity, or none (then `index` is kept).
  std::optional<std::size_t> add(const FileIdentity& identity, std::size_t index) {
    if (const auto found = find(identity)) return found;
    by_name_.emplace(identity.name, index);
    if (identity.inode) by_inode_.emplace(*identity.inode, index);
    return std::nullopt;
  }
  std::optional<std::size_t> find(const FileIdentity& identity) const {
    if (const auto found = by_name_.find(identity.name); found != by_name_.end()) return found->second;
    if (identity.inode)
      if (const auto found = by_inode_.find(*identity.inode); found != by_inode_.end()) return found->second;
    return std::nullopt;
  }

 private:
  std::unordered_map<std::string, std::size_t> by_name_;
  std::map<std::pair<dev_t, ino_t>, std::size_t> by_inode_;
};

/// No two planned files may be the same file: the first would be lost (or a sidecar replaced).
void check_distinct_files(const Recipe& recipe, const std::vector<PlannedFile>& files, const std::vector<FileIdentity>& identities) {
  FilesByIdentity seen;
  for (std::size_t k = 0; k < files.size(); ++k) {
    const auto earlier = seen.add(identities[k], k);
    if (!earlier) continue;
    const PlannedFile& first = files[*earlier];
    const PlannedFile& second = files[k];
    if (first.role == PlannedRole::output && second.role == PlannedRole::output)
      fail("outputs {} and {} (outputs {} and {} of the recipe) would write the same file: give each output its own name",
           escaped_name(recipe.outputs[first.output].file), escaped_name(recipe.outputs[second.output].file), first.output + 1,
           second.output + 1);
    if (first.role == PlannedRole::output || second.role == PlannedRole::output) {
      const PlannedFile& output = first.role == PlannedRole::output ? first : second;
      const PlannedFile& other = first.role == PlannedRole::output ? second : first;
      fail("{} would overwrite {}: give each output its own name", planned_phrase(recipe, output), planned_phrase(recipe, other));
    }
    fail("{} and {} would be the same file: give each output its own name", planned_phrase(recipe, first), planned_phrase(recipe, second));
  }
}

struct ReadFile {
  std::filesystem::path path;
  std::string reader;  ///< the key that names it ("file.path", "node `a` file")
};

/// The files the recipe reads, each with its sidecar (read beside a heightmap or mesh).
std::vector<ReadFile> read_files_of(const Recipe& recipe) {
  std::vector<ReadFile> inputs;
  const auto add = [&](const std::string& name, const std::string& reader) {
    if (name.empty()) return;
    const std::filesystem::path path = detail::resolve(recipe, name);
    inputs.push_back({path, reader});
    inputs.push_back({io::sidecar_path(path), reader});
  };
  for (const auto& row : recipe_table().rows)
    if (row.kind == params::Kind::path) add(std::get<std::string>(row.get(recipe)), row.key);
  for (const GraphNode& node : recipe.nodes) {
    const NodeKind& kind = node.node_kind();
    for (const auto& row : kind.rows)
      if (row.kind == params::Kind::path)
        add(std::get<std::string>(kind.get(node.params, row.key)), fmt::format("node `{}` {}", node.id, row.key));
  }
  return inputs;
}

/// No planned file may be a file the recipe reads, nor the recipe file itself (except as the
/// sidecar of the output it rebuilds: `sansui run out/t.tif.json` writes out/t.tif.json again).
void check_not_read_files(const Recipe& recipe, const std::vector<PlannedFile>& files, const std::vector<FileIdentity>& identities) {
  const std::vector<ReadFile> inputs = read_files_of(recipe);
  FilesByIdentity read;
  for (std::size_t k = 0; k < inputs.size(); ++k) read.add(planned_identity(inputs[k].path), k);
  FilesByIdentity recipe_file;
  if (!recipe.output_rules.recipe_file.empty()) recipe_file.add(planned_identity(recipe.output_rules.recipe_file), 0);
  for (std::size_t k = 0; k < files.size(); ++k) {
    const PlannedFile& file = files[k];
    const std::string written = file.role == PlannedRole::output ? "output " + escaped_name(file.path.string())
                                                                 : planned_phrase(recipe, file) + " " + escaped_name(file.path.string());
    if (const auto input = read.find(identities[k]))
      fail("{} would overwrite {}, which {} reads: write the output under another name", written, inputs[*input].path.string(),
           inputs[*input].reader);
    if (file.role != PlannedRole::sidecar && recipe_file.find(identities[k]))
      fail("{} would overwrite the recipe this run reads ({}): give the output another name", planned_phrase(recipe, file),
           escaped_name(recipe.output_rules.recipe_file.string()));
  }
}

/// A name that is not a regular file (or absent) is refused: the rename would replace a device,
/// FIFO or socket with a file, or a symbolic link with a file instead of writing its target.
void check_planned_file_types(const Recipe& recipe, const std::vector<PlannedFile>& files) {
  for (const PlannedFile& file : files) {
    struct stat info {};
    if (::lstat(file.path.c_str(), &info) != 0) continue;  // absent: made by the run
    if (S_ISLNK(info.st_mode)) {
      std::error_code error;
      const std::filesystem::path target = std::filesystem::read_symlink(file.path, error);
      if (!recipe.output_rules.follow_symlinks)
        fail(
            "{} is a symbolic link to {}: writing would replace the link with a file; write another name, remove the link, or pass "
            "--follow-symlinks to write its target",
            planned_phrase(recipe, file), escaped_name(target.string()));
      if (::stat(file.path.c_str(), &info) != 0) continue;  // a dangling link: its target is made
    }
    const char* what = S_ISCHR(info.st_mode)    ? "a character device"
                       : S_ISBLK(info.st_mode)  ? "a block device"
                       : S_ISFIFO(info.st_mode) ? "a FIFO (named pipe)"
                       : S_ISSOCK(info.st_mode) ? "a socket"
                       : S_ISDIR(info.st_mode)  ? "a directory"
                                                : nullptr;
    if (what != nullptr)
      fail("{} is {}, not a file: writing would replace it with one; write another name", planned_phrase(recipe, file), what);
  }
}

/// Names that differ only in case are one file on a file system that ignores case (macOS,
/// Windows, a FAT or exFAT stick): a warning, since here they are two files.
///
/// Only ASCII letters are folded. Full Unicode case folding and normalisation (NFC against NFD,
/// as macOS stores names) need Unicode's tables (ICU): a dependency for a warning, and the
/// names here are distinct on this (byte-comparing) file system anyway. Non-ASCII names that
/// differ only in case or normal form are written as two files without a warning.
std::vector<std::string> case_only_warnings(const Recipe& recipe, const std::vector<PlannedFile>& files,
                                            const std::vector<FileIdentity>& identities) {
  std::vector<std::string> warnings;
  std::unordered_map<std::string, std::size_t> folded;
  for (std::size_t k = 0; k < files.size(); ++k) {
    std::string key = identities[k].name;
    std::ranges::transform(key, key.begin(), [](unsigned char c) { return static_cast<char>(c >= 'A' && c <= 'Z' ? c + ('a' - 'A') : c); });
    const auto [found, added] = folded.emplace(key, k);
    if (added) continue;
    const PlannedFile& first = files[found->second];
    // Sidecars and headers of two outputs that differ in case follow from the outputs' warning.
    if (first.role != PlannedRole::output && files[k].role != PlannedRole::output) continue;
    warnings.push_back(
        fmt::format("{} and {} differ only in case: on a file system that ignores case (macOS, Windows) one would overwrite the other",
                    planned_phrase(recipe, first), planned_phrase(recipe, files[k])));
  }
  return warnings;
}

/// A tiled world's files of one output: FOLDER/STEM_X_Y.EXT for every tile (X, Y), each with
/// its sidecar (scene/tiled_world.cpp names them so). Too many to list one by one (a world may
/// have millions of tiles), so they are checked as a pattern.
struct TiledFiles {
  std::filesystem::path folder;  ///< absolute, normal
  std::string stem, extension;
  std::int64_t tiles_x = 0, tiles_y = 0;
  std::size_t output = 0;
};

std::vector<TiledFiles> tiled_files_of(const Recipe& recipe) {
  std::vector<TiledFiles> tiled;
  if (!recipe.world.tiled) return tiled;
  const long long samples = recipe.world.world_size.value_or(recipe.world.size), tile = recipe.world.tile_size - 1;
  if (tile < 1 || samples < 2) return tiled;  // refused by check_tiled_world
  const std::int64_t per_side = std::max<std::int64_t>(1, (samples - 1) / tile);
  for (std::size_t k = 0; k < recipe.outputs.size(); ++k) {
    const std::optional<OutputKind> kind = resolved_kind(recipe.outputs[k]);
    const bool grid = kind == OutputKind::heightmap || kind == OutputKind::erosion_map || kind == OutputKind::deposition_map ||
                      kind == OutputKind::flow_map;
    if (!grid && kind != OutputKind::splat_map) continue;
    const std::filesystem::path path = absolute_normal(detail::resolve(recipe, recipe.outputs[k].file));
    tiled.push_back({path.parent_path(), path.stem().string(), grid ? ".tif" : ".png", per_side, per_side, k});
  }
  return tiled;
}

/// A folder's identity: its device and inode when it exists (the same folder through a link),
/// else its name.
FileIdentity folder_identity(const std::filesystem::path& folder) {
  return planned_identity(folder);
}

bool same_folder(const FileIdentity& a, const FileIdentity& b) {
  return a.name == b.name || (a.inode && b.inode && *a.inode == *b.inode);
}

/// Whether `name` is one of `files`' tile names (or, with `sidecars`, a tile's sidecar):
/// STEM_X_Y.EXT with X and Y written as the run writes them, within the world's tiles.
bool is_tile_name(const TiledFiles& files, std::string_view name, bool sidecars) {
  if (sidecars && name.ends_with(".json")) name.remove_suffix(5);
  if (!name.starts_with(files.stem + "_") || !name.ends_with(files.extension)) return false;
  name = name.substr(files.stem.size() + 1, name.size() - files.stem.size() - 1 - files.extension.size());
  const std::size_t split = name.find('_');
  if (split == std::string_view::npos) return false;
  const auto number_below = [](std::string_view digits, std::int64_t limit) {
    if (digits.empty() || digits.size() > 18 || (digits.size() > 1 && digits.front() == '0')) return false;
    std::int64_t value = 0;
    for (const char c : digits) {
      if (c < '0' || c > '9') return false;
      value = value * 10 + (c - '0');
    }
    return value < limit;
  };
  return number_below(name.substr(0, split), files.tiles_x) && number_below(name.substr(split + 1), files.tiles_y);
}

/// Whether the file `path` is one of the tiles (or tile sidecars) of `files`.
bool is_tile_file(const TiledFiles& files, const FileIdentity& folder, const std::filesystem::path& path) {
  const std::filesystem::path normal = absolute_normal(path);
  return is_tile_name(files, normal.filename().string(), true) && same_folder(folder, folder_identity(normal.parent_path()));
}

/// The tiles of a tiled world, checked as the single files are: no two outputs write the same
/// tiles; no other planned file, input or the recipe is a tile; no tile that exists is a link,
/// device, FIFO, socket or folder (listed from each folder: as many checks as files there).
void check_tiled_files(const Recipe& recipe, const std::vector<PlannedFile>& files) {
  const std::vector<TiledFiles> tiled = tiled_files_of(recipe);
  std::vector<FileIdentity> folders;
  folders.reserve(tiled.size());
  for (const TiledFiles& t : tiled) folders.push_back(folder_identity(t.folder));
  const auto phrase = [&](const TiledFiles& t) {
    return fmt::format("the tiles of output {} ({}_X_Y{})", escaped_name(recipe.outputs[t.output].file), escaped_name(t.stem), t.extension);
  };
  for (std::size_t a = 0; a < tiled.size(); ++a) {
    for (std::size_t b = a + 1; b < tiled.size(); ++b)
      if (tiled[a].stem == tiled[b].stem && tiled[a].extension == tiled[b].extension && same_folder(folders[a], folders[b]))
        fail("outputs {} and {} would write the same tiles ({}_X_Y{}): give each output its own name",
             escaped_name(recipe.outputs[tiled[a].output].file), escaped_name(recipe.outputs[tiled[b].output].file),
             escaped_name(tiled[a].stem), tiled[a].extension);
    for (const PlannedFile& file : files)
      if (is_tile_file(tiled[a], folders[a], file.path))
        fail("{} would overwrite one of {}: give each output its own name", planned_phrase(recipe, file), phrase(tiled[a]));
    for (const ReadFile& input : read_files_of(recipe))
      if (is_tile_file(tiled[a], folders[a], input.path))
        fail("{} would overwrite {}, which {} reads: write the output under another name", phrase(tiled[a]), input.path.string(),
             input.reader);
    if (!recipe.output_rules.recipe_file.empty() && is_tile_file(tiled[a], folders[a], recipe.output_rules.recipe_file) &&
        !recipe.output_rules.recipe_file.string().ends_with(".json"))
      fail("{} would overwrite the recipe this run reads ({}): give the output another name", phrase(tiled[a]),
           escaped_name(recipe.output_rules.recipe_file.string()));
    std::error_code error;
    for (std::filesystem::directory_iterator entry(tiled[a].folder, error), end; !error && entry != end; entry.increment(error)) {
      if (!is_tile_name(tiled[a], entry->path().filename().string(), true)) continue;
      struct stat info {};
      if (::lstat(entry->path().c_str(), &info) != 0) continue;
      const bool link = S_ISLNK(info.st_mode);
      if (link && recipe.output_rules.follow_symlinks && ::stat(entry->path().c_str(), &info) != 0) continue;
      if (S_ISREG(info.st_mode)) continue;
      fail("{} (one of {}) is {}, not a file: writing would replace it with one; remove it or write another name",
           escaped_name(entry->path().string()), phrase(tiled[a]),
           S_ISLNK(info.st_mode)   ? "a symbolic link"
           : S_ISDIR(info.st_mode) ? "a directory"
                                   : "a device, FIFO or socket");
    }
  }
}

}  // namespace

void check_output_names(const Recipe& recipe) {
  const OutputRules& rules = recipe.output_rules;
  std::filesystem::path folder;
  std::filesystem::path real_folder;
  if (!rules.confined_to.empty()) {
    folder = absolute_normal(rules.confined_to);
    std::error_code error;
    real_folder = std::filesystem::weakly_canonical(folder, error);
    if (error) real_folder.clear();
  }
  for (const Output& output : recipe.outputs) {
    const auto control = std::ranges::find_if(output.file, [](unsigned char c) { return c < 0x20 || c == 0x7f; });
    if (control != output.file.end())
      fail("output {} has a control character (\\x{:02x}) in its name: a file name cannot hold one; rename the output",
           escaped_name(output.file), static_cast<unsigned char>(*control));
    if (folder.empty() || output.file.empty()) continue;
    const std::filesystem::path file = absolute_normal(detail::resolve(recipe, output.file));
    if (!lies_inside(file, folder))
      fail("output {} leaves the recipe's folder ({}): write a name inside it, use --out-dir DIR, or pass --allow-outside-paths",
           escaped_name(output.file), folder.string());
    if (rules.follow_symlinks || real_folder.empty()) continue;
    // A link in the folder that leads out of it (a directory link on the way; the file's own
    // link is check_file_types's).
    std::error_code error;
    const std::filesystem::path real_parent = std::filesystem::weakly_canonical(file.parent_path(), error);
    if (!error && !lies_inside(real_parent / file.filename(), real_folder))
      fail(
          "output {} leaves the recipe's folder ({}) through a symbolic link (to {}): write a name inside it, use --out-dir DIR, or pass "
          "--follow-symlinks",
          escaped_name(output.file), folder.string(), real_parent.string());
  }
}

OutputPlan plan_outputs(const Recipe& recipe) {
  OutputPlan plan;
  for (std::size_t k = 0; k < recipe.outputs.size(); ++k) add_planned_files(recipe, k, plan.files);
  std::vector<FileIdentity> identities;
  identities.reserve(plan.files.size());
  for (const PlannedFile& file : plan.files) identities.push_back(planned_identity(file.path));
  check_planned_file_types(recipe, plan.files);
  check_distinct_files(recipe, plan.files, identities);
  check_not_read_files(recipe, plan.files, identities);
  check_tiled_files(recipe, plan.files);
  plan.warnings = case_only_warnings(recipe, plan.files, identities);
  return plan;
}

}  // namespace sansui::scene
