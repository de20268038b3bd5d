// `sansui`: the command-line front end. A thin layer: apps/cli/run_cli.cpp parses the options
// and runs the command; this joins the worker threads at exit.
#include "apps/cli/run_cli.hpp"
#include "core/parallel.hpp"
#include "io/atomic_file.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"

int main(int argc, char** argv) {
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::io::remove_temporaries_on_signals();                // SIGINT, SIGTERM: no NAME.tmp-PID-N left behind
  sansui::scene::set_painter(&sansui::render::render_image);  // pictures: scene/painter.hpp
  return sansui::cli::run_cli(argc, argv);
}
