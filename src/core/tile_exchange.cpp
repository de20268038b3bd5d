// The exchange of one process (see tile_exchange.hpp).
#include "core/tile_exchange.hpp"

#include <algorithm>

namespace sansui {

std::vector<TileMessage> OneProcess::exchange(std::vector<TileMessage> outgoing) {
  for (const TileMessage& m : outgoing) bytes_sent += static_cast<std::int64_t>(m.bytes.size());
  ++exchanges;
  std::stable_sort(outgoing.begin(), outgoing.end(), [](const TileMessage& a, const TileMessage& b) { return a.from < b.from; });
  return outgoing;
}

std::vector<const TileMessage*> addressed_to(const std::vector<TileMessage>& messages, int to) {
  std::vector<const TileMessage*> found;
  for (const TileMessage& m : messages)
    if (m.to == to) found.push_back(&m);
  return found;
}

}  // namespace sansui
