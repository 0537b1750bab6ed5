#pragma once
// ThreadSanitizer tree only: see shim_threads.h.
#include <cstddef>

namespace tbb {

template <class Value>
class blocked_range {
 public:
  using const_iterator = Value;
  blocked_range(Value begin, Value end, std::size_t grainsize = 1) : begin_(begin), end_(end), grain_(grainsize) {}
  Value begin() const { return begin_; }
  Value end() const { return end_; }
  std::size_t size() const { return std::size_t(end_ - begin_); }
  std::size_t grainsize() const { return grain_; }
  bool empty() const { return !(begin_ < end_); }

 private:
  Value begin_, end_;
  std::size_t grain_;
};

}  // namespace tbb
