#pragma once
// Opening and reading a level-of-detail cache (docs/IO.md "Level-of-detail cache").
// openLodCache checks the cache against the source (format version, path, size, modification
// time) and against itself (checksum, node links, the point file's size) before anything is
// allocated from it; readNode reads one node with pread, so several threads may read nodes of
// one LodCache at once.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/lod/lod_format.hpp"

namespace plumb {

/// One node's points. world(i) = origin + quantum * quanta[i], exact to quantum / 2 of the
/// source coordinate; positions[i] is the same offset in float metres (for drawing: exact to
/// 2^-24 of the node's half side).
struct LodNodePoints {
  std::uint32_t node = 0;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< the node's centre, on the quantum grid
  double quantum = 0;
  std::vector<std::array<std::int32_t, 3>> quanta;
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::uint16_t> station;  ///< index in LodHierarchy::stations
  std::vector<float> intensity;        ///< empty when the cache has none; NaN for stations without
  std::vector<Rgb8> rgb;               ///< empty when the cache has none; 0 0 0 for stations without

  std::size_t size() const { return quanta.size(); }
  Eigen::Vector3d world(std::size_t i) const {
    return origin + quantum * Eigen::Vector3d(quanta[i][0], quanta[i][1], quanta[i][2]);
  }
  /// A cloud with offset = origin (residuals where float drops more than 1 µm), scan_id =
  /// station, intensity and colours when present.
  PointCloud toPointCloud() const;
};

class LodCache {
 public:
  LodCache(std::filesystem::path directory, LodIndex index, int points_fd);
  ~LodCache();
  LodCache(const LodCache&) = delete;
  LodCache& operator=(const LodCache&) = delete;

  const LodHierarchy& hierarchy() const { return index_.hierarchy; }
  const LodSourceStamp& source() const { return index_.source; }
  const std::filesystem::path& directory() const { return directory_; }
  /// index + point data, bytes.
  std::uint64_t bytesOnDisk() const;
  /// Reads node `id`. Thread-safe. Throws FileError naming points.plod for a short read or
  /// damaged points (a position outside the node, a station out of range), InputError for
  /// an id out of range.
  LodNodePoints readNode(std::uint32_t id) const;

 private:
  std::filesystem::path directory_;
  LodIndex index_;
  int fd_ = -1;
};

enum class LodCacheState {
  valid,
  missing,         ///< no cache for this source
  version,         ///< written by another format version
  source_changed,  ///< the source's size or modification time differs (or it is gone)
  damaged,         ///< unreadable or inconsistent files
};

struct LodCacheOpenResult {
  LodCacheState state = LodCacheState::missing;
  std::string reason;  ///< why it must be rebuilt (file, what, where); empty when valid
  std::shared_ptr<const LodCache> cache;  ///< set when valid
  bool valid() const { return state == LodCacheState::valid; }
};

/// The cache of `source` under `cache_root` if it can be used as is, else why not (never
/// throws for a missing, stale or damaged cache).
LodCacheOpenResult openLodCache(const std::filesystem::path& source, const std::filesystem::path& cache_root);

}  // namespace plumb
