// P-type Fourier descriptors and phase randomisation (Misawa, Chiba, Saito 1987, Sec. 4.2):
// see fourier.hpp.
#include "contour/fourier.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "contour/random_keys.hpp"

namespace sansui::contour {

Ring resample_closed(const Ring& ring, int samples) {
  const std::size_t n = ring.size();
  Ring out;
  if (n == 0 || samples <= 0) return out;
  out.reserve(static_cast<std::size_t>(samples));
  const double total = perimeter(ring);
  const double step = total / samples;
  std::size_t segment = 0;
  double segment_start = 0.0;  // arc length at ring[segment]
  double segment_length = distance(ring[0], ring[1 % n]);
  for (int m = 0; m < samples; ++m) {
    const double target = m * step;
    while (segment + 1 < n && segment_start + segment_length < target) {
      segment_start += segment_length;
      ++segment;
      segment_length = distance(ring[segment], ring[(segment + 1) % n]);
    }
    const double t = segment_length > 0.0 ? std::clamp((target - segment_start) / segment_length, 0.0, 1.0) : 0.0;
    const Point a = ring[segment], b = ring[(segment + 1) % n];
    out.push_back(a + t * (b - a));
  }
  return out;
}

namespace {

Steps steps_of(const Ring& resampled, double h) {
  const std::size_t n = resampled.size();
  Steps w(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Point delta = resampled[(j + 1) % n] - resampled[j];
    w[j] = {delta.x / h, delta.y / h};
  }
  return w;
}

}  // namespace

std::vector<double> p_type_descriptors(const Ring& resampled) {
  const std::size_t n = resampled.size();
  const double h = perimeter(resampled) / static_cast<double>(n);
  std::vector<double> out;
  out.reserve(2 * n);
  for (const auto& c : descriptors_of_steps(steps_of(resampled, h))) {
    out.push_back(c.real());
    out.push_back(c.imag());
  }
  return out;
}

Steps descriptors_of_steps(const Steps& w) {
  Eigen::FFT<double> fft;
  Steps spectrum;
  fft.fwd(spectrum, w);
  const double scale = 1.0 / static_cast<double>(w.size());
  for (auto& c : spectrum) c *= scale;
  return spectrum;
}

Steps randomise_step_phases(const Steps& w, int f0, std::uint64_t phase_key) {
  const int n = static_cast<int>(w.size());
  const bool randomise = f0 < n / 2;  // f0 = n/2 would touch only the Nyquist bin: it means "off"
  Eigen::FFT<double> fft;
  Steps spectrum;
  fft.fwd(spectrum, w);  // n * c(k)
  for (int index = 0; index < n; ++index) {
    const int k = index < n / 2 ? index : index - n;  // in [-n/2, n/2)
    if (!randomise || k == 0 || std::abs(k) < f0) continue;
    const double phase = 2.0 * std::numbers::pi * uniform_at(phase_key, index, 0);
    auto& c = spectrum[static_cast<std::size_t>(index)];
    c = std::polar(std::abs(c), phase);
  }
  Steps out;
  fft.inv(out, spectrum);  // Eigen's inverse divides by n: w'(j) = sum_k c'(k) e^{2 pi i jk/n}
  return out;
}

Ring randomise_phases(const Ring& ring, const FourierParams& params, std::uint64_t phase_key) {
  const int n = params.samples;
  assert(n >= 8 && (n & (n - 1)) == 0 && params.f0 >= 0 && params.f0 <= n / 2);
  Ring z = resample_closed(ring, n);
  const double h = perimeter(ring) / n;
  if (!(h > 0.0)) return z;
  const Steps w = randomise_step_phases(steps_of(z, h), params.f0, phase_key);
  Ring out;
  out.reserve(static_cast<std::size_t>(n));
  // Sum from z(0) in compensated form: the closing error stays at rounding level.
  double x = z[0].x, y = z[0].y, carry_x = 0.0, carry_y = 0.0;
  for (int m = 0; m < n; ++m) {
    out.push_back({x, y});
    const double dx = h * w[static_cast<std::size_t>(m)].real() - carry_x;
    const double dy = h * w[static_cast<std::size_t>(m)].imag() - carry_y;
    const double next_x = x + dx, next_y = y + dy;
    carry_x = (next_x - x) - dx;
    carry_y = (next_y - y) - dy;
    x = next_x;
    y = next_y;
  }
  return out;
}

}  // namespace sansui::contour
