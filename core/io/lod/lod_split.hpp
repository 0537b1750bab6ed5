#pragma once
// A streamed split of an octree cell too large for memory (docs/IO.md "Level-of-detail
// cache"): points go by, each is offered to the samples of the cell's nodes `levels` deep
// (the same first-come rule as buildLodSubtree), and what no node keeps is appended to the
// temporary bucket file of its cell `levels` below, to be built (or split again) later.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "io/lod/lod_node_output.hpp"
#include "io/lod/lod_sample.hpp"

namespace plumb {

struct LodBucket {
  LodKey key;
  std::filesystem::path file;
  std::uint64_t count = 0;
};

class LodSplit {
 public:
  /// `levels` (1..3) node levels kept in memory below and including `top`; bucket files
  /// go to `dir`, each buffered up to `buffer_points` points.
  LodSplit(const LodGrid& grid, const LodKey& top, int levels, std::size_t capacity, std::filesystem::path dir,
           std::size_t buffer_points);
  void add(const LodPoint& p);
  /// Writes the in-memory nodes to `out` and returns the non-empty buckets in order.
  std::vector<LodBucket> finish(LodNodeOutput& out);
  std::uint64_t spilled() const { return spilled_; }

 private:
  std::size_t nodeIndex(const LodPoint& p, int level) const;
  void flush(std::size_t bucket);

  LodGrid grid_;
  LodKey top_;
  int levels_;
  std::size_t capacity_, buffer_points_;
  std::filesystem::path dir_;
  std::vector<std::unique_ptr<LodNodeSample>> nodes_;  ///< level by level, x fastest
  std::vector<std::vector<LodPoint>> buffers_;
  std::vector<std::uint64_t> counts_;
  std::uint64_t spilled_ = 0;
};

/// Reads a bucket file whole (`count` records). Throws FileError naming it.
std::vector<LodPoint> readLodBucket(const LodBucket& bucket);
/// Hands a bucket file's points to `add` in blocks, then removes the file.
template <class F>
void streamLodBucket(const LodBucket& bucket, F&& add);
/// One block of a bucket file from record `first` (at most `n` records).
std::vector<LodPoint> readLodBucketBlock(const LodBucket& bucket, std::uint64_t first, std::size_t n);

template <class F>
void streamLodBucket(const LodBucket& bucket, F&& add) {
  constexpr std::size_t kBlock = 1 << 16;
  for (std::uint64_t first = 0; first < bucket.count; first += kBlock)
    for (const LodPoint& p : readLodBucketBlock(bucket, first, kBlock)) add(p);
  std::filesystem::remove(bucket.file);
}

}  // namespace plumb
