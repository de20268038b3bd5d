// The MPI plugin sansui-mpi.so (see mpi_plugin.hpp): MPI's session, the ranks' exchange, and one
// end of the run for every rank.
#include "mpi/mpi_plugin.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include <mpi.h>

#include "mpi/mpi_exchange.hpp"

extern "C" __attribute__((visibility("default"))) int sansui_mpi_main(int argc, char** argv, const sansui::mpi::PluginHost* host) {
  using namespace sansui::mpi;
  if (host == nullptr || host->version == nullptr || std::strcmp(host->version, SANSUI_VERSION) != 0) {
    std::fprintf(stderr, "sansui: the MPI plugin is version %s, the program %s: install sansui and sansui-mpi of one version\n",
                 SANSUI_VERSION, host != nullptr && host->version != nullptr ? host->version : "unknown");
    return 2;
  }
  // Every rank runs the same command, and tiled worlds spread their tiles over the ranks. A rank
  // that fails ends the whole run (its partners would wait for it for ever).
  Session session(argc, argv);
  Exchange exchange;
  *host->exchange = &exchange;
  std::string error;
  *host->deferred_error = &error;
  const int code = host->run(argc, argv);
  *host->deferred_error = nullptr;
  *host->exchange = nullptr;
  if (code == 0) return 0;
  // Bad input fails every rank alike (each reads the same recipe): rank 0 says it once, and the
  // run ends without MPI_Abort's banner. A rank that failed alone ends them all.
  const bool together = exchange.failed_together || every_rank_failed(std::chrono::seconds(5));
  if (!together || exchange.rank() == 0) std::fputs(error.c_str(), stderr);
  if (!together) MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}
