#pragma once
// The streaming read interface (docs/IO.md): a reader hands a file to a ChunkSink
// scan by scan, in chunks of at most StreamOptions::chunk_points points, so a consumer
// (statistics, conversion, splitting, subsampling) never holds a whole scan. Header-only so
// every format module can implement it without depending on the dispatcher.
//
// Order of calls: begin(outline) once; for each scan beginScan, chunk... (possibly none),
// endScan; end(outline) once. A chunk carries every field the whole-file reader gives that
// scan (positions with the exact double coordinate: offset + positions + position_residuals,
// intensity, colour, extras...), in the scan's own frame (apply Scan::pose for the dataset
// frame). Per-scan decisions readDataset takes after seeing every point (an E57 scan whose
// colours are all invalid loses its colour column; LAS fields that are 0 everywhere have no
// column) are reported in StreamScanEnd, not applied to the chunks.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/dataset.hpp"

namespace plumb {

struct StreamOptions {
  /// Most points per chunk (values below 4096 are raised to 4096). Default 256 Ki points:
  /// 9-16 MB of columns for a typical scanner prototype (x y z, residuals, intensity, row,
  /// column, colour).
  std::size_t chunk_points = std::size_t{1} << 18;
  /// E57: keep direction-only points (ReadOptions::keep_direction_only).
  bool keep_direction_only = false;
};

/// One scan, before its points.
struct StreamScan {
  std::size_t index = 0;  ///< position in Dataset::scans (skipped E57 scans are not counted)
  Scan scan;              ///< name, guid, description, pose, has_pose; empty cloud
  /// Records the file holds for this scan (the points delivered may be fewer: E57 invalid
  /// records are dropped); empty when the format does not say (ASCII PLY/PCD hold it anyway).
  std::optional<std::uint64_t> record_count;
  std::vector<std::string> fields;  ///< PointCloud::fieldNames() of every chunk
  /// Intensity limits the file declares (E57 intensityLimits or the field's type range).
  std::optional<std::pair<double, double>> intensity_limits;
  /// True when the field's type guarantees whole numbers within 0..65535 (LAS uint16, E57
  /// Integer within those limits, PLY/PCD integer types that fit).
  bool intensity_integral = false;
};

/// What the file holds, before any point.
struct StreamOutline {
  /// Source, format, coordinate system and the metadata known from the header; scans hold
  /// no points (see `scans`). After the last scan (ChunkSink::end) the metadata is complete,
  /// as readDataset gives it.
  Dataset dataset;
  std::vector<StreamScan> scans;  ///< one per scan to come, in order
};

/// One scan, after its points: what readDataset's Scan would show.
struct StreamScanEnd {
  std::size_t index = 0;
  std::uint64_t points = 0;
  std::vector<std::string> fields;  ///< PointCloud::fieldNames() of the scan read whole
  std::int32_t grid_rows = 0, grid_columns = 0;
};

class ChunkSink {
 public:
  virtual ~ChunkSink() = default;
  virtual void begin(const StreamOutline& outline) { (void)outline; }
  virtual void beginScan(const StreamScan& scan) { (void)scan; }
  /// Points of the current scan, in its own frame. Valid only during the call.
  virtual void chunk(const PointCloud& points) = 0;
  virtual void endScan(const StreamScanEnd& end) { (void)end; }
  /// After the last scan: the outline with the complete metadata.
  virtual void end(const StreamOutline& outline) { (void)outline; }
};

/// Chunk size actually used for `options` (at least 4096 points).
inline std::size_t chunkCapacity(const StreamOptions& options) {
  return options.chunk_points < 4096 ? 4096 : options.chunk_points;
}

}  // namespace plumb
