// The renderer's own failure, kept apart from GL headers so that callers can catch it.
#pragma once

#include <stdexcept>
#include <string>

namespace sansui::render {

/// OpenGL or EGL is missing or failed (no driver, a shader did not compile, out of GPU
/// memory). Not a user's input error: the CLI reports it with exit code 1.
class GlError : public std::runtime_error {
 public:
  explicit GlError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace sansui::render
