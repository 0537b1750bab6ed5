// A deliberate data race inside a TBB loop (every iteration increments one plain int from
// whichever thread runs it), built only in the ThreadSanitizer tree. tsan_parallel.cmake runs it
// and requires TSan to report the race: proof that the tree's TBB (tbb_shim) runs loop bodies
// concurrently and that the suppressions do not hide races in our lambdas.
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <thread>

int main() {
  int shared = 0;
  tbb::parallel_for(0, 64, [&](int) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ++shared;
  });
  std::printf("%d\n", shared);
  return 0;
}
