// libpng's error callbacks for Sansui's PNG readers and writers (image_io.cpp, png16.cpp).
// libpng reports an error by longjmp, which skips C++ destructors: every libpng call lives in a
// function whose locals are trivially destructible and that returns false with the message kept
// in a PngError; the C++ side around it owns the buffers and throws.
#pragma once

#include <cstdio>

#include <png.h>

namespace sansui::io::detail {

struct PngError {
  char message[256] = "unknown libpng error";
};

[[noreturn]] inline void on_png_error(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngError*>(png_get_error_ptr(png));
  std::snprintf(error->message, sizeof error->message, "%s", message);
  png_longjmp(png, 1);
}

inline void on_png_warning(png_structp, png_const_charp) {}  // the library never prints

}  // namespace sansui::io::detail
