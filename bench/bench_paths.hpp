// Where the benchmarks find the source tree and the `sansui` program. Compiled into
// bench_paths.cpp alone (bench/CMakeLists.txt), for the reason tests/test_paths.hpp gives.
#pragma once

namespace sansui::bench {

extern const char source_dir[];
extern const char cli_path[];

}  // namespace sansui::bench
