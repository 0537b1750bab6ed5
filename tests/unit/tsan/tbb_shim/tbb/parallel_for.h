#pragma once
// ThreadSanitizer tree only: see shim_threads.h.
#include <cstddef>
#include <type_traits>

#include "tbb/blocked_range.h"
#include "tbb/shim_threads.h"

namespace tbb {

template <class Index, class F, class = std::enable_if_t<std::is_integral_v<Index>>>
void parallel_for(Index first, Index last, const F& f) {
  shim_detail::forChunks(first, last, 1, [&](std::size_t, Index lo, Index hi) {
    for (Index i = lo; i < hi; ++i) f(i);
  });
}

template <class Value, class Body>
void parallel_for(const blocked_range<Value>& range, const Body& body) {
  shim_detail::forChunks(range.begin(), range.end(), range.grainsize(),
                         [&](std::size_t, Value lo, Value hi) { body(blocked_range<Value>(lo, hi, range.grainsize())); });
}

}  // namespace tbb
