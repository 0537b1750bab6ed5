#pragma once
// Storage of a per-point attribute column: a std::vector with two differences that matter for
// clouds of tens of millions of points.
// - resize(n) value-initialises (zeros) like any std::vector. Readers, which size a column and
//   then write every value, call resizeForOverwrite(column, n) instead: new values of trivial
//   types stay uninitialised. Zeroing first would only add a pass over memory the kernel has
//   just zeroed: for a 10M-point PLY read that pass was 70 MB of extra writes and ~7% of the
//   CPU time (perf, tests/bench/ply). The uninitialised sizing is explicit and local to the
//   call, so no other code can read garbage by accident.
// - Blocks of 4 MiB and more are mapped 2 MiB-aligned and marked for transparent huge pages
//   (Linux, THP in "madvise" or "always" mode): the first touch of a huge column takes one
//   page fault per 2 MiB instead of 512, and no partial 2 MiB at either end falls back to
//   4 KiB pages (malloc's unaligned mappings left up to 4 MB of each column in small pages).
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace plumb {

namespace column_memory {
/// Blocks from this size on are mapped by allocateLarge.
inline constexpr std::size_t kLargeBytes = std::size_t{4} << 20;
/// A 2 MiB-aligned anonymous mapping of `bytes` (throws std::bad_alloc).
void* allocateLarge(std::size_t bytes);
void freeLarge(void* p, std::size_t bytes) noexcept;
/// Set only inside resizeForOverwrite on this thread: construct() then default-initialises.
inline thread_local bool overwrite_next_resize = false;
}  // namespace column_memory

/// std::allocator whose value-initialising construct() default-initialises inside
/// resizeForOverwrite, and which maps large blocks 2 MiB-aligned for huge pages. Stateless:
/// all instances are equal.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  using value_type = T;
  DefaultInitAllocator() noexcept = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };

  T* allocate(std::size_t n) {
    if (n * sizeof(T) >= column_memory::kLargeBytes && n <= static_cast<std::size_t>(-1) / sizeof(T))
      return static_cast<T*>(column_memory::allocateLarge(n * sizeof(T)));
    return std::allocator<T>::allocate(n);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) >= column_memory::kLargeBytes) column_memory::freeLarge(p, n * sizeof(T));
    else std::allocator<T>::deallocate(p, n);
  }

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    if (column_memory::overwrite_next_resize) {
      ::new (static_cast<void*>(p)) U;
    } else if constexpr (requires { U::Zero(); }) {
      ::new (static_cast<void*>(p)) U;  // Eigen's value-initialisation leaves values unset
      *p = U::Zero();
    } else {
      ::new (static_cast<void*>(p)) U();
    }
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::construct_at(p, std::forward<Args>(args)...);
  }
};

template <class T, class U>
bool operator==(const DefaultInitAllocator<T>&, const DefaultInitAllocator<U>&) noexcept {
  return true;
}

template <class T>
using Column = std::vector<T, DefaultInitAllocator<T>>;

/// Resizes `column` to n leaving new values of trivial types uninitialised: for readers that
/// write every value right after. Anything else uses resize (zeros).
template <class T>
void resizeForOverwrite(Column<T>& column, std::size_t n) {
  struct Scope {
    Scope() { column_memory::overwrite_next_resize = true; }
    ~Scope() { column_memory::overwrite_next_resize = false; }
  } scope;
  column.resize(n);
}

/// Any other vector (a column not stored as Column<T>): an ordinary, zeroing resize.
template <class T, class A>
void resizeForOverwrite(std::vector<T, A>& v, std::size_t n) {
  v.resize(n);
}

}  // namespace plumb
