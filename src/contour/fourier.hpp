// Contour shape in the frequency domain: P-type Fourier descriptors (Uesaka 1984, as used by
// Misawa, Chiba, Saito 1987, seeds/000, Sec. 4.2, Figs. 14-15). The closed curve is resampled to
// n equal steps of length h, w(j) = (z(j+1) - z(j)) / h, c(k) = (1/n) sum_j w(j) e^{-2 pi i jk/n};
// every coefficient with |k| >= f0 (k in [-n/2, n/2)) gets a uniform random phase and keeps its
// magnitude; the curve is rebuilt as z'(m) = z(0) + h sum_{j<m} w'(j). c(0) is never touched, so
// the curve stays closed. f0 = n/2 turns the randomisation off (then the output is the resampled
// curve). The transforms use Eigen's FFT in double precision (Debian's kissfft is float only).
#pragma once

#include <complex>
#include <cstdint>
#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct FourierParams {
  /// n: samples of the resampled curve. [Range: power of two, 8..65536] [Default: 1024]
  int samples = 1024;
  /// f0: lowest frequency whose phase is randomised. [Range: 0..n/2] [Default: 256]
  int f0 = 256;
};

/// The closed ring resampled to n points at equal arc-length steps, starting at ring[0].
Ring resample_closed(const Ring& ring, int samples);

/// P-type Fourier descriptors c(k), k = 0..n-1 (k >= n/2 stands for k - n), of a ring already
/// resampled to n equal steps; as interleaved (re, im) pairs.
std::vector<double> p_type_descriptors(const Ring& resampled);

using Steps = std::vector<std::complex<double>>;

/// c(k) = (1/n) sum_j w(j) e^{-2 pi i jk/n}, k = 0..n-1 (k >= n/2 stands for k - n), by FFT.
Steps descriptors_of_steps(const Steps& w);

/// w' from w: every coefficient with f0 <= |k| (k in [-n/2, n/2), k != 0) gets the phase
/// 2 pi u(k), u the contour's uniform random number at frequency index k; magnitudes and c(0)
/// stay. f0 = n/2 changes nothing.
Steps randomise_step_phases(const Steps& w, int f0, std::uint64_t phase_key);

/// Resamples and randomises the phases of the high frequencies (see above); `phase_key` is the
/// contour's random stream (random_keys.hpp), keyed by frequency.
Ring randomise_phases(const Ring& ring, const FourierParams& params, std::uint64_t phase_key);

}  // namespace sansui::contour
