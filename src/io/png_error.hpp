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

/// Writes a PNG to `file`: `write(png, info)` sets the header and writes the rows, from
/// png_set_IHDR to png_write_end. False on a libpng error, whose message is then in `error`;
/// `write`'s locals must be trivially destructible, since the error longjmps past them.
template <class Write>
bool write_png_with(std::FILE* file, PngError& error, Write&& write) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, on_png_error, on_png_warning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  write(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace sansui::io::detail
