#include "core/grid.hpp"

#include <new>

namespace sansui {

// Cache-line aligned, for vector loads. (Transparent huge pages were tried for big grids: they
// saved page faults but fresh processes spent as long compacting memory, so they are not asked for.)
void* allocate_samples(std::size_t bytes) {
  constexpr std::size_t alignment = 64;
  const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
  void* memory = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

}  // namespace sansui
