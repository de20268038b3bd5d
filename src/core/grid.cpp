#include "core/grid.hpp"

#include <new>

#include <sys/mman.h>

#include "core/memory.hpp"

namespace sansui {

namespace {

constexpr std::size_t huge_page = std::size_t{2} << 20;
constexpr std::size_t huge_grid = std::size_t{32} << 20;  // grids from here on ask for huge pages

}  // namespace

// Cache-line aligned, for vector loads. A big grid is aligned to 2 MB and asks the kernel for
// transparent huge pages (where it allows them on request: "madvise" mode): its first touch then
// costs one fault per 2 MB instead of one per 4 kB, which on virtual machines is most of the time
// of writing a fresh grid.
void* allocate_samples(std::size_t bytes) {
  // Every grid's size comes from outside data (an option, a file's header, a mesh's extent), so
  // each is held to the memory limit: a last line behind the checks the readers and sources make
  // before any work, which name the option or file.
  check_memory(static_cast<double>(bytes), "a grid");
  const std::size_t alignment = bytes >= huge_grid ? huge_page : 64;
  const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
  void* memory = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded);
  if (memory == nullptr) throw std::bad_alloc();
  if (alignment == huge_page) (void)::madvise(memory, rounded, MADV_HUGEPAGE);  // a hint: refusing it changes nothing
  return memory;
}

}  // namespace sansui
