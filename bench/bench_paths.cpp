#include "bench/bench_paths.hpp"

namespace sansui::bench {

extern const char source_dir[] = SANSUI_SOURCE_DIR;
extern const char cli_path[] = SANSUI_CLI_PATH;

}  // namespace sansui::bench
