#pragma once
// The sample a node keeps (docs/IO.md "Level-of-detail cache"): the first point to reach
// each free cell of the node's grid, until the node holds `capacity` points. Decisions depend
// only on the points offered before, so a stream and an in-memory build choose alike.
#include <cstdint>
#include <vector>

#include "io/lod/lod_grid.hpp"

namespace plumb {

/// A set of cell keys (open addressing, linear probing; keys below 2^30).
class LodCellSet {
 public:
  /// True when `key` was absent (and is now present).
  bool insert(std::uint32_t key);
  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  void grow();
  std::vector<std::uint32_t> slots_;
  std::size_t size_ = 0;
};

struct LodNodeSample {
  std::vector<LodPoint> points;
  LodCellSet cells;
  /// Keeps p when the node has room and p's cell is free; false: p goes to a child.
  bool offer(const LodGrid& grid, int depth, const LodPoint& p, std::size_t capacity) {
    if (points.size() >= capacity || !cells.insert(grid.cell(p, depth))) return false;
    points.push_back(p);
    return true;
  }
};

}  // namespace plumb
