// parallel_sort, the part of the parallel seam (core/parallel.hpp) that must stay a template
// over the iterators: apart, so that only the few files that sort parse oneTBB's sort.
#pragma once

#include <algorithm>
#include <functional>

#if !defined(SANSUI_PARALLEL_SERIAL) && !defined(SANSUI_PARALLEL_THREADS)
#include <tbb/parallel_sort.h>
#endif

namespace sansui {

/// Sorts [first, last) by `compare`, not stably: give it a total order (ties broken by index or
/// unique keys) and the order is the same in either back end and with any number of threads.
template <class RandomIt, class Compare = std::less<>>
void parallel_sort(RandomIt first, RandomIt last, Compare compare = {}) {
#if defined(SANSUI_PARALLEL_SERIAL) || defined(SANSUI_PARALLEL_THREADS)  // the few sorts are not worth a parallel one
  std::sort(first, last, compare);
#else
  tbb::parallel_sort(first, last, compare);
#endif
}

}  // namespace sansui
