#pragma once
// ThreadSanitizer tree only: see shim_threads.h. Sorting runs on the calling thread (the sort
// is TBB's, not ours: nothing of our code to check in it).
#include <algorithm>

namespace tbb {

template <class It>
void parallel_sort(It first, It last) { std::sort(first, last); }

template <class It, class Less>
void parallel_sort(It first, It last, const Less& less) { std::sort(first, last, less); }

}  // namespace tbb
