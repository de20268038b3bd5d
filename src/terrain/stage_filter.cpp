#include "terrain/stage_filter.hpp"

#include <array>
#include <cmath>

#include "core/parallel.hpp"

namespace sansui::terrain {
namespace {

constexpr std::array<std::string_view, 5> stage_names = {"original", "young", "mature", "old", "peneplain"};

/// x^a (x < 1) joined at x = 1 to a line of slope 1/divisor: the paper's old and peneplain.
double power_then_line(double x, double exponent, double divisor, bool paper_exact) {
  if (x < 1.0) return std::pow(x, exponent);
  return paper_exact ? x / divisor : 1.0 + (x - 1.0) / divisor;
}

/// Standard deviation of all heights (the unit of x when none is given).
double standard_deviation(const Heightfield& heights) {
  if (heights.empty()) return 0.0;
  double sum = 0.0, squares = 0.0;
  for (float h : heights.values()) sum += h;
  const double mean = sum / static_cast<double>(heights.size());
  for (float h : heights.values()) squares += (h - mean) * (h - mean);
  return std::sqrt(squares / static_cast<double>(heights.size()));
}

}  // namespace

std::optional<Stage> stage_from_name(std::string_view name) {
  for (std::size_t i = 0; i < stage_names.size(); ++i)
    if (stage_names[i] == name) return static_cast<Stage>(i);
  return std::nullopt;
}

std::string_view stage_name(Stage stage) {
  return stage_names[static_cast<std::size_t>(stage)];
}

std::vector<std::pair<std::string, Stage>> stage_choices() {
  std::vector<std::pair<std::string, Stage>> choices;
  for (std::size_t i = 0; i < stage_names.size(); ++i) choices.emplace_back(stage_names[i], static_cast<Stage>(i));
  return choices;
}

double stage_filter(Stage stage, double x, bool paper_exact) {
  switch (stage) {
    case Stage::original:
      return std::pow(x, 0.1);
    case Stage::young:
      return std::pow(x, 0.5);
    case Stage::mature:
      return x;
    case Stage::old:
      return power_then_line(x, 1.3, 1.3, paper_exact);
    case Stage::peneplain:
      return power_then_line(x, 3.0, 3.0, paper_exact);
  }
  return x;
}

void apply_stage_filter(Heightfield& heights, const StageFilterParams& params) {
  if (params.stage == Stage::mature) return;
  const double sea = params.sea_level_m, sigma = params.sigma_m ? *params.sigma_m : standard_deviation(heights);
  if (!(sigma > 0.0)) return;  // a flat world has nothing to reshape
  parallel_for(0, heights.height(), [&](int y) {
    for (float& h : heights.row(y)) {
      const double x = (h - sea) / sigma;
      if (x > 0.0) h = static_cast<float>(sea + sigma * stage_filter(params.stage, x, params.paper_exact));
    }
  });
}

}  // namespace sansui::terrain
