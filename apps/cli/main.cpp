// `sansui`: the command-line front end. A thin layer: apps/cli/run_cli.cpp parses the options
// and runs the command; this joins the worker threads at exit, and under mpirun hands the run
// to the MPI plugin.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include <dlfcn.h>  // the MPI plugin (POSIX)

#if defined(__linux__)
#include <unistd.h>
#endif

#include "apps/cli/cli_support.hpp"
#include "apps/cli/run_cli.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "mpi/mpi_plugin.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
#else
constexpr bool sanitized = false;
#endif

/// Runs this process again with glibc's malloc asking the kernel for transparent huge pages
/// (the documented tunable glibc.malloc.hugetlb=1), for the commands that draw pictures, when the
/// kernel gives huge pages only on request (transparent_hugepage "madvise", the common default).
/// A full scene's picture touches about 0.8 GB of fresh memory, much of it in the OpenGL driver
/// (textures, the multisampled target), which no madvise of ours reaches: in 4 KB pages that is
/// 200,000 page faults, 1.3 s of CPU on a virtual machine (issue 32); in 2 MB pages a tenth of
/// that. The second start costs about 0.1 s of CPU. A tunable given by the caller (also
/// glibc.malloc.hugetlb=0, to turn this off) is left as it is; if the new start fails, this one
/// goes on.
void prefer_huge_pages([[maybe_unused]] int argc, [[maybe_unused]] char** argv) {
#if defined(__linux__) && defined(__GLIBC__)
  if (sanitized) return;                                       // the sanitizers' allocator does not read glibc's tunables
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) return;  // a rank of mpirun's: started once, by it
  const char* found = std::getenv("GLIBC_TUNABLES");
  const std::string given = found != nullptr ? found : "";
  if (given.find("glibc.malloc.hugetlb") != std::string::npos) return;
  bool draws = false;
  for (int i = 1; i < argc; ++i) draws = draws || std::strcmp(argv[i], "run") == 0 || std::strcmp(argv[i], "render") == 0;
  if (!draws) return;
  std::ifstream mode_file("/sys/kernel/mm/transparent_hugepage/enabled");
  const std::string mode((std::istreambuf_iterator<char>(mode_file)), std::istreambuf_iterator<char>());
  if (mode.find("[madvise]") == std::string::npos) return;
  const std::string tunables = given.empty() ? "glibc.malloc.hugetlb=1" : given + ":glibc.malloc.hugetlb=1";
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  // By the file's own path, so that the process keeps its name (ps, top); /proc/self/exe if the
  // file was replaced meanwhile.
  std::string self(4096, '\0');
  const ssize_t length = readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (length > 0) execv(self.substr(0, static_cast<std::size_t>(length)).c_str(), argv);
  execv("/proc/self/exe", argv);
  // Still here: the new start failed; go on as we are, with the caller's environment.
  if (found != nullptr)
    setenv("GLIBC_TUNABLES", given.c_str(), 1);
  else
    unsetenv("GLIBC_TUNABLES");
#endif
}

/// Under mpirun every rank runs the same command, and tiled worlds spread their tiles over the
/// ranks: through the MPI plugin (mpi/mpi_plugin.hpp), loaded from beside this program (a build
/// tree) or from LIBDIR/sansui/ (installed by the sansui-mpi package). Without it the run is
/// refused (each rank would otherwise make the whole world, into the same files): rank 0 says
/// what to install, and every rank ends with exit code 2.
int run_over_mpi_ranks(int argc, char** argv) {
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  const bool first = rank == nullptr || std::strcmp(rank, "0") == 0;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  const std::filesystem::path folder = error ? std::filesystem::path(argv[0]).parent_path() : self.parent_path();
  const std::filesystem::path installed = (folder / SANSUI_PLUGIN_DIR_FROM_BIN / sansui::mpi::plugin_file_name).lexically_normal();
  void* plugin = nullptr;
  for (const std::filesystem::path& path : {folder / sansui::mpi::plugin_file_name, installed}) {
    if (!std::filesystem::is_regular_file(path, error)) continue;
    // RTLD_GLOBAL: Open MPI's own components, which it loads in turn, find its symbols.
    plugin = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (plugin == nullptr) {
      if (first) std::fprintf(stderr, "sansui: the MPI plugin %s does not load: %s\n", path.c_str(), dlerror());
      return 2;
    }
    break;
  }
  if (plugin == nullptr) {
    if (first)
      std::fprintf(stderr,
                   "sansui: started by mpirun, but the MPI plugin (%s) is not installed: install the package sansui-mpi, "
                   "or run without mpirun\n",
                   installed.c_str());
    return 2;
  }
  const auto entry = reinterpret_cast<sansui::mpi::PluginMain>(dlsym(plugin, sansui::mpi::plugin_entry_name));
  if (entry == nullptr) {
    if (first)
      std::fprintf(stderr, "sansui: the MPI plugin has no %s: install sansui and sansui-mpi of one version\n",
                   sansui::mpi::plugin_entry_name);
    return 2;
  }
  const sansui::mpi::PluginHost host{.version = SANSUI_VERSION,
                                     .run = [](int count, char** values) { return sansui::cli::run_cli(count, values); },
                                     .exchange = &sansui::cli::tile_exchange(),
                                     .deferred_error = &sansui::cli::deferred_error()};
  return entry(argc, argv, &host);  // the plugin stays loaded: MPI_Finalize ran, and exit() follows
}

}  // namespace

int main(int argc, char** argv) {
  prefer_huge_pages(argc, argv);
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::io::remove_temporaries_on_signals();                // SIGINT, SIGTERM: no NAME.tmp-PID-N left behind
  sansui::io::let_gdal_own_the_process();                     // only local DEM drivers, when GDAL is first loaded
  sansui::scene::set_painter(&sansui::render::render_image);  // pictures: scene/painter.hpp
  if (sansui::mpi::started_by_mpirun()) return run_over_mpi_ranks(argc, argv);
  return sansui::cli::run_cli(argc, argv);
}
