#pragma once
// Where a build puts finished nodes: their points appended to points.plod as they come, and
// the node list put in depth-first order at the end (lod_hierarchy.hpp).
#include <filesystem>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "common/atomic_file.hpp"
#include "io/lod/lod_hierarchy.hpp"

namespace plumb {

class LodNodeOutput {
 public:
  /// Opens `points_file` (written atomically: committed by commit()).
  LodNodeOutput(const std::filesystem::path& points_file, bool has_intensity, bool has_rgb);
  /// Appends a node's points (non-empty; a key written once).
  void write(const LodKey& key, const std::vector<LodPoint>& points);
  /// Nodes in depth-first order, children in octant order, with parent/child links.
  std::vector<LodNode> nodes(const LodGrid& grid) const;
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t points() const { return points_; }
  void commit() { file_.commit(); }

 private:
  struct Entry {
    std::uint64_t offset = 0, count = 0;
  };
  using MapKey = std::tuple<int, std::uint32_t, std::uint32_t, std::uint32_t>;
  static MapKey mapKey(const LodKey& k) { return {k.depth, k.xyz[0], k.xyz[1], k.xyz[2]}; }
  void visit(const LodGrid& grid, const LodKey& key, std::uint32_t parent, std::vector<LodNode>& out) const;

  AtomicFileWriter file_;
  bool has_intensity_, has_rgb_;
  std::map<MapKey, Entry> entries_;
  std::uint64_t bytes_ = 0, points_ = 0;
};

}  // namespace plumb
