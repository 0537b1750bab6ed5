#pragma once
// Parameters and result of building a level-of-detail cache (lod_builder.hpp).
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace plumb {

struct LodCacheParams {
  /// Coordinate quantum, metres: positions are stored as integers of this step from the
  /// cache origin, so a point is kept to half of it (0.05 mm at the default 0.1 mm). The
  /// extent of the file must stay below 2^31 quanta (214 km at 0.1 mm).
  double quantum = 1e-4;
  /// Most points a node holds (a leaf made of more than this many copies of one position
  /// is the only exception). Between 16 and 1,000,000.
  std::size_t node_capacity = 50'000;
  /// Sampling grid of a node, cells per side (a power of two, 16..1024): a node keeps at
  /// most one point per cell, so the spacing at depth d is root side / cells / 2^d.
  std::uint32_t grid_cells = 128;
  /// Memory the build may hold for points, MB (buckets built in memory, spill buffers,
  /// the upper nodes of a streamed split). Larger inputs are spilled to disk.
  double memory_budget_mb = 256;
  /// Points per chunk while streaming the source (StreamOptions::chunk_points).
  std::size_t chunk_points = std::size_t{1} << 16;
};

struct LodCacheBuildResult {
  std::filesystem::path directory;  ///< the cache's folder (lodCacheDirectory)
  std::uint64_t points = 0;         ///< finite points stored
  std::uint64_t skipped = 0;        ///< non-finite points left out
  std::size_t nodes = 0;
  int max_depth = 0;
  std::uint64_t bytes = 0;             ///< index + point data on disk
  std::uint64_t spilled_points = 0;    ///< points written to temporary bucket files (0: built in memory)
  std::size_t largest_in_memory = 0;   ///< most points built in memory at once
  double seconds = 0;
};

}  // namespace plumb
