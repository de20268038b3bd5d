// Storage for the big arrays of subdivision: vectors whose elements are left unset on resize
// (every step writes each element itself, so zero-filling would be a wasted pass over hundreds
// of megabytes) and which live on transparent huge pages when large (see allocate_samples),
// which saves most page faults on the first write.
#pragma once

#include <cstdlib>
#include <new>
#include <vector>

#include "core/grid.hpp"

namespace sansui::mesh {

template <class T>
struct BigAllocator {
  using value_type = T;
  BigAllocator() = default;
  template <class U>
  BigAllocator(const BigAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) { return static_cast<T*>(allocate_samples(n * sizeof(T))); }
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
