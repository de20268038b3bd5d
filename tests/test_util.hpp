// Helpers shared by the tests.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include <unistd.h>

#include "core/error.hpp"

namespace sansui::test {

/// FNV-1a over bytes: a stable fingerprint for golden values.
inline std::uint64_t fnv1a(const void* data, std::size_t size, std::uint64_t hash = 0xCBF29CE484222325ull) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001B3ull;
  return hash;
}
template <class T>
std::uint64_t fnv1a(std::span<const T> values) {
  return fnv1a(values.data(), values.size_bytes());
}

/// The message of the InputError `f` throws, or "(no error)".
inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

/// A fresh, empty temporary directory for one test, removed when it goes out of scope.
class TempDir {
 public:
  explicit TempDir(const std::string& name);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }

 private:
  std::filesystem::path path_;
};

inline TempDir::TempDir(const std::string& name)
    : path_(std::filesystem::temp_directory_path() / ("sansui-test-" + name + "-" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}
inline TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace sansui::test
