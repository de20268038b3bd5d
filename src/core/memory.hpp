// How much memory the machine has for us now, and the limit that sizes read from files and
// options are checked against before anything is allocated (`--max-memory`).
#pragma once

#include <cstddef>
#include <string_view>

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

}  // namespace sansui
