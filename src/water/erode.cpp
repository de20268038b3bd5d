// The default erosion chain (see erode.hpp).
#include "water/erode.hpp"

namespace sansui::water {

ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, const Context& context) {
  params.fluvial.validate();
  params.thermal.validate();
  params.droplets.validate();
  ErosionResult result = erode_stream_power(heights, params.fluvial, nullptr, context);
  if (params.thermal.iterations > 0) result.heights = erode_thermal(result.heights, params.thermal, context);
  if (params.droplets.droplets > 0) result.heights = erode_droplets(result.heights, params.droplets, context);
  return result;
}

}  // namespace sansui::water
