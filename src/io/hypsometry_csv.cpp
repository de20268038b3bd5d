#include "io/hypsometry_csv.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "io/number_pairs.hpp"

namespace sansui::io {

HypsometryPoints parse_hypsometry(std::string_view text, std::string_view source) {
  HypsometryPoints curve;
  for (const auto& [a, h, line] :
       detail::read_number_pairs(text, source, "a point of a hypsometric curve: give area,height as fractions")) {
    if (!(a >= 0.0 && a <= 1.0 && h >= 0.0 && h <= 1.0)) fail("{}:{}: area {} and height {} must both lie in [0, 1]", source, line, a, h);
    curve.emplace_back(a, h);
  }
  if (curve.size() < 2) fail("{}: a hypsometric curve needs at least 2 points, found {}", source, curve.size());
  std::sort(curve.begin(), curve.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
  for (std::size_t i = 1; i < curve.size(); ++i)
    if (!(curve[i].second > curve[i - 1].second && curve[i].first < curve[i - 1].first))
      fail("{}: the curve must have strictly falling area as height rises (at height {})", source, curve[i].second);
  return curve;
}

}  // namespace sansui::io
