#include "io/atomic_file.hpp"

#include <atomic>
#include <system_error>

#include <unistd.h>

#include "core/error.hpp"

namespace sansui::io {

void check_writable(const std::filesystem::path& path) {
  if (path.empty()) fail("output path is empty");
  const std::filesystem::path directory = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    fail("cannot write {}: directory {} does not exist", path.string(), directory.string());
  if (::access(directory.c_str(), W_OK) != 0) fail("cannot write {}: directory {} is not writable", path.string(), directory.string());
  if (std::filesystem::is_directory(path, error)) fail("cannot write {}: it is a directory", path.string());
}

void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path& temporary)>& write) {
  check_writable(path);
  // Process id and a counter: unique even when two threads of one process write the same name.
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  try {
    write(temporary);
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) fail("cannot write {}: {}", path.string(), error.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

}  // namespace sansui::io
