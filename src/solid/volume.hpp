// A cubic lattice of floats, (2^levels + 1)^3 values, x fastest, then y, then z (the order of
// the .r32 volume file). Type I fills one; Type IV keeps one for its upper levels.
#pragma once

#include <cassert>
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <span>

namespace sansui::solid {

class Volume {
 public:
  Volume() = default;
  /// A lattice of 2^levels + 1 points per side whose values are left unset. [Range: 0..12]
  explicit Volume(int levels);

  int levels() const { return levels_; }
  int side() const { return side_; }
  std::size_t size() const { return static_cast<std::size_t>(side_) * plane_; }
  std::size_t bytes() const { return size() * sizeof(float); }

  std::size_t index(int x, int y, int z) const {
    assert(x >= 0 && x < side_ && y >= 0 && y < side_ && z >= 0 && z < side_);
    return static_cast<std::size_t>(z) * plane_ + static_cast<std::size_t>(y) * static_cast<std::size_t>(side_) +
           static_cast<std::size_t>(x);
  }
  float& operator()(int x, int y, int z) { return data_.get()[index(x, y, z)]; }
  float operator()(int x, int y, int z) const { return data_.get()[index(x, y, z)]; }

  float* data() { return data_.get(); }
  const float* data() const { return data_.get(); }
  std::span<const float> values() const { return {data_.get(), size()}; }
  /// The z-th plane: side^2 values, x fastest.
  std::span<const float> plane(int z) const { return {data_.get() + index(0, 0, z), plane_}; }

 private:
  struct Free {
    void operator()(float* p) const { std::free(p); }
  };
  int levels_ = 0;
  int side_ = 0;
  std::size_t plane_ = 0;
  std::unique_ptr<float, Free> data_;
};

}  // namespace sansui::solid
