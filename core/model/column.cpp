#include "model/column.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace plumb::column_memory {
namespace {

constexpr std::size_t kHuge = std::size_t{2} << 20;
constexpr std::size_t kPage = 4096;

std::size_t pagesOf(std::size_t bytes) { return (bytes + kPage - 1) & ~(kPage - 1); }

}  // namespace

void* allocateLarge(std::size_t bytes) {
  // Map 2 MiB more than needed, then unmap the unaligned head and the tail beyond the block.
  const std::size_t size = pagesOf(bytes);
  void* raw = ::mmap(nullptr, size + kHuge, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto base = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (base + kHuge - 1) & ~(kHuge - 1);
  if (aligned > base) ::munmap(raw, aligned - base);
  const std::uintptr_t end = base + size + kHuge;
  if (end > aligned + size) ::munmap(reinterpret_cast<void*>(aligned + size), end - (aligned + size));
#ifdef MADV_HUGEPAGE
  ::madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // a hint: harmless if refused
#endif
  return reinterpret_cast<void*>(aligned);
}

void freeLarge(void* p, std::size_t bytes) noexcept {
  if (p) ::munmap(p, pagesOf(bytes));
}

}  // namespace plumb::column_memory
