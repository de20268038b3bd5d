// The mesh formats' drivers: each format's reader, writer and sidecar description, as
// io/file_formats.cpp registers them (the readers and writers are in obj.cpp and gltf.cpp).
#include "io/mesh_formats.hpp"

namespace sansui::io::detail {
namespace {

namespace fs = std::filesystem;

const std::vector<unsigned char> no_texture;

}  // namespace

const MeshDriver obj_driver{false, read_obj,
                            [](const fs::path& temporary, const fs::path& target, const TriangleMesh& mesh, const MeshWrite& w) {
                              write_obj(temporary, target, mesh, w.material_file);
                            },
                            "Wavefront OBJ: v, vn and vt (same index as v; vt's v up the image), f v/vt/vn, 1-based"};

const MeshDriver glb_driver{true, [](const fs::path& path) { return read_gltf(path, true); },
                            [](const fs::path& temporary, const fs::path& target, const TriangleMesh& mesh, const MeshWrite& w) {
                              write_glb(temporary, target, mesh, w.bounds, w.base_color_png ? *w.base_color_png : no_texture, w.name);
                            },
                            "binary glTF 2.0: float32 POSITION, NORMAL and TEXCOORD_0, uint32 indices, one mesh"};

const MeshDriver gltf_driver{true, [](const fs::path& path) { return read_gltf(path, false); }, nullptr, "glTF 2.0"};

}  // namespace sansui::io::detail
