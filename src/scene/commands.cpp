#include "scene/commands.hpp"

#include "io/file_formats.hpp"

namespace sansui::scene {

namespace {

// The extensions and what they hold, from io's list of formats.
std::string heights_help() {
  return io::format_help(io::FormatData::heights, io::Access::write);
}
std::string meshes_help() {
  return io::format_help(io::FormatData::mesh, io::Access::write);
}

/// The water outputs of every command that can erode (CommandSpec::erode_option).
const std::vector<OutputOption>& water_output_options() {
  using O = OutputKind;
  static const std::vector<OutputOption> options{
      {"--rivers", O::rivers, false, "Write the rivers as GeoJSON lines with Strahler order and discharge (.geojson)"},
      {"--lakes", O::lakes, false, "Write the lakes as GeoJSON polygons with their water level (.geojson)"},
      {"--flow-map", O::flow_map, false, "Splat map: log10 of the drainage area (.png 16-bit, .r32, .tif)"},
      {"--erosion-map", O::erosion_map, false, "Splat map: metres eroded by --erode (.png 16-bit, .r32, .tif)"},
      {"--deposition-map", O::deposition_map, false, "Splat map: metres deposited by --erode (.png 16-bit, .r32, .tif)"},
      {"--wetness-map", O::wetness_map, false, "Splat map: wetness 0..1 (.png 16-bit, .r32, .tif)"},
      {"--water-depth-map", O::water_depth_map, false, "Splat map: metres of river and lake water (.png 16-bit, .r32, .tif)"},
      {"--splat-map", O::splat_map, false,
       "Splat map of the land's bands: RGBA weights of sand/beach, grass, rock and snow summing to 1 per pixel (.png)"}};
  return options;
}

/// Every command, before the water outputs are added.
std::vector<CommandSpec> command_list();

}  // namespace

const std::vector<CommandSpec>& command_specs() {
  static const std::vector<CommandSpec> specs = [] {
    std::vector<CommandSpec> all = command_list();
    for (CommandSpec& spec : all)
      if (spec.erode_option) spec.outputs.insert(spec.outputs.end(), water_output_options().begin(), water_output_options().end());
    return all;
  }();
  return specs;
}

namespace {

/// The sections of a scene around a picture (climate to atmosphere), under one heading in --help.
std::vector<SectionUse> scene_sections(const std::string& group) {
  return {{"climate", "", group}, {"season", "", group},  {"weather", "", group}, {"time", "", group},      {"camera", "camera-", group},
          {"land", "", group},    {"sea", "sea-", group}, {"sky", "sky-", group}, {"atmosphere", "", group}};
}

/// The sections of a picture a command draws besides its own outputs (--render): the picture,
/// its rock and its scene, under one heading.
std::vector<SectionUse> picture_sections(const std::string& group) {
  std::vector<SectionUse> sections{{"render", "", group}, {"rock", "rock-", group}};
  const std::vector<SectionUse> scene = scene_sections(group);
  sections.insert(sections.end(), scene.begin(), scene.end());
  return sections;
}

/// The parts one after another.
std::vector<SectionUse> joined(std::initializer_list<std::vector<SectionUse>> parts) {
  std::vector<SectionUse> all;
  for (const std::vector<SectionUse>& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

/// The plants and the water of a command that can draw them.
std::vector<SectionUse> plant_and_water_sections(const std::string& flow_group) {
  return {{"vegetation", "plants-", "Plants"}, {"flow", "flow-", flow_group}};
}

CommandSpec terrain_command() {
  return {"terrain",
          "Fractal terrain by midpoint displacement with successive random additions, whole or as seamless tiles.",
          SourceKind::midpoint,
          {{"midpoint", "", "Terrain"},
           {"world", "", "World, tiles and previews"},
           {"heightmap_output", "", "Heightmap files"},
           {"georeference", "", "Coordinate reference system"},
           {"flow", "flow-", "Rivers and lakes"}},
          true,
          {},
          {{"-o,--out", std::nullopt, true, "Output file, repeatable; format from the extension: " + heights_help() + " " + meshes_help()}},
          {},
          true};
}

CommandSpec render_command() {
  using O = OutputKind;
  return {"render",
          "Draw a heightmap as a picture (PNG), headless: bird's-eye perspective or top view, coloured by elevation and slope bands, "
          "sun-shaded with shadows.",
          SourceKind::file,
          joined({{{"file", "", "Heightmap"}, {"render", "", "Picture"}, {"rock", "rock-", "Rock on cliffs"}},
                  scene_sections("Scene: climate, season, weather, time, sky, sea"),
                  plant_and_water_sections("Rivers and lakes (--draw-water)")}),
          false,
          {{"heightmap", "file.path"}},
          {{"-o,--out", O::render, false, "Picture to write (.png)."},
           {"--plants", O::plants, false, "Also write the plants as a list of instances (.csv or .json) for game engines"}},
          {}};
}

CommandSpec contour_command() {
  using O = OutputKind;
  return {"contour",
          "A mountain from one contour line (Misawa, Chiba, Saito): contours, map, DEM, bird's-eye view.",
          SourceKind::contour,
          joined({{{"contour_seed", "", "Seed contour"},
                   {"contour", "", "Contour generation"},
                   {"dem", "dem-", "DEM"},
                   {"contour_dem", "dem-", "DEM"},
                   {"heightmap_output", "", "DEM file"},
                   {"georeference", "", "Coordinate reference system"},
                   {"map", "map-", "Contour map"}},
                  picture_sections("Bird's-eye view (--render)"),
                  plant_and_water_sections("Rivers and lakes")}),
          false,
          {{"seed_file", "contour_seed.file"}},
          {{"--contours", O::contours, false, "Write the contours as GeoJSON (.geojson)"},
           {"--map", O::map, true, "Write a contour map (.svg or .png); repeatable"},
           {"--dem", O::heightmap, false, "Write a DEM: " + heights_help()},
           {"--render", O::render, false, "Write a bird's-eye picture of the DEM (.png), as sansui render draws it"},
           {"--plants", O::plants, false, "Write the plants as a list of instances (.csv or .json) for game engines"}},
          {},
          true};
}

CommandSpec contour_dem_command() {
  using O = OutputKind;
  return {"contour-dem",
          "A DEM from a given contour map (GeoJSON lines with elevations, as gdal_contour writes them), interpolated between "
          "the bracketing contours like GRASS r.surf.contour: no terraces, rounded summits and pits.",
          SourceKind::contour_map,
          {{"contour_map", "", "Contour map"},
           {"dem", "dem-", "DEM grid"},
           {"heightmap_output", "", "DEM file"},
           {"georeference", "", "Coordinate reference system"}},
          false,
          {{"contours", "contour_map.file"}},
          {{"--dem", O::heightmap, true, "DEM output, repeatable: " + heights_help()},
           {"--preview", O::preview, false, "Top-down shaded relief of the DEM (.png, north up), for a quick look"},
           {"--render", O::render, false, "A picture of the DEM (.png), as sansui render draws it"}},
          {}};
}

CommandSpec compare_command() {
  using O = OutputKind;
  return {"compare",
          "Compare a generated DEM with a real one: hypsometry, slopes, summits, contours, spectra.",
          SourceKind::file,
          {{"compare", "", "Comparison"}, {"file", "", "Generated DEM"}, {"map", "map-", "Contour maps"}},
          false,
          {{"real", "compare.real"}, {"generated", "file.path"}},
          {{"--json", O::comparison, false, "Also write every measure as JSON"},
           {"--map-real", O::map_real, false, "Write a contour map of the real DEM at the compared levels (.svg or .png)"},
           {"--map-generated", O::map_generated, false, "Write a contour map of the generated DEM at the compared levels (.svg or .png)"}},
          {{"", O::comparison, {}, {}}}};
}

CommandSpec solid_command() {
  using O = OutputKind;
  return {"solid",
          "3-D random fractal solid textures: marble, wood and rock strata (Okada et al.).",
          SourceKind::none,
          {{"solid_field", "", "Field"}, {"solid", "", "Texture and pictures"}},
          false,
          {},
          {{"-o,--out", O::volume, false,
            "Raw field FIELD.r32: the whole lattice as float32, x fastest, then y, then z, with the sidecar FIELD.r32.json beside it."},
           {"--sphere", O::sphere, false, "PNG of a shaded sphere carved out of the block (the paper's Experiment 2)."},
           {"--cube", O::cube, false, "PNG of the block's top, front and right faces."},
           {"--slice", O::slice, false, "PNG of a slice through the block where --slice-at says."}},
          {}};
}

CommandSpec subdivide_command() {
  using O = OutputKind;
  return {"subdivide",
          "Fractal subdivision of a triangle mesh (Nishimura & Sakata): a coarse mountain to a detailed one and a DEM.",
          SourceKind::mesh,
          joined({{{"mesh", "", "Coarse mesh"},
                   {"sketch", "sketch-", "Sketch"},
                   {"subdivide", "", "Subdivision"},
                   {"dem", "dem-", "DEM"},
                   {"heightmap_output", "", "DEM files"},
                   {"georeference", "", "Coordinate reference system"}},
                  picture_sections("Picture (--render)"),
                  plant_and_water_sections("Rivers and lakes")}),
          false,
          {{"mesh", "mesh.file"}},
          {{"-o,--out", O::mesh, true, "Mesh output, repeatable: " + meshes_help() + ", with a JSON sidecar."},
           {"--dem", O::heightmap, true, "DEM output, repeatable: " + heights_help() + "; highest surface wins."},
           {"--preview", O::preview, false, "Top-down shaded relief of the DEM (.png, north up), for a quick look."},
           {"--render", O::render, false, "A picture of the DEM (.png), as sansui render draws it."},
           {"--plants", O::plants, false, "The plants as a list of instances (.csv or .json) for game engines."}},
          {},
          true};
}

CommandSpec tree_command() {
  using O = OutputKind;
  return {"tree",
          "One plant of the species library (Oka et al. 1997, Table 1): a picture on a patch of ground, or its mesh for other tools.",
          SourceKind::none,
          {{"tree", "", "Plant"}, {"season", "", "Plant"}, {"render", "", "Picture"}},
          false,
          {},
          {{"-o,--out", O::tree, true, "A picture (.png) or mesh (.glb .obj, with vertex colours) of the plant; repeatable"}},
          {}};
}

std::vector<CommandSpec> command_list() {
  return {terrain_command(), render_command(), contour_command(),   contour_dem_command(),
          compare_command(), solid_command(),  subdivide_command(), tree_command()};
}

}  // namespace

}  // namespace sansui::scene
