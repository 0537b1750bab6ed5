#include "common/temp_file_registry.hpp"

#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstring>

namespace plumb::temp_files {
namespace {

enum State : int { kFree = 0, kFilling = 1, kLive = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};

constexpr int kSlots = 32;
Slot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

}  // namespace

int add(const char* path) noexcept {
  const std::size_t len = std::strlen(path);
  if (len >= PATH_MAX) return -1;
  for (int k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (!g_slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(g_slots[k].path, path, len + 1);
    g_slots[k].state.store(kLive);
    return k;
  }
  return -1;
}

void remove(int slot) noexcept {
  if (slot >= 0 && slot < kSlots) g_slots[slot].state.store(kFree);
}

void unlinkAll() noexcept {
  for (auto& s : g_slots)
    if (s.state.load() == kLive) ::unlink(s.path);
}

}  // namespace plumb::temp_files
