// Writing files without ever leaving a half-written one: write to a temporary name in the same
// directory, then rename over the target (atomic on POSIX). If anything throws before commit(),
// the temporary file is removed.
#pragma once

#include <filesystem>
#include <functional>

namespace sansui::io {

/// Calls write(temporary_path), then renames the temporary file to `path`. Checks first that
/// the directory exists and is writable, with a message naming it. Throws InputError.
void write_atomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path& temporary)>& write);

/// Throws InputError unless `path`'s directory exists and is writable: lets commands fail before
/// long work rather than after.
void check_writable(const std::filesystem::path& path);

}  // namespace sansui::io
