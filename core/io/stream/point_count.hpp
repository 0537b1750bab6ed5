#pragma once
// How many points a point file holds, known before reading it (to decide between reading it
// whole and streaming it): from the header where the format has one (E57 record counts, LAS
// point count, PLY vertex count), else from the file size.
#include <cstdint>
#include <filesystem>

namespace plumb {

struct PointCountEstimate {
  std::uint64_t points = 0;  ///< records the header declares, or an upper estimate
  bool from_header = false;  ///< false: estimated from the file size
  bool model = false;        ///< the file holds a model (model format, PLY with faces)
};

/// Errors are readDataset's FileErrors for a missing or unreadable file or a bad header.
PointCountEstimate estimatePointCount(const std::filesystem::path& path);

}  // namespace plumb
