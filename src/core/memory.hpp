// How much memory the machine has for us now, and the limit that sizes read from files and
// options are checked against before anything is allocated (`--max-memory`).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace sansui {

/// Bytes of memory available now (Linux MemAvailable), or the physical memory if that is unknown.
std::size_t available_memory_bytes();

/// The most memory one allocation decided by outside data (a declared image size, a vertex
/// count, a grid size) may take: by default 3/4 of the physical memory. A process-wide setting,
/// like the thread count: the CLI sets it from --max-memory, the fuzz targets lower it.
std::size_t memory_limit_bytes();
void set_memory_limit_bytes(std::size_t bytes);

/// Throws InputError unless `bytes` fit the limit: "`what` needs X GB, more than the memory
/// limit of Y GB (--max-memory)". Call it before the allocation. A memory-only budget::check
/// (core/budget.hpp), where stages that also estimate their time check both.
void check_memory(double bytes, std::string_view what);

/// Sizes from which big arrays ask for transparent huge pages. [Units: bytes]
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;
inline constexpr std::size_t huge_array_bytes = std::size_t{4} << 20;

/// Asks the kernel for transparent huge pages (where it allows them on request: "madvise"
/// mode) over the 2 MB pages lying wholly inside [memory, memory + bytes), before anything
/// touches them. A hint, for big arrays written in full: their first touch then costs one fault
/// per 2 MB instead of one per 4 kB, which on a virtual machine is much of the time of filling
/// fresh memory (see mesh/buffer.hpp).
void advise_huge_pages(void* memory, std::size_t bytes);

/// v.reserve(count), with the storage on huge pages (advise_huge_pages) when it is at least
/// huge_array_bytes; call it on an empty vector before filling it.
template <class T>
void reserve_on_huge_pages(std::vector<T>& v, std::size_t count) {
  v.reserve(count);
  if (count * sizeof(T) >= huge_array_bytes) advise_huge_pages(v.data(), count * sizeof(T));
}

/// v.resize(count), where a vector that must grow takes fresh storage on huge pages
/// (reserve_on_huge_pages): for working arrays kept between calls and read out of order, where
/// 4 kB pages cost a TLB miss on most reads. The contents are not kept when it grows.
template <class T>
void resize_on_huge_pages(std::vector<T>& v, std::size_t count) {
  if (v.capacity() < count) {
    std::vector<T>().swap(v);
    reserve_on_huge_pages(v, count);
  }
  v.resize(count);
}

}  // namespace sansui
