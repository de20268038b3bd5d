// `sansui`: the command-line front end. A thin layer: apps/cli/run_cli.cpp parses the options
// and runs the command; this joins the worker threads at exit.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#if defined(__linux__)
#include <unistd.h>
#endif

#include "apps/cli/cli_support.hpp"
#include "apps/cli/run_cli.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"
#include "io/heightmap_io.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"

#if defined(SANSUI_HAVE_MPI)
#include <optional>

#include <mpi.h>

#include "mpi/mpi_exchange.hpp"
#endif

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

}  // namespace

int main(int argc, char** argv) {
  prefer_huge_pages(argc, argv);
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::io::remove_temporaries_on_signals();                // SIGINT, SIGTERM: no NAME.tmp-PID-N left behind
  sansui::io::let_gdal_own_the_process();                     // only local DEM drivers, when GDAL is first loaded
  sansui::scene::set_painter(&sansui::render::render_image);  // pictures: scene/painter.hpp
#if defined(SANSUI_HAVE_MPI)
  // Under mpirun every rank runs the same command, and tiled worlds spread their tiles over the
  // ranks. A rank that fails ends the whole run (its partners would wait for it for ever).
  if (sansui::mpi::started_by_mpirun()) {
    sansui::mpi::Session session(argc, argv);
    sansui::mpi::Exchange exchange;
    sansui::cli::tile_exchange() = &exchange;
    std::string error;
    sansui::cli::deferred_error() = &error;
    const int code = sansui::cli::run_cli(argc, argv);
    sansui::cli::deferred_error() = nullptr;
    sansui::cli::tile_exchange() = nullptr;
    if (code == 0) return 0;
    // Bad input fails every rank alike (each reads the same recipe): rank 0 says it once, and the
    // run ends without MPI_Abort's banner. A rank that failed alone ends them all.
    const bool together = exchange.failed_together || sansui::mpi::every_rank_failed(std::chrono::seconds(5));
    if (!together || exchange.rank() == 0) std::fputs(error.c_str(), stderr);
    if (!together) MPI_Abort(MPI_COMM_WORLD, code);
    return code;
  }
#endif
  return sansui::cli::run_cli(argc, argv);
}
