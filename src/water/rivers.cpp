// River extraction and Strahler order (see rivers.hpp).
#include "water/rivers.hpp"

#include <algorithm>

namespace sansui::water {

RiverNetwork extract_rivers(const FlowRouting& flow, const FlowParams& params) {
  const int width = flow.receiver.width(), height = flow.receiver.height();
  const std::size_t n = flow.receiver.size();
  const CellIndex* rec = flow.receiver.data();
  const double* area = flow.area_m2.data();
  RiverNetwork network;
  network.channel = Grid<std::uint8_t>(width, height, 0, flow.receiver.cell_size_m);
  network.strahler = Grid<std::uint8_t>(width, height, 0, flow.receiver.cell_size_m);
  copy_placement(network.channel, flow.area_m2);
  copy_placement(network.strahler, flow.area_m2);
  std::uint8_t* channel = network.channel.data();
  std::uint8_t* order = network.strahler.data();
  for (std::size_t i = 0; i < n; ++i) channel[i] = area[i] >= params.channel_area_m2 ? 1 : 0;

  // Strahler: upstream first, each channel cell takes the highest order among its channel
  // donors, plus one where two or more donors share that order. A channel's receiver is always
  // a channel (its area is larger), so the network is closed downstream.
  std::vector<std::uint8_t> highest(n, 0), count(n, 0), channel_donors(n, 0);
  for (std::size_t k = flow.stack.size(); k-- > 0;) {
    const CellIndex i = flow.stack[k];
    if (!channel[i]) continue;
    order[i] = highest[i] == 0 ? std::uint8_t{1} : static_cast<std::uint8_t>(highest[i] + (count[i] >= 2 ? 1 : 0));
    const CellIndex r = rec[i];
    if (r == i) continue;
    channel_donors[r] = static_cast<std::uint8_t>(std::min(channel_donors[r] + 1, 8));
    if (order[i] > highest[r])
      highest[r] = order[i], count[r] = 1;
    else if (order[i] == highest[r])
      ++count[r];
  }

  // Reaches start at sources (no channel donor) and confluences (two or more).
  for (std::size_t start = 0; start < n; ++start) {
    if (!channel[start] || channel_donors[start] == 1) continue;
    River river;
    river.strahler_order = order[start];
    auto c = static_cast<CellIndex>(start);
    river.cells.push_back(c);
    while (rec[c] != c) {
      river.area_m2 = area[c];
      c = rec[c];
      river.cells.push_back(c);
      if (channel_donors[c] != 1) break;  // a confluence: the next reach starts here
    }
    if (river.cells.size() == 1) river.area_m2 = area[c];  // a one-cell channel at an outlet
    river.discharge_m3_per_s = river_discharge_m3_per_s(river.area_m2, params);
    network.rivers.push_back(std::move(river));
  }
  return network;
}

}  // namespace sansui::water
