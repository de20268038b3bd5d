// Type I: the whole lattice, level by level (see type1_array.hpp).
//
// Level n works in two passes over z-planes, each plane an independent task:
//  A. planes on the coarser lattice (z a multiple of 2h): edges along x and y, then the face
//     centres in the xy-plane, which need only those edges;
//  B. the planes between them: edges along z, faces in the xz- and yz-planes, then cube centres,
//     which read the planes of pass A above and below.
// Every node is written once, from values written before, with the rules of node_rules.hpp, so
// the result is the same for any thread count and equals Types II-IV bit for bit.
#include "solid/type1_array.hpp"

#include <atomic>
#include <type_traits>
#include <vector>

#include "core/gaussian_row.hpp"
#include "core/parallel.hpp"
#include "core/random.hpp"
#include "solid/node_rules.hpp"

namespace sansui::solid {
namespace {

using rules::mean2;
using rules::mean4;
using rules::mean6;

using rng::gaussian_row;  // noise[t] = g * L(n) for the counters base + t * step: the nodes (x_first + t * x_step, y, z)

class Filler {
 public:
  Filler(const FieldParams& params, Volume& volume)
      : volume_(volume),
        levels_(params.levels),
        shift_(rules::world_shift(params.levels)),
        key_(rng::stream_key(params.seed, rules::stream)),
        scales_(displacement_scales(params)) {}

  void corners(const FieldParams& params) {
    const int last = 1 << levels_;
    for (int i = 0; i < 8; ++i)
      volume_((i & 1) * last, ((i >> 1) & 1) * last, ((i >> 2) & 1) * last) = params.corners[static_cast<std::size_t>(i)];
  }

  /// Level n: pass A over the planes of the coarser lattice, then pass B between them. Progress
  /// goes from `from` to `to` plane by plane: the finest level alone is 7/8 of the work.
  void level(int n, const Context& context, double from, double to) {
    const int half = 1 << (levels_ - n);
    const int planes_a = (1 << (n - 1)) + 1, planes_b = 1 << (n - 1);
    std::atomic<int> planes_done{0};
    auto plane_done = [&] { context.report("solid", from + (to - from) * (++planes_done) / double(planes_a + planes_b)); };
    parallel_for_ranges<int>(0, planes_a, 1, [&](int r_begin, int r_end) {
      std::vector<float> noise(static_cast<std::size_t>(volume_.side()));
      for (int i = r_begin; i != r_end; ++i) {
        context.check_cancelled();
        if (half == 1)  // the finest level, 7/8 of all nodes: a constant stride lets it vectorise
          coarse_plane(n, std::integral_constant<int, 1>{}, 2 * i, noise.data());
        else
          coarse_plane(n, half, 2 * half * i, noise.data());
        plane_done();
      }
    });
    parallel_for_ranges<int>(0, planes_b, 1, [&](int r_begin, int r_end) {
      std::vector<float> noise(static_cast<std::size_t>(volume_.side()));
      for (int i = r_begin; i != r_end; ++i) {
        context.check_cancelled();
        if (half == 1)
          between_plane(n, std::integral_constant<int, 1>{}, 1 + 2 * i, noise.data());
        else
          between_plane(n, half, half + 2 * half * i, noise.data());
        plane_done();
      }
    });
  }

 private:
  void fill_noise(int x_first, int x_step, int y, int z, int count, float scale, float* noise) const {
    gaussian_row(key_ + rules::counter(x_first, y, z, levels_) * rng::golden_gamma,
                 (static_cast<std::uint64_t>(x_step) << shift_) * rng::golden_gamma, count, scale, noise);
  }

  float* row(int y, int z) { return &volume_(0, y, z); }

