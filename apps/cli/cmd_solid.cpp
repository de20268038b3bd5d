// `sansui solid`: 3-D random fractal solid textures (seeds/002, SPEC 2): the field by any of the
// paper's four evaluators, marble/wood/strata textures, pictures and the raw volume.
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/image_io.hpp"
#include "solid/evaluator.hpp"
#include "solid/pictures.hpp"
#include "solid/texture.hpp"
#include "solid/volume_file.hpp"

namespace sansui::cli {
namespace {

struct SolidOptions {
  std::string type = "IV";
  solid::FieldParams field;
  int r2 = -1;  // -1: min(6, R)
  std::string corners;
  std::string texture = "marble";
  std::optional<double> strength;
  std::string volume;
  std::string sphere, cube;
  std::vector<std::string> slice;  // {"AXIS=V", "OUT.png"}
  int size_px = 512;
  bool no_reuse = false;
  double memory_mb = 0.0;  // 0: what the machine has available
};

/// Bytes of memory available now (MemAvailable), or the physical memory if that is unknown.
std::size_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::size_t kilobytes = 0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024;
  return static_cast<std::size_t>(::sysconf(_SC_PHYS_PAGES)) * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

std::array<float, 8> parse_corners(const std::string& text) {
  std::array<float, 8> corners{};
  std::stringstream stream(text);
  std::string part;
  std::size_t count = 0;
  while (std::getline(stream, part, ',')) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size() || count >= 8)
      fail("--corners '{}' is not allowed: give 8 numbers separated by commas (corner x + 2y + 4z)", text);
    corners[count++] = static_cast<float>(value);
  }
  if (count != 8) fail("--corners '{}' is not allowed: give 8 numbers separated by commas (corner x + 2y + 4z)", text);
  return corners;
}

struct SliceSpec {
  int axis = 2;
  double position = 0.0;  // lattice units
};

/// "z=128" (lattice units) or "z=50%" (of the block).
SliceSpec parse_slice(const std::string& text, int levels) {
  const std::string usage = "give AXIS=V with AXIS x, y or z and V in lattice units 0..2^R or a percentage, e.g. z=50%";
  if (text.size() < 3 || text[1] != '=' || (text[0] != 'x' && text[0] != 'y' && text[0] != 'z'))
    fail("--slice '{}' is not allowed: {}", text, usage);
  SliceSpec spec;
  spec.axis = text[0] - 'x';
  std::string number = text.substr(2);
  const bool percent = !number.empty() && number.back() == '%';
  if (percent) number.pop_back();
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error != std::errc() || end != number.data() + number.size() || number.empty() || !std::isfinite(value))
    fail("--slice '{}' is not allowed: {}", text, usage);
  const double last = std::ldexp(1.0, levels);
  spec.position = percent ? value / 100.0 * last : value;
  if (!(spec.position >= 0.0 && spec.position <= last))
    fail("--slice '{}' is outside the block: V must be in [0, {}] (or 0%..100%)", text, last);
  return spec;
}

void check_output(const std::string& path, const std::string& option, const std::string& extension) {
  if (path.empty()) return;
  if (extension_of(path) != extension)
    fail("{} {} has the extension '{}': it must be {}", option, path, extension_of(path), extension);
  io::check_writable(path);
}

