#include "solid/volume.hpp"

#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sansui::solid {

Volume::Volume(int levels) : levels_(levels), side_((1 << levels) + 1) {
  assert(levels >= 0 && levels <= 12);
  plane_ = static_cast<std::size_t>(side_) * static_cast<std::size_t>(side_);
  // Large lattices are aligned to 2 MB and asked to live on huge pages: a 513^3 lattice is half
  // a gigabyte, and 4 kB pages would cost more page faults than the fill itself.
  constexpr std::size_t huge_page = std::size_t{2} << 20;
  const std::size_t wanted = bytes();
  const std::size_t alignment = wanted >= huge_page ? huge_page : 64;
  const std::size_t rounded = (wanted + alignment - 1) / alignment * alignment;
  void* memory = std::aligned_alloc(alignment, rounded);
  if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (alignment == huge_page) ::madvise(memory, rounded, MADV_HUGEPAGE);
#endif
  data_.reset(static_cast<float*>(memory));
}

}  // namespace sansui::solid
