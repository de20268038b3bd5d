// How much memory the machine has for us now, for checks that refuse work that cannot fit.
#pragma once

#include <cstddef>

namespace sansui {

/// Bytes of memory available now (Linux MemAvailable), or the physical memory if that is unknown.
std::size_t available_memory_bytes();

}  // namespace sansui
