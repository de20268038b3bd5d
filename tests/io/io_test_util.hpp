// Helpers for the io/ tests: sample heightfields and meshes, directory listings, error capture.
#pragma once

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/grid.hpp"
#include "core/random.hpp"
#include "core/triangle_mesh.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {

/// A width x height heightfield: a smooth slope plus noise, spanning roughly [low_m, high_m].
inline Heightfield sample_heights(int width, int height, std::uint64_t seed = 1, double low_m = -120.0, double high_m = 2400.0) {
  auto heights = Heightfield::uninitialized(width, height, 10.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double slope = (x + 2.0 * y) / (width + 2.0 * height);
      heights(x, y) = static_cast<float>(low_m + (high_m - low_m) * (0.8 * slope + 0.2 * rng::uniform(seed, 7, x, y)));
    }
  return heights;
}

/// A fingerprint of the samples, for bit-for-bit comparisons.
inline std::uint64_t hash_of(const Heightfield& heights) {
  return fnv1a(heights.values());
}

/// The names of the files in `directory`, sorted (to show that nothing was left behind).
inline std::vector<std::string> files_in(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  std::ranges::sort(names);
  return names;
}

/// The message of the InputError `action` throws, or "<no InputError>".
template <class Action>
std::string input_error_of(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "<no InputError>";
}

/// The whole file as bytes.
inline std::vector<unsigned char> file_bytes(const std::filesystem::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

/// Writes `bytes` to `path` (for corrupt or hand-made inputs).
inline void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream stream(path, std::ios::binary);
  stream.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream stream(path, std::ios::binary);
  stream << text;
}

/// Keeps the first `size` bytes of a file (a truncated download).
inline void truncate_file(const std::filesystem::path& path, std::uintmax_t size) {
  std::filesystem::resize_file(path, size);
}

}  // namespace sansui::test
