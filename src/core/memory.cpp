#include "core/memory.hpp"

#include <atomic>
#include <cstdint>
#include <fstream>
#include <string>

#include <sys/mman.h>
#include <unistd.h>

#include "core/budget.hpp"

namespace sansui {
namespace {

std::size_t physical_memory_bytes() {
  return static_cast<std::size_t>(::sysconf(_SC_PHYS_PAGES)) * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

std::atomic<std::size_t>& limit() {
  static std::atomic<std::size_t> bytes{physical_memory_bytes() / 4 * 3};
  return bytes;
}

}  // namespace

std::size_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  std::size_t kilobytes = 0;
  while (meminfo >> key >> kilobytes >> unit)
    if (key == "MemAvailable:") return kilobytes * 1024;
  return physical_memory_bytes();
}

std::size_t memory_limit_bytes() {
  return limit().load(std::memory_order_relaxed);
}

void set_memory_limit_bytes(std::size_t bytes) {
  limit().store(bytes, std::memory_order_relaxed);
}

void advise_huge_pages(void* memory, std::size_t bytes) {
  const auto begin = reinterpret_cast<std::uintptr_t>(memory);
  const std::uintptr_t first = (begin + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  const std::uintptr_t last = (begin + bytes) / huge_page_bytes * huge_page_bytes;
  // The aligned start as an offset into the block, not an integer cast back to a pointer.
  if (last > first) (void)::madvise(static_cast<char*>(memory) + (first - begin), last - first, MADV_HUGEPAGE);  // refused: nothing changes
}

void check_memory(double bytes, std::string_view what) {
  budget::Cost cost;
  cost.bytes = bytes;
  cost.what = what;
  budget::check(cost);
}

}  // namespace sansui
