// The `sansui` program's run over MPI ranks as a plugin, sansui-mpi.so (the sansui-mpi package):
// the program links no MPI, so installing it does not install Open MPI; when mpirun starts it,
// it loads the plugin with dlopen and hands it the command line (apps/cli/main.cpp). The plugin
// starts MPI, lends the command its exchange between ranks (mpi_exchange.hpp) and ends the run
// alike on every rank. Nothing here includes MPI: main() reads this header without it.
#pragma once

#include <cstdlib>
#include <string>

#include "core/tile_exchange.hpp"

namespace sansui::mpi {

/// The plugin's file name: beside the program in a build tree, in LIBDIR/sansui/ when installed.
inline constexpr const char* plugin_file_name = "sansui-mpi.so";
/// The plugin's one exported function, a PluginMain.
inline constexpr const char* plugin_entry_name = "sansui_mpi_main";

/// What the program lends the plugin. The two are built together (the packages depend on each
/// other's exact version); `version` is checked all the same, since a plugin of another build
/// would read these fields wrongly.
struct PluginHost {
  /// SANSUI_VERSION of the program.
  const char* version = nullptr;
  /// Runs the command line once (apps/cli/run_cli.hpp's run_cli).
  int (*run)(int argc, char** argv) = nullptr;
  /// Where run() finds the tiles' exchange: the plugin's while it runs, null after.
  TileExchange** exchange = nullptr;
  /// Where run() keeps the line of a failed command instead of printing it, for the plugin to
  /// print once (on rank 0 when every rank failed alike).
  std::string** deferred_error = nullptr;
};

/// The plugin's entry: runs the command over the ranks and returns the program's exit code.
using PluginMain = int (*)(int argc, char** argv, const PluginHost* host);

/// True when this process was started by mpirun (Open MPI's or a PMI launcher's environment).
inline bool started_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

}  // namespace sansui::mpi
