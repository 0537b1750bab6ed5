#pragma once
// ThreadSanitizer tree only (PLUMB_TSAN puts tests/unit/tsan/tbb_shim first on the include
// path): the few TBB algorithms the core uses, run on plain std::threads so that TSan sees every
// hand-off (thread start and join) and checks our loop bodies for data races. Debian's libtbb
// is not instrumented: with it, TSan sees no ordering between the code before a parallel_for
// and the worker running its body, and reports hundreds of false races (measured: 458 on the
// segment tests). Each call splits its range into at most 16 chunks (no smaller than the grain)
// and runs them on 4 threads, so that neighbouring chunks really do run at the same time.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace tbb::shim_detail {

inline constexpr std::size_t kThreads = 4;
inline constexpr std::size_t kMaxChunks = 16;

/// Chunks of [0, n) no smaller than `grain`, at most kMaxChunks.
inline std::size_t chunkCount(std::size_t n, std::size_t grain) {
  return std::clamp<std::size_t>(n / std::max<std::size_t>(grain, 1), 1, kMaxChunks);
}

/// Runs f(c, lo, hi) for chunk c = [lo, hi) of [first, last), on kThreads threads.
template <class Index, class F>
void forChunks(Index first, Index last, std::size_t grain, const F& f) {
  if (!(first < last)) return;
  const std::size_t n = std::size_t(last - first);
  const std::size_t chunks = chunkCount(n, grain);
  const std::size_t threads = std::min(kThreads, chunks);
  auto lo = [&](std::size_t c) { return Index(first + Index(n * c / chunks)); };
  std::vector<std::thread> pool;
  for (std::size_t t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (std::size_t c = t; c < chunks; c += threads) f(c, lo(c), lo(c + 1));
    });
  for (auto& th : pool) th.join();
}

}  // namespace tbb::shim_detail