  /// Row y of plane z, halfway between rows `a` and `b` (of the same plane, or the same row of
  /// two planes): at the coarser lattice's columns, then at the columns between those.
  template <class Half>
  void between_rows(int n, Half half, int y, int z, const float* __restrict a, const float* __restrict b, float* __restrict noise) {
    const int step = 2 * half;
    const int new_per_row = 1 << (n - 1), old_per_row = new_per_row + 1;
    const float scale = scales_[static_cast<std::size_t>(n)];
    float* __restrict r = row(y, z);
    fill_noise(0, step, y, z, old_per_row, scale, noise);
    for (int t = 0; t < old_per_row; ++t) {
      const int x = step * t;
      r[x] = mean2(a[x], b[x]) + noise[t];
    }
    fill_noise(half, step, y, z, new_per_row, scale, noise);
    for (int t = 0; t < new_per_row; ++t) {
      const int x = half + step * t;
      r[x] = mean4(r[x - half], r[x + half], a[x], b[x]) + noise[t];
    }
  }

  /// Pass A: plane z is on the level-(n-1) lattice. Half is int or a compile-time 1.
  template <class Half>
  void coarse_plane(int n, Half half, int z, float* __restrict noise) {
    const int step = 2 * half, last = 1 << levels_;
    const int new_per_row = 1 << (n - 1);  // odd multiples of half in 0..last
    const float scale = scales_[static_cast<std::size_t>(n)];
    // Edges along x, on the rows of the coarser lattice.
    for (int y = 0; y <= last; y += step) {
      fill_noise(half, step, y, z, new_per_row, scale, noise);
      float* __restrict r = row(y, z);
      for (int t = 0; t < new_per_row; ++t) {
        const int x = half + step * t;
        r[x] = mean2(r[x - half], r[x + half]) + noise[t];
      }
    }
    // Edges along y, then the xy-face centres between them, on the rows in between.
    for (int y = half; y < last; y += step) between_rows(n, half, y, z, row(y - half, z), row(y + half, z), noise);
  }

  /// Pass B: plane z lies halfway between two planes of pass A.
  template <class Half>
  void between_plane(int n, Half half, int z, float* __restrict noise) {
    const int step = 2 * half, last = 1 << levels_;
    const int new_per_row = 1 << (n - 1);
    const int old_per_row = new_per_row + 1;
    const float scale = scales_[static_cast<std::size_t>(n)];
    // Rows of the coarser lattice: edges along z, then the xz-face centres between them.
    for (int y = 0; y <= last; y += step) between_rows(n, half, y, z, row(y, z - half), row(y, z + half), noise);
    // Rows in between: yz-face centres, then the cube centres between them.
    for (int y = half; y < last; y += step) {
      const float* __restrict north = row(y - half, z);
      const float* __restrict south = row(y + half, z);
      const float* __restrict below = row(y, z - half);
      const float* __restrict above = row(y, z + half);
      float* __restrict r = row(y, z);
      fill_noise(0, step, y, z, old_per_row, scale, noise);
      for (int t = 0; t < old_per_row; ++t) {
        const int x = step * t;
        r[x] = mean4(north[x], south[x], below[x], above[x]) + noise[t];
      }
      fill_noise(half, step, y, z, new_per_row, scale, noise);
      for (int t = 0; t < new_per_row; ++t) {
        const int x = half + step * t;
        r[x] = mean6(r[x - half], r[x + half], north[x], south[x], below[x], above[x]) + noise[t];
      }
    }
  }

  Volume& volume_;
  int levels_;
  int shift_;
  std::uint64_t key_;
  std::vector<float> scales_;
};

}  // namespace

Volume generate_type1(const FieldParams& params, const Context& context) {
  params.validate();
  Volume volume(params.levels);
  Filler filler(params, volume);
  filler.corners(params);
  // A level's share of the work: the nodes it adds.
  const double total = static_cast<double>(volume.size());
  double done = 1.0 / total;
  for (int n = 1; n <= params.levels; ++n) {
    const double side = static_cast<double>((1 << n) + 1);
    const double after = side * side * side / total;
    filler.level(n, context, done, after);
    done = after;
  }
  return volume;
}

}  // namespace sansui::solid
