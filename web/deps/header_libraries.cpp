// The browser build's tinygltf and tinyobjloader (cmake/SansuiWeb.cmake): Debian ships both as
// headers plus a shared object compiled from them; a .wasm cannot link the shared object, so the
// implementations are compiled here from the same Debian headers, as that shared object was.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_gltf.h>
#include <tiny_obj_loader.h>
