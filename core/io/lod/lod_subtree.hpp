#pragma once
// Builds the nodes of one octree cell from its points in memory (docs/IO.md
// "Level-of-detail cache"): a node of at most `capacity` points, or at the deepest level,
// is a leaf holding them all; otherwise it keeps its grid sample (lod_sample.hpp) and
// hands the rest to its children, in order.
#include <cstddef>
#include <vector>

#include "io/lod/lod_node_output.hpp"

namespace plumb {

/// Writes `key`'s node and its descendants to `out`. `points` all lie inside `key`.
void buildLodSubtree(const LodGrid& grid, const LodKey& key, std::vector<LodPoint> points, std::size_t capacity,
                     LodNodeOutput& out);

}  // namespace plumb
