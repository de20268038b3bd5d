// sansui_python_stubs FILE: writes the module's type stubs (python/src/signatures.hpp) to FILE.
#include <cstdio>
#include <exception>

#include "io/text_file.hpp"
#include "signatures.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: sansui_python_stubs FILE.pyi\n");
    return 2;
  }
  try {
    sansui::io::write_text_file(argv[1], sansui::python::stubs_text(), "type stubs");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "sansui_python_stubs: %s\n", error.what());
    return 1;
  }
  return 0;
}
