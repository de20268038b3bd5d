// Storage for the big arrays of subdivision: vectors whose elements are left unset on resize
// (every step writes each element itself, so zero-filling would be a wasted pass over hundreds
// of megabytes). Deliberately not on transparent huge pages (unlike Grid): measured on the
// shared 2-core machine, a fresh `sansui subdivide` process spent 1.0-1.8 s instead of 0.63 s in
// 8 steps with MADV_HUGEPAGE, the kernel compacting memory on every first touch; only repeated
// runs in one process gained (0.41 s).
#pragma once

#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace sansui::mesh {

template <class T>
struct BigAllocator {
  using value_type = T;
  BigAllocator() = default;
  template <class U>
  BigAllocator(const BigAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = (n * sizeof(T) + 63) / 64 * 64;
    void* memory = std::aligned_alloc(64, bytes == 0 ? 64 : bytes);
    if (memory == nullptr) throw std::bad_alloc();
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
