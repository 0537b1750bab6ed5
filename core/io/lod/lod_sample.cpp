#include "io/lod/lod_sample.hpp"

namespace plumb {

bool LodCellSet::insert(std::uint32_t key) {
  if (2 * (size_ + 1) > slots_.size()) grow();
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t i = (key * std::size_t{2654435761u}) & mask;; i = (i + 1) & mask) {
    if (slots_[i] == key) return false;
    if (slots_[i] == kEmpty) {
      slots_[i] = key;
      ++size_;
      return true;
    }
  }
}

void LodCellSet::grow() {
  std::vector<std::uint32_t> old(slots_.empty() ? 64 : slots_.size() * 2, kEmpty);
  old.swap(slots_);
  size_ = 0;
  for (const std::uint32_t k : old)
    if (k != kEmpty) insert(k);
}

}  // namespace plumb
