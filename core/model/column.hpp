#pragma once
// Storage of a per-point attribute column: a std::vector whose resize(n) leaves new values of
// trivial types uninitialised (default-initialised) instead of zeroing them. Readers size a
// column and then write every value, so zeroing first would only add a pass over memory that
// the kernel has just zeroed: for a 10M-point PLY read that pass was 70 MB of extra writes and
// ~7% of the CPU time (measured with perf, tests/bench/ply). resize(n, value), assign() and
// push_back() behave as usual; code that relies on new values being zero must say so with
// resize(n, 0).
#include <memory>
#include <utility>
#include <vector>

namespace plumb {

/// std::allocator whose value-initialising construct() default-initialises instead.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  using std::allocator<T>::allocator;
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::construct_at(p, std::forward<Args>(args)...);
  }
};

template <class T>
using Column = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace plumb
