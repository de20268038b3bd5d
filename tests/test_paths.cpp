// The paths of test_paths.hpp, from the macros tests/CMakeLists.txt gives this file alone. A
// program that is not built leaves its path undefined, and a test that runs it does not link.
#include "test_paths.hpp"

namespace sansui::test {

extern const char source_dir[] = SANSUI_SOURCE_DIR;
extern const char cli_path[] = SANSUI_CLI_PATH;
#ifdef SANSUI_VIEWER_PATH
extern const char viewer_path[] = SANSUI_VIEWER_PATH;
#endif
#ifdef SANSUI_GL_FREE_RUNNER_PATH
extern const char gl_free_runner_path[] = SANSUI_GL_FREE_RUNNER_PATH;
#endif
#ifdef SANSUI_SCALAR_BUILD_PATH
extern const char scalar_build_path[] = SANSUI_SCALAR_BUILD_PATH;
#endif
#ifdef SANSUI_SERIAL_BUILD_PATH
extern const char serial_build_path[] = SANSUI_SERIAL_BUILD_PATH;
#endif
#ifdef SANSUI_THREADS_BUILD_PATH
extern const char threads_build_path[] = SANSUI_THREADS_BUILD_PATH;
#endif

}  // namespace sansui::test
