// A world cut into tiles, and the one collective operation tiled algorithms need: every rank
// hands over its messages, each addressed to a tile (or to the root), and receives those
// addressed to its own tiles. One process working through the tiles in turn and MPI ranks
// (src/mpi/) implement it alike, so a tiled algorithm is written once and gives the same bytes on
// any number of ranks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "core/rect.hpp"

namespace sansui {

/// Square tiles of `tile` cells per side over a world of width x height samples. Tiles own their
/// cells without overlap; the last column and row of tiles also own the world's last samples
/// (a world of n x tile + 1 samples: tiles of tile_size = tile + 1 samples that share their borders).
/// A world with a `margin` (land past its edges, water/edge_margin.hpp) is 2 x margin samples
/// wider and higher: its first and last columns and rows of tiles also own the margin's cells, so
/// it has the tiles of the world without it, each over the same land.
struct TileCut {
  int width = 0, height = 0;
  int tile = 0;
  int margin = 0;

  int tiles_x() const { return std::max(1, (width - 1 - 2 * margin) / tile); }
  int tiles_y() const { return std::max(1, (height - 1 - 2 * margin) / tile); }
  int tiles() const { return tiles_x() * tiles_y(); }
  /// The cells tile t owns, in world coordinates.
  Rect owned(int t) const {
    const int tx = t % tiles_x(), ty = t / tiles_x();
    return {tx == 0 ? 0 : margin + tx * tile, ty == 0 ? 0 : margin + ty * tile, tx + 1 == tiles_x() ? width : margin + (tx + 1) * tile,
            ty + 1 == tiles_y() ? height : margin + (ty + 1) * tile};
  }
  /// The owned cells and a ring of `ring` cells around them, clipped to the world.
  Rect haloed(int t, int ring = 1) const {
    const Rect r = owned(t);
    return Rect{r.x0 - ring, r.y0 - ring, r.x1 + ring, r.y1 + ring}.intersect(Rect{0, 0, width, height});
  }
  int tile_at(int x, int y) const {
    return std::min(std::max(y - margin, 0) / tile, tiles_y() - 1) * tiles_x() + std::min(std::max(x - margin, 0) / tile, tiles_x() - 1);
  }
  std::int64_t index(int x, int y) const { return static_cast<std::int64_t>(y) * width + x; }
  int x_of(std::int64_t i) const { return static_cast<int>(i % width); }
  int y_of(std::int64_t i) const { return static_cast<int>(i / width); }
  int tile_of(std::int64_t i) const { return tile_at(x_of(i), y_of(i)); }
};

/// A message between tiles. `to` = root_tile: the root's (rank 0's) global solve.
struct TileMessage {
  int from = 0, to = 0;
  std::vector<std::byte> bytes;
};
inline constexpr int root_tile = -1;

/// Plain values packed into a message and taken out in the same order.
class Packer {
 public:
  template <class T>
  Packer& put(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint64_t count = values.size();
    append(&count, sizeof count);
    append(values.data(), values.size() * sizeof(T));
    return *this;
  }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) {
    const auto* first = static_cast<const std::byte*>(data);
    bytes_.insert(bytes_.end(), first, first + size);
  }
  std::vector<std::byte> bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(std::span<const std::byte> bytes) : bytes_(bytes) {}
  template <class T>
  std::vector<T> take() {
    static_assert(std::is_trivially_copyable_v<T>);
    std::uint64_t count = 0;
    read(&count, sizeof count);
    if (count > (bytes_.size() - at_) / sizeof(T)) throw std::runtime_error("a tile message is shorter than it says");
    std::vector<T> values(count);
    read(values.data(), count * sizeof(T));
    return values;
  }

 private:
  void read(void* data, std::size_t size) {
    if (size > bytes_.size() - at_) throw std::runtime_error("a tile message is shorter than it says");
    if (size > 0) std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
  }
  std::span<const std::byte> bytes_;
  std::size_t at_ = 0;
};

/// The ranks' collective exchange (see the file comment).
class TileExchange {
 public:
  virtual ~TileExchange() = default;
  virtual int rank() const = 0;
  virtual int ranks() const = 0;
  /// The rank that works on tile t (the root: rank 0). Tiles go round the ranks in turn.
  int owner(int t) const { return t < 0 ? 0 : t % ranks(); }
  /// The tiles of `cut` this rank works on, in order.
  std::vector<int> my_tiles(const TileCut& cut) const {
    std::vector<int> mine;
    for (int t = rank(); t < cut.tiles(); t += ranks()) mine.push_back(t);
    return mine;
  }
  /// Collective: hands over `outgoing`; returns the messages addressed to this rank's tiles (and
  /// to the root on rank 0), ordered by sender tile, then as sent.
  virtual std::vector<TileMessage> exchange(std::vector<TileMessage> outgoing) = 0;
  /// Collective: the sum of `value` over the ranks.
  virtual std::int64_t sum(std::int64_t value) = 0;
  /// Collective: the largest of `value` over the ranks.
  virtual double max(double value) = 0;

  /// Bytes of the messages this rank has handed to exchange() so far, and how many exchanges.
  std::int64_t bytes_sent = 0, exchanges = 0;

  /// Set when every rank has agreed that the run fails (bad input found alike everywhere): the
  /// ranks may then end one by one. Otherwise a rank that fails must end them all (MPI_Abort),
  /// since its partners would wait for it in the next exchange.
  bool failed_together = false;
};

/// One process that works on every tile: messages go straight back.
class OneProcess final : public TileExchange {
 public:
  int rank() const override { return 0; }
  int ranks() const override { return 1; }
  std::vector<TileMessage> exchange(std::vector<TileMessage> outgoing) override;
  std::int64_t sum(std::int64_t value) override { return value; }
  double max(double value) override { return value; }
};

/// The messages of `messages` addressed to tile `to`, in order.
std::vector<const TileMessage*> addressed_to(const std::vector<TileMessage>& messages, int to);

}  // namespace sansui
