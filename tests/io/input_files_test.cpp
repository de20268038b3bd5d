// Inputs are read alone: an input path must be a regular file (never a device, FIFO or socket,
// which could block or never end), and no input makes Sansui open another file it names (an
// OBJ's mtllib, a glTF's external buffers and images, an SVG's references).
#include <atomic>
#include <chrono>
#include <thread>

#include <sys/stat.h>
#include <unistd.h>

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/heightmap_io.hpp"
#include "io/mesh_io.hpp"
#include "io/text_file.hpp"
#include "io/vertex_locks.hpp"
#include "scene/seed_files.hpp"
#include "tests/io/io_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

using ::testing::HasSubstr;

/// True if something opened the FIFO `path` for reading while `action` ran. A reader would block
/// until a writer comes: a watchdog opens it for writing after a while, which lets the reader go
/// on (reading an empty file) and tells.
template <class Action>
bool opens_fifo(const std::filesystem::path& path, Action&& action) {
  std::atomic<bool> done{false}, opened{false};
  std::thread watchdog([&] {
    for (int i = 0; i < 40 && !done; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    while (!done) {
      const int descriptor = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);  // fails (ENXIO) unless a reader waits
      if (descriptor >= 0) opened = true, ::close(descriptor);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  });
  try {
    action();
  } catch (...) {}
  done = true;
  watchdog.join();
  return opened;
}

TEST(InputFiles, DevicesAndFifosAreRefusedAtOnceNamingThePath) {
  test::TempDir directory("input-devices");
  const auto fifo = directory / "pipe.r32";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(test::input_error_of([&] { io::read_heightmap(fifo); }),
            "cannot read " + fifo.string() + ": it is not a regular file (a device, FIFO or socket): inputs must be files");
  for (const char* name : {"zero.png", "zero.tif", "zero.obj", "zero.glb", "zero.csv"}) {
    std::filesystem::create_symlink("/dev/zero", directory / name);
    const auto path = directory / name;
    const std::string message = test::input_error_of([&] {
      if (io::heightmap_format_for(path))
        io::read_heightmap(path);
      else if (path.extension() == ".csv")
        io::read_text_file(path);
      else
        io::read_mesh(path);
    });
    EXPECT_THAT(message, HasSubstr(path.string() + ": it is not a regular file")) << name;
  }
  EXPECT_THAT(test::input_error_of([&] { io::read_locked_positions(directory / "zero.obj"); }), HasSubstr("not a regular file"));
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));  // nothing waited on the FIFO
}

TEST(InputFiles, AnObjsMtllibIsNeverOpened) {
  test::TempDir directory("input-mtllib");
  ASSERT_EQ(::mkfifo((directory / "trap.mtl").c_str(), 0600), 0);
  test::write_text(directory / "m.obj", "mtllib trap.mtl\nmtllib /dev/zero\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
  TriangleMesh mesh;
  EXPECT_FALSE(opens_fifo(directory / "trap.mtl", [&] { mesh = io::read_mesh(directory / "m.obj"); }));
  EXPECT_EQ(mesh.indices.size(), 3u);  // the geometry reads as if the line were not there
  EXPECT_FALSE(opens_fifo(directory / "trap.mtl", [&] { (void)io::read_locked_positions(directory / "m.obj"); }));
}

/// A .gltf of one triangle whose buffer is `uri`, with an image at `image_uri` if not empty.
std::string gltf_with(const std::string& uri, const std::string& image_uri = {}) {
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}},
                         {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                         {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
                         {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                         {"buffers", {{{"byteLength", 36}, {"uri", uri}}}}};
  if (!image_uri.empty()) gltf["images"] = {{{"uri", image_uri}}};
  return gltf.dump();
}

TEST(InputFiles, AGltfsExternalBuffersAreRefusedAndItsImagesIgnored) {
  test::TempDir directory("input-gltf-uri");
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  test::write_bytes(directory / "m.bin", std::vector<unsigned char>(reinterpret_cast<const unsigned char*>(positions),
                                                                    reinterpret_cast<const unsigned char*>(positions) + sizeof positions));
  test::write_text(directory / "external.gltf", gltf_with("m.bin"));
  EXPECT_EQ(test::input_error_of([&] { io::read_mesh(directory / "external.gltf"); }),
            "cannot read " + (directory / "external.gltf").string() +
                ": it refers to the external file 'm.bin': Sansui reads only the input file itself (embed buffers in a .glb or as data: "
                "URIs)");
  EXPECT_THAT(test::input_error_of([&] { io::read_locked_positions(directory / "external.gltf"); }),
              HasSubstr("refers to the external file 'm.bin'"));
  // The same buffer as a data: URI reads; an image naming a FIFO is not opened.
  ASSERT_EQ(::mkfifo((directory / "trap.png").c_str(), 0600), 0);
  test::write_text(directory / "embedded.gltf",
                   gltf_with("data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIA/", "trap.png"));
  TriangleMesh mesh;
  EXPECT_FALSE(opens_fifo(directory / "trap.png", [&] { mesh = io::read_mesh(directory / "embedded.gltf"); }));
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(InputFiles, AnSvgSeedsReferencesAreNotFollowed) {
  // The SVG reader takes the first <polygon>, <polyline> or <path>; <use> and <image> are text.
  const auto seed =
      scene::parse_seed(R"(<svg xmlns:xlink="http://www.w3.org/1999/xlink"><image xlink:href="/dev/zero"/><use xlink:href="other.svg#p"/>)"
                        R"(<polygon points="0,0 100,0 100,100 0,100"/></svg>)",
                        io::SeedFormat::svg, "s.svg", 1.0);
  EXPECT_EQ(seed.ring.size(), 4u);
}

}  // namespace
}  // namespace sansui
