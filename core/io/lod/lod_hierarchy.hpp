#pragma once
// The node list of a level-of-detail cache (docs/IO.md "Level-of-detail cache"): what the
// viewer needs to choose nodes (selectLodNodes) before reading any point.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "io/lod/lod_grid.hpp"

namespace plumb {

inline constexpr std::uint32_t kNoLodNode = 0xffffffffu;

struct LodNode {
  std::uint32_t id = 0;              ///< index in LodHierarchy::nodes
  std::uint32_t parent = kNoLodNode;
  std::array<std::uint32_t, 8> children{kNoLodNode, kNoLodNode, kNoLodNode, kNoLodNode,
                                        kNoLodNode, kNoLodNode, kNoLodNode, kNoLodNode};  ///< by octant
  LodKey key;                        ///< depth and integer position in the octree
  Bounds bounds;                     ///< the node's cube, dataset frame (metres)
  double spacing = 0;                ///< distance between the node's samples, metres
  std::uint64_t point_count = 0;     ///< points of this node alone (not its children)
  std::uint64_t data_offset = 0;     ///< byte of its points in the point data file
  int depth() const { return key.depth; }
  bool leaf() const {
    for (const std::uint32_t c : children)
      if (c != kNoLodNode) return false;
    return true;
  }
};

struct LodStation {
  std::string name;
  bool has_intensity = false;
  bool has_rgb = false;
};

struct LodHierarchy {
  LodGrid grid;
  Bounds bounds;                      ///< of the points, dataset frame
  std::vector<LodStation> stations;   ///< by station index (the scan's index in the file)
  bool has_intensity = false;         ///< some station has intensity (others read NaN)
  bool has_rgb = false;               ///< some station has colour (others read 0, 0, 0)
  std::uint64_t points = 0;
  std::uint32_t node_capacity = 0;
  /// Depth-first, children in octant order: nodes[0] is the root, a parent comes before its
  /// children. Empty when the file has no finite point.
  std::vector<LodNode> nodes;
};

}  // namespace plumb
