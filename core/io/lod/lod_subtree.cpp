#include "io/lod/lod_subtree.hpp"

#include <array>

#include "io/lod/lod_sample.hpp"

namespace plumb {

void buildLodSubtree(const LodGrid& grid, const LodKey& key, std::vector<LodPoint> points, std::size_t capacity,
                     LodNodeOutput& out) {
  if (points.empty()) return;
  if (points.size() <= capacity || key.depth >= grid.levels) {
    out.write(key, points);
    return;
  }
  std::array<std::vector<LodPoint>, 8> children;
  {
    LodNodeSample sample;
    for (const LodPoint& p : points)
      if (!sample.offer(grid, key.depth, p, capacity)) children[grid.octant(p, key.depth)].push_back(p);
    std::vector<LodPoint>().swap(points);
    out.write(key, sample.points);
  }
  for (int o = 0; o < 8; ++o) buildLodSubtree(grid, key.child(o), std::move(children[o]), capacity, out);
}

}  // namespace plumb
