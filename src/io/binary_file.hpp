// Plain stdio files for the format writers and readers, with every failure turned into an
// InputError that names the file the user gave (not the temporary name it is written under).
// Internal to io/.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>

namespace sansui::io::detail {

/// A file being written (normally a temporary of write_atomically), with a large stdio buffer
/// so that row-by-row writers make few system calls.
class OutputFile {
 public:
  /// Opens `temporary` for writing; messages name `target`. Throws InputError.
  OutputFile(const std::filesystem::path& temporary, const std::filesystem::path& target);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Appends bytes. Throws InputError (e.g. disk full).
  void write(const void* data, std::size_t size);
  void write(std::string_view text) { write(text.data(), text.size()); }
  /// Flushes and closes, reporting any deferred write error. Call once after the last write.
  void close();
  /// For libraries that write through a FILE* themselves (libpng).
  std::FILE* get() const { return file_; }
  /// Throws InputError "cannot write TARGET: <errno text>" (for errors seen through get()).
  [[noreturn]] void fail_with_errno() const;

 private:
  std::FILE* file_ = nullptr;
  std::filesystem::path target_;
};

/// Opens `path` for reading and returns its descriptor (O_CLOEXEC), if it is a regular file.
/// Throws InputError naming it if it is missing, unreadable, a directory, or a device, FIFO or
/// socket: an input (or a name inside one) must never make Sansui read a device file, which
/// could block forever (a FIFO) or never end (/dev/zero). Opened without blocking, then checked
/// with fstat, so the check is of the file that is read.
int open_regular_file(const std::filesystem::path& path);

/// A file being read. Messages name the file.
class InputFile {
 public:
  /// Opens `path` for reading. Throws InputError as open_regular_file.
  explicit InputFile(const std::filesystem::path& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// The file's size in bytes.
  std::uintmax_t size() const { return size_; }
  /// Reads exactly `size` bytes. Throws InputError if the file ends first.
  void read(void* data, std::size_t size);
  std::FILE* get() const { return file_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::FILE* file_ = nullptr;
  std::filesystem::path path_;
  std::uintmax_t size_ = 0;
};

}  // namespace sansui::io::detail
