#pragma once
// What a point file holds (points, finite points, bounds, fields, grid, pose, metadata),
// gathered from a stream (point_stream.hpp) in bounded memory: the numbers readDataset then
// Dataset::pointCount / Dataset::bounds / PointCloud::fieldNames give, exactly (bounds
// included: world coordinates with or without their residuals as readDataset would keep them).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

struct ScanStatistics {
  std::string name;
  bool has_pose = false;
  RigidTransform pose;
  std::uint64_t points = 0;
  std::uint64_t finite_points = 0;  ///< points with a finite position
  std::vector<std::string> fields;  ///< PointCloud::fieldNames() of the scan read whole
  std::int32_t grid_rows = 0, grid_columns = 0;
  Bounds bounds;  ///< of the finite points, dataset frame
};

struct DatasetStatistics {
  std::filesystem::path source;
  std::string format;
  std::string coordinate_system;
  std::vector<std::pair<std::string, std::string>> metadata;  ///< as Dataset::metadata
  std::vector<ScanStatistics> scans;
  std::uint64_t points = 0;
  Bounds bounds;  ///< of all scans, dataset frame
};

/// Streams `path` and gathers its statistics.
DatasetStatistics datasetStatistics(const std::filesystem::path& path, const StreamOptions& options = {},
                                    Progress* progress = nullptr);

/// The same statistics of a dataset in memory (consumed: each scan is released once counted).
DatasetStatistics datasetStatistics(Dataset data);

}  // namespace plumb
