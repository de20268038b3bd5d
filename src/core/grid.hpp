// Grid<T>: a row-major 2-D array with a cell size in metres, plus non-owning views of
// sub-rectangles. The one heightfield type of Sansui is Grid<float> (metres).
#pragma once

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>
#include <type_traits>

#include "core/rect.hpp"

namespace sansui {

/// A non-owning view of a rectangle of a row-major grid. Row r starts at data + r * stride.
template <class T>
struct GridView {
  T* data = nullptr;
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;  ///< elements between the starts of two rows

  T& operator()(int x, int y) const {
    assert(x >= 0 && x < width && y >= 0 && y < height);
    return data[y * stride + x];
  }
  std::span<T> row(int y) const {
    assert(y >= 0 && y < height);
    return {data + y * stride, static_cast<std::size_t>(width)};
  }
  /// The sub-rectangle r of this view (r in this view's coordinates).
  GridView sub(Rect r) const {
    assert(r.x0 >= 0 && r.y0 >= 0 && r.x1 <= width && r.y1 <= height && !r.empty());
    return {data + r.y0 * stride + r.x0, r.width(), r.height(), stride};
  }
  operator GridView<const T>() const { return {data, width, height, stride}; }
};

template <class T>
using ConstGridView = GridView<const T>;

/// An owning row-major grid: index = y * width + x, x east, y south (row 0 is the north edge).
/// Sample (x, y) stands at east = origin_x_m + x * cell_size_m, south = origin_y_m + y * cell_size_m.
/// Storage for grid samples, cache-line aligned; freed with std::free.
void* allocate_samples(std::size_t bytes);

template <class T>
class Grid {
  static_assert(std::is_trivially_copyable_v<T>, "Grid holds plain samples");

 public:
  Grid() = default;
  /// A grid filled with `fill`.
  Grid(int width, int height, T fill = T{}, double cell_size = 1.0) : Grid(uninitialized(width, height, cell_size)) {
    std::fill_n(data_.get(), size(), fill);
  }
  /// A grid whose samples are left unset: for code that writes every sample itself.
  static Grid uninitialized(int width, int height, double cell_size = 1.0) {
    assert(width >= 0 && height >= 0);
    Grid grid;
    grid.width_ = width;
    grid.height_ = height;
    grid.cell_size_m = cell_size;
    grid.data_.reset(static_cast<T*>(allocate_samples(grid.size() * sizeof(T))));
    return grid;
  }

  /// A grid over `data`, which it does not own or free: a caller's buffer (a numpy array's),
  /// kept alive and unchanged by the caller while the grid lives. Copies own their samples.
  static Grid borrowing(T* data, int width, int height, double cell_size = 1.0) {
    assert(width >= 0 && height >= 0);
    Grid grid;
    grid.width_ = width;
    grid.height_ = height;
    grid.cell_size_m = cell_size;
    grid.data_ = std::unique_ptr<T[], Free>(data, Free{false});
    return grid;
  }

  Grid(const Grid& other) : Grid(uninitialized(other.width_, other.height_, other.cell_size_m)) {
    copy_metadata_from(other);
    std::copy_n(other.data_.get(), size(), data_.get());
  }
  Grid& operator=(const Grid& other) {
    if (this != &other) *this = Grid(other);
    return *this;
  }
  Grid(Grid&&) noexcept = default;
  Grid& operator=(Grid&&) noexcept = default;

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t size() const { return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_); }
  bool empty() const { return size() == 0; }

  T* data() { return data_.get(); }
  const T* data() const { return data_.get(); }
  std::span<T> values() { return {data_.get(), size()}; }
  std::span<const T> values() const { return {data_.get(), size()}; }

  T& operator()(int x, int y) {
    assert(x >= 0 && x < width_ && y >= 0 && y < height_);
    return data_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
  }
  const T& operator()(int x, int y) const { return const_cast<Grid&>(*this)(x, y); }

  std::span<T> row(int y) { return view().row(y); }
  std::span<const T> row(int y) const { return view().row(y); }

  GridView<T> view() { return {data_.get(), width_, height_, width_}; }
  ConstGridView<T> view() const { return {data_.get(), width_, height_, width_}; }
  GridView<T> view(Rect r) { return view().sub(r); }
  ConstGridView<T> view(Rect r) const { return view().sub(r); }
  Rect bounds() const { return {0, 0, width_, height_}; }

  /// Keeps cell size and origin of `other` (used when a grid is derived from another).
  void copy_metadata_from(const Grid& other) {
    cell_size_m = other.cell_size_m;
    origin_x_m = other.origin_x_m;
    origin_y_m = other.origin_y_m;
  }

  double cell_size_m = 1.0;  ///< distance between neighbouring samples. [Units: m] [Range: > 0]
  double origin_x_m = 0.0;   ///< position of sample (0, 0), east. [Units: m]
  double origin_y_m = 0.0;   ///< position of sample (0, 0), south. [Units: m]

 private:
  int width_ = 0;
  int height_ = 0;
  struct Free {
    bool owned = true;  // false for a borrowed buffer
    void operator()(T* p) const {
      if (owned) std::free(p);
    }
  };
  std::unique_ptr<T[], Free> data_;
};

/// A copy of the rectangle r of `source` as a new grid.
template <class T>
Grid<std::remove_const_t<T>> copy_of(GridView<T> source) {
  auto grid = Grid<std::remove_const_t<T>>::uninitialized(source.width, source.height);
  for (int y = 0; y < source.height; ++y) std::ranges::copy(source.row(y), grid.row(y).begin());
  return grid;
}

/// Copies `source` into `target`, which must have the same size.
template <class S, class T>
void copy_into(GridView<S> source, GridView<T> target) {
  assert(source.width == target.width && source.height == target.height);
  for (int y = 0; y < source.height; ++y) std::ranges::copy(source.row(y), target.row(y).begin());
}

/// The heightfield every terrain source produces: elevations in metres.
using Heightfield = Grid<float>;

}  // namespace sansui
