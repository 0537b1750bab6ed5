#pragma once
// ThreadSanitizer tree only: see shim_threads.h. Partial results are joined in range order.
#include <cstddef>
#include <vector>

#include "tbb/blocked_range.h"
#include "tbb/shim_threads.h"

namespace tbb {

template <class Value, class T, class Body, class Join>
T parallel_reduce(const blocked_range<Value>& range, const T& identity, const Body& body, const Join& join) {
  // One slot per chunk, written only by the thread that runs the chunk.
  std::vector<T> results(shim_detail::chunkCount(range.size(), range.grainsize()), identity);
  shim_detail::forChunks(range.begin(), range.end(), range.grainsize(), [&](std::size_t c, Value lo, Value hi) {
    results[c] = body(blocked_range<Value>(lo, hi, range.grainsize()), identity);
  });
  T out = identity;
  for (const T& r : results) out = join(out, r);
  return out;
}

/// The shim's parallel_reduce already joins chunk results in range order.
template <class Value, class T, class Body, class Join>
T parallel_deterministic_reduce(const blocked_range<Value>& range, const T& identity,
                                const Body& body, const Join& join) {
  return parallel_reduce(range, identity, body, join);
}

}  // namespace tbb
