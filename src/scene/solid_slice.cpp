#include "scene/solid_slice.hpp"

#include <charconv>
#include <cmath>
#include <optional>

#include "core/error.hpp"

namespace sansui::scene {
namespace {

constexpr std::string_view usage = "AXIS=V with AXIS x, y or z and V in lattice units 0..2^R or a percentage, e.g. z=50%";

struct Parsed {
  int axis = 2;
  double value = 0.0;
  bool percent = false;
};

std::optional<Parsed> parse(std::string_view text) {
  if (text.size() < 3 || text[1] != '=' || (text[0] != 'x' && text[0] != 'y' && text[0] != 'z')) return std::nullopt;
  Parsed parsed;
  parsed.axis = text[0] - 'x';
  std::string_view number = text.substr(2);
  parsed.percent = number.back() == '%';
  if (parsed.percent) number.remove_suffix(1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), parsed.value);
  if (number.empty() || error != std::errc() || end != number.data() + number.size() || !std::isfinite(parsed.value)) return std::nullopt;
  return parsed;
}

}  // namespace

std::string slice_problem(std::string_view text) {
  return parse(text) ? "" : std::string(usage);
}

SliceSpec parse_slice(std::string_view text, int levels) {
  const auto parsed = parse(text);
  if (!parsed) fail("solid.slice_at '{}' is not allowed: give {}", text, usage);
  const double last = std::ldexp(1.0, levels);
  SliceSpec spec{parsed->axis, parsed->percent ? parsed->value / 100.0 * last : parsed->value};
  if (!(spec.position >= 0.0 && spec.position <= last))
    fail("solid.slice_at '{}' is outside the block: V must be in [0, {}] (or 0%..100%)", text, last);
  return spec;
}

io::Volume field_volume(solid::FieldEvaluator& field) {
  const solid::FieldParams& params = field.params();
  io::Volume volume;
  volume.side = field.last() + 1;
  volume.plane = [&field](int z, float* plane) { solid::evaluate_plane(field, z, plane); };
  volume.description = "the lattice {0..2^R}^3 of the 3-D random fractal field D (Okada et al. 1990)";
  volume.about = {{"field",
                   {{"levels", params.levels},
                    {"beta", params.beta},
                    {"seed", params.seed},
                    {"corners", params.corners},
                    {"evaluator", solid::type_name(field.type())}}}};
  return volume;
}

}  // namespace sansui::scene
