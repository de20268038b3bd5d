// Storage for the big arrays of subdivision: vectors whose elements are left unset on resize
// (every step writes each element itself, so zero-filling would be a wasted pass over hundreds
// of megabytes). Arrays of 4 MB and more are aligned to 2 MB and ask for transparent huge pages
// (core/memory.hpp). An earlier measurement found huge pages slower in a fresh process (1.0-1.8 s
// against 0.63 s, the kernel compacting memory on first touch); measured again on the shared
// 2-core machine (load 3-4), a whole `sansui subdivide ... --steps 8 -o m.glb` took 175,000 page
// faults and 4.2-5.0 s with 4 kB pages against 15,000 faults and 2.6-2.7 s with every big array on
// huge pages: on this virtual machine each 4 kB first touch costs microseconds.
#pragma once

#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/memory.hpp"

namespace sansui::mesh {

template <class T>
struct BigAllocator {
  using value_type = T;
  BigAllocator() = default;
  template <class U>
  BigAllocator(const BigAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t alignment = n * sizeof(T) >= huge_array_bytes ? huge_page_bytes : 64;
    const std::size_t bytes = (n * sizeof(T) + alignment - 1) / alignment * alignment;
    void* memory = std::aligned_alloc(alignment, bytes == 0 ? alignment : bytes);
    if (memory == nullptr) throw std::bad_alloc();
    if (alignment == huge_page_bytes) advise_huge_pages(memory, bytes);
    return static_cast<T*>(memory);
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
  /// Default-initialisation: plain data stays unset until written.
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  bool operator==(const BigAllocator<U>&) const noexcept {
    return true;
  }
};

/// A vector for the big arrays of a mesh.
template <class T>
using Buffer = std::vector<T, BigAllocator<T>>;

}  // namespace sansui::mesh
