// A program that runs a recipe file through scene/ and links no renderer: what a tool that only
// makes heightmaps, meshes or vector files links (gl_free_link_test.cpp checks it with ldd).
#include <cstdio>
#include <exception>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"

int main(int argc, char** argv) {
  const sansui::WorkerThreadsJoinedAtExit workers;
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SCENE.toml\n", argv[0]);
    return 2;
  }
  try {
    const sansui::scene::LoadedRecipe loaded = sansui::scene::load_recipe(argv[1]);
    (void)sansui::scene::run_recipe(loaded.recipe);
    return 0;
  } catch (const sansui::InputError& e) {
    std::fprintf(stderr, "recipe_runner: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "recipe_runner: internal error: %s\n", e.what());
    return 1;
  }
}
