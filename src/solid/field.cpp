#include "solid/field.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/exact_math.hpp"

namespace sansui::solid {
namespace {

std::string human_bytes(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.1f} GB", bytes / 1e9);
  if (bytes >= 1e6) return fmt::format("{:.1f} MB", bytes / 1e6);
  if (bytes >= 1e3) return fmt::format("{:.1f} kB", bytes / 1e3);
  return fmt::format("{:.0f} bytes", bytes);
}

}  // namespace

std::vector<float> displacement_scales(const FieldParams& params) {
  constexpr double log2_e = 1.4426950408889634074;
  std::vector<float> scales(static_cast<std::size_t>(params.levels) + 1);
  scales[0] = 1.0f;
  for (int n = 1; n <= params.levels; ++n)
    scales[static_cast<std::size_t>(n)] = static_cast<float>(exact_exp2(-(n - 1) * params.beta * log2_e));
  return scales;
}

std::string type_name(EvaluatorType type) {
  switch (type) {
    case EvaluatorType::type1:
      return "I";
    case EvaluatorType::type2:
      return "II";
    case EvaluatorType::type3:
      return "III";
    case EvaluatorType::type4:
      return "IV";
  }
  return "?";
}

EvaluatorType type_from_name(const std::string& name) {
  if (name == "I" || name == "i" || name == "1") return EvaluatorType::type1;
  if (name == "II" || name == "ii" || name == "2") return EvaluatorType::type2;
  if (name == "III" || name == "iii" || name == "3") return EvaluatorType::type3;
  if (name == "IV" || name == "iv" || name == "4") return EvaluatorType::type4;
  fail("type '{}' is unknown: allowed are I, II, III, IV", name);
}

std::size_t lattice_bytes(int levels) {
  const auto side = static_cast<std::size_t>((std::size_t{1} << levels) + 1);
  return side * side * side * sizeof(float);
}

double paper_words_c1(int levels) {
  const double side = std::ldexp(1.0, levels) + 1.0;
  return side * side * side;
}
double paper_words_c2(double nodes) {
  return 13.0 * nodes;
}
double paper_words_c3(int levels) {
  return 13.0 * 19.0 * levels;
}
double paper_words_c4(int levels, int r2) {
  return paper_words_c1(r2) + 13.0 * 19.0 * (levels - r2);
}

void check_fits(EvaluatorType type, const FieldParams& params, int r2, double type2_nodes, std::size_t budget_bytes) {
  params.validate();
  const int levels = params.levels;
  const auto budget = static_cast<double>(budget_bytes);
  switch (type) {
    case EvaluatorType::type1: {
      const double need = 4.0 * paper_words_c1(levels);
      if (need > budget)
        fail("Type I at R = {} needs {} for its {}^3 lattice, more than the {} of memory available: use --type III or IV", levels,
             human_bytes(need), params.side(), human_bytes(budget));
      break;
    }
    case EvaluatorType::type2: {
      const double need = static_cast<double>(type2_bytes_per_node) * type2_nodes;
      if (need > budget)
        fail("Type II at R = {} needs about {} for the {:.3g} nodes of its map, more than the {} of memory available: use --type III or IV",
             levels, human_bytes(need), type2_nodes, human_bytes(budget));
      break;
    }
    case EvaluatorType::type3:
      break;
    case EvaluatorType::type4: {
      if (r2 < 0 || r2 > levels) fail("R2 = {} is not allowed: it must be 0..R (R = {})", r2, levels);
      const double need = 4.0 * paper_words_c1(r2);
      if (need > budget)
        fail("Type IV with R2 = {} needs {} for its {}^3 array, more than the {} of memory available: use a smaller --r2", r2,
             human_bytes(need), (1 << r2) + 1, human_bytes(budget));
      break;
    }
  }
}

double type2_picture_nodes(int levels, int size_px) {
  const double side = std::ldexp(1.0, levels) + 1.0;
  const double pixels = static_cast<double>(size_px) * static_cast<double>(size_px);
  return std::min(side * side * side, 27.0 * pixels * std::max(levels - 7, 1));
}

budget::Cost type2_cost(const FieldParams& params, double nodes, std::string_view outputs) {
  budget::Cost cost;
  cost.bytes = static_cast<double>(type2_bytes_per_node) * nodes;
  cost.seconds = 1e-6 * nodes;
  cost.what = fmt::format("Type II at R = {} (about {:.3g} nodes in its memo map for {})", params.levels, nodes, outputs);
  cost.smaller = "use --type III or IV, a smaller R or a smaller picture size";
  cost.force.clear();  // Types III and IV give the same values in bounded memory
  return cost;
}

}  // namespace sansui::solid
