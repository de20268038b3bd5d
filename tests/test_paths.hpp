// Where the tests find the source tree and the programs they run.
//
// The paths are compiled into test_paths.cpp alone: tests/CMakeLists.txt gives that one file
// their macros. A macro with the clone's path on every test's command line would change the
// compile of every test object in each fresh clone, and ccache would miss them all (its base
// directory rewrites a path that starts an argument, not one inside a macro's value).
#pragma once

namespace sansui::test {

extern const char source_dir[];           // the source tree
extern const char cli_path[];             // the `sansui` program
extern const char viewer_path[];          // `sansui-viewer`, where the viewer is built
extern const char gl_free_runner_path[];  // tests/link: a scene run by a program without GL
extern const char scalar_build_path[];    // tests/terrain: the terrain built without vectors
extern const char serial_build_path[];    // tests/core: the library on the serial back end
extern const char threads_build_path[];   // tests/core: the library on the std::thread back end

}  // namespace sansui::test
