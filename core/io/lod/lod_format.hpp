#pragma once
// On-disk layout of a level-of-detail cache (docs/IO.md "Level-of-detail cache"): a folder
// per source holding index.plod (header, source stamp, stations, node list, checksum) and
// points.plod (each node's points as columns: x y z as uint32 quanta from the origin,
// station uint16, then intensity float32 and r g b uint8 when the cache has them).
// Little-endian, as written by this host.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/lod/lod_hierarchy.hpp"

namespace plumb {

inline constexpr std::uint32_t kLodFormatVersion = 1;
inline constexpr const char* kLodIndexFile = "index.plod";
inline constexpr const char* kLodPointsFile = "points.plod";
inline constexpr std::size_t kLodPointsHeaderBytes = 16;  ///< magic + version + reserved

/// What identifies the source a cache was built from.
struct LodSourceStamp {
  std::string path;  ///< canonical absolute path
  std::uint64_t size = 0;
  std::int64_t mtime_ns = 0;
  bool operator==(const LodSourceStamp&) const = default;
};

/// Stamp of `source` now. Throws FileError when it cannot be read.
LodSourceStamp lodSourceStamp(const std::filesystem::path& source);

/// <cache_root>/<16 hex digits of a hash of the canonical path>.
std::filesystem::path lodCacheDirectory(const std::filesystem::path& source, const std::filesystem::path& cache_root);

/// Bytes a node of `count` points takes in points.plod.
std::uint64_t lodNodeBytes(std::uint64_t count, bool has_intensity, bool has_rgb);
/// A node's points as stored (columns; see above).
std::string encodeLodPoints(const std::vector<LodPoint>& points, bool has_intensity, bool has_rgb);
/// The header of points.plod.
std::string lodPointsHeader();

struct LodIndex {
  LodSourceStamp source;
  LodHierarchy hierarchy;
  std::uint64_t points_file_bytes = 0;
};

std::string encodeLodIndex(const LodIndex& index);
/// Parses index.plod; throws FileError naming `file`, what is wrong and the byte, for any
/// damage (magic, version, sizes, checksum, node links). Version mismatch: message starts
/// with "format version".
LodIndex decodeLodIndex(const std::string& bytes, const std::filesystem::path& file);

}  // namespace plumb
