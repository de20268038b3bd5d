#include "io/binary_file.hpp"

#include <cerrno>
#include <cstring>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include <fcntl.h>

#include "core/error.hpp"

namespace sansui::io::detail {
namespace {

/// stdio buffer size: large enough that writing an 8193-sample row is one system call.
constexpr std::size_t buffer_bytes = std::size_t{1} << 20;

}  // namespace

OutputFile::OutputFile(const std::filesystem::path& temporary, const std::filesystem::path& target)
    : file_(std::fopen(temporary.c_str(), "wb")), target_(target) {
  if (file_ == nullptr) fail_with_errno();
  std::setvbuf(file_, nullptr, _IOFBF, buffer_bytes);
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) std::fclose(file_);
}

void OutputFile::write(const void* data, std::size_t size) {
  if (size != 0 && std::fwrite(data, 1, size, file_) != size) fail_with_errno();
}

void OutputFile::close() {
  std::FILE* file = file_;
  file_ = nullptr;
  // Each result checked, and the error of the first failing call reported (a full disk shows in
  // the flush of the last buffer, or only in the close on some file systems).
  errno = 0;
  const bool flushed = std::fflush(file) == 0 && std::ferror(file) == 0;
  const int flush_error = errno;
  const bool closed = std::fclose(file) == 0;
  if (!flushed) {
    errno = flush_error;
    fail_with_errno();
  }
  if (!closed) fail_with_errno();
}

void OutputFile::fail_with_errno() const {
  const int error = errno;
  fail("cannot write {}: {}", target_.string(), error != 0 ? std::strerror(error) : "write error");
}

int open_regular_file(const std::filesystem::path& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0) fail("cannot read {}: {}", path.string(), std::strerror(errno));
  struct stat status {};
  if (::fstat(descriptor, &status) != 0 || !S_ISREG(status.st_mode)) {
    const bool directory = S_ISDIR(status.st_mode);
    ::close(descriptor);
    if (directory) fail("cannot read {}: it is a directory", path.string());
    fail("cannot read {}: it is not a regular file (a device, FIFO or socket): inputs must be files", path.string());
  }
  // Regular files never block; reads through stdio want the flag off all the same.
  ::fcntl(descriptor, F_SETFL, ::fcntl(descriptor, F_GETFL) & ~O_NONBLOCK);
  return descriptor;
}

InputFile::InputFile(const std::filesystem::path& path) : path_(path) {
  const int descriptor = open_regular_file(path);
  struct stat status {};
  ::fstat(descriptor, &status);
  size_ = static_cast<std::uintmax_t>(status.st_size);
  file_ = ::fdopen(descriptor, "rb");
  if (file_ == nullptr) {
    const int error = errno;
    ::close(descriptor);
    fail("cannot read {}: {}", path.string(), std::strerror(error));
  }
}

InputFile::~InputFile() {
  if (file_ != nullptr) std::fclose(file_);
}

void InputFile::read(void* data, std::size_t size) {
  if (size != 0 && std::fread(data, 1, size, file_) != size) {
    if (std::ferror(file_) != 0) fail("cannot read {}: {}", path_.string(), std::strerror(errno));
    fail("cannot read {}: the file is truncated", path_.string());
  }
}

}  // namespace sansui::io::detail
