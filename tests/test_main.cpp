// The test programs' main: GoogleTest's, plus oneTBB's workers joined before exit (see
// core/parallel.hpp: the sanitizer build's leak check must not race their exit).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/parallel.hpp"
#include "render/render_image.hpp"
#include "scene/painter.hpp"

int main(int argc, char** argv) {
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::scene::set_painter(&sansui::render::render_image);  // pictures: scene/painter.hpp
  testing::InitGoogleMock(&argc, argv);
  return RUN_ALL_TESTS();
}