void run_solid(SolidOptions o) {
  // Everything is checked before any work, so bad input never leaves a partial file.
  const solid::EvaluatorType type = solid::type_from_name(o.type);
  if (!o.corners.empty()) o.field.corners = parse_corners(o.corners);
  o.field.validate();
  if (o.r2 < 0) o.r2 = std::min(6, o.field.levels);
  if (type == solid::EvaluatorType::type4 && o.r2 > o.field.levels)
    fail("R2 = {} is not allowed: it must be 0..R (R = {})", o.r2, o.field.levels);
  solid::SolidTexture texture = solid::texture_preset(o.texture);
  if (o.strength) {
    if (!std::isfinite(*o.strength)) fail("--strength {} is not a finite number", *o.strength);
    texture.marble.strength = texture.wood.strength = texture.strata.strength = *o.strength;
  }
  std::optional<SliceSpec> slice;
  if (!o.slice.empty()) slice = parse_slice(o.slice[0], o.field.levels);
  const std::string slice_path = o.slice.empty() ? "" : o.slice[1];
  if (o.volume.empty() && o.sphere.empty() && o.cube.empty() && !slice)
    fail("no output: give -o FIELD.r32, --sphere OUT.png, --cube OUT.png or --slice z=V OUT.png");
  check_output(o.volume, "-o", ".r32");
  if (!o.volume.empty()) io::check_writable(solid::volume_sidecar_path(o.volume));
  check_output(o.sphere, "--sphere", ".png");
  check_output(o.cube, "--cube", ".png");
  check_output(slice_path, "--slice", ".png");
  if (o.size_px < 8 || o.size_px > solid::max_picture_px)
    fail("--size {} is not allowed: it must be 8..{}", o.size_px, solid::max_picture_px);
  if (!(o.memory_mb >= 0.0)) fail("--memory {} MB is not allowed: it must be >= 0", o.memory_mb);
  const std::size_t budget = o.memory_mb > 0.0 ? static_cast<std::size_t>(o.memory_mb * 1e6) : available_memory_bytes();
  const double side = o.field.side();
  solid::check_fits(type, o.field, o.r2, o.volume.empty() ? 0.0 : side * side * side, budget);

  ProgressBar progress;
  auto field = solid::make_evaluator(type, o.field, {o.r2, !o.no_reuse}, progress.context());
  if (slice) io::write_png(slice_path, solid::render_slice(*field, texture, slice->axis, slice->position, o.size_px, progress.context()));
  if (!o.sphere.empty()) io::write_png(o.sphere, solid::render_sphere(*field, texture, o.size_px, progress.context()));
  if (!o.cube.empty()) io::write_png(o.cube, solid::render_cube(*field, texture, o.size_px, progress.context()));
  if (!o.volume.empty()) {
    nlohmann::json provenance = run_provenance("solid");
    provenance["parameters"] = {{"type", solid::type_name(type)}, {"levels", o.field.levels}, {"r2", o.r2},
                                {"beta", o.field.beta}, {"seed", o.field.seed}, {"corners", o.field.corners}};
    solid::write_volume_r32(o.volume, *field, provenance, progress.context());
  }
}

}  // namespace

void add_solid_command(CLI::App& app) {
  auto options = std::make_shared<SolidOptions>();
  SolidOptions& o = *options;
  CLI::App* command = app.add_subcommand("solid", "3-D random fractal solid textures: marble, wood and rock strata (Okada et al.).");
  command->add_option("--type", o.type, "Evaluator: I (whole array), II (memo map), III (ancestors only), IV (array to R2, then III); all give the same values. [Default: IV]");
  command->add_option("--levels,-R", o.field.levels, "Recursion levels R: the lattice is {0..2^R}^3. [Range: 1..20; Type I/II as memory allows] [Default: 8]");
  command->add_option("--r2", o.r2, "Type IV: levels held in the Type I array. [Range: 0..R] [Default: min(6, R)]");
  command->add_option("--beta", o.field.beta, "Decay constant: level n displaces by g*exp(-(n-1)*beta); larger is smoother. [Range: > 0] [Default: 0.6]");
  command->add_option("--seed", o.field.seed, "Random seed: the same seed gives the same field, bit for bit. [Default: 1]");
  command->add_option("--corners", o.corners, "The 8 corner values, corner x + 2y + 4z, as A,B,C,D,E,F,G,H. [Default: all 0]");
  command->add_option("--texture", o.texture, "white-marble, green-marble, oak, pine, strata, marble (= white-marble), wood (= oak), or field (D in grey). [Default: marble]");
  command->add_option("--strength", o.strength, "k: how far the field displaces the texture (eq. 7). [Units: block per unit of D] [Default: the preset's]");
  command->add_option("-o,--out", o.volume, "Raw field FIELD.r32: the whole lattice as float32, x fastest, then y, then z, with the sidecar FIELD.r32.json beside it.");
  command->add_option("--sphere", o.sphere, "PNG of a shaded sphere carved out of the block (the paper's Experiment 2).");
  command->add_option("--cube", o.cube, "PNG of the block's top, front and right faces.");
  command->add_option("--slice", o.slice, "PNG of a slice: AXIS=V OUT.png, V in lattice units (0..2^R) or a percentage, e.g. --slice z=50% slice.png")->expected(2);
  command->add_option("--size", o.size_px, "Picture width and height. [Units: px] [Range: 8..8192] [Default: 512]");
  command->add_flag("--no-reuse", o.no_reuse, "Types III/IV: a fresh memo for every query, as in the paper (slower).");
  command->add_option("--memory", o.memory_mb, "Memory the field may use. [Units: MB] [Default: what the machine has available]");
  command->callback([options] { run_solid(*options); });
}

}  // namespace sansui::cli
