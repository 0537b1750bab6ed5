#pragma once
// E57 (ASTM E2807) point reader. Rules (see also docs/E57_FORMAT.md):
// - Every data3D entry becomes one Scan: points in the scan's own frame (Scan.cloud), the
//   pose (quaternion + translation) in Scan.pose (has_pose false and identity when absent).
// - Positions: cartesianX/Y/Z, or sphericalRange/Azimuth/Elevation converted with
//   x = r cos(el) cos(az), y = r cos(el) sin(az), z = r sin(el). Integer, ScaledInteger (any
//   bit width 0..64) and Float (single/double) fields are decoded.
// - cartesianInvalidState / sphericalInvalidState: 0 = kept; 2 (or any other value) = dropped;
//   1 = "direction only" (no valid range) is dropped unless keep_direction_only, in which
//   case the point is kept with its stored coordinates and the scalar field "direction_only"
//   (1 for those points, 0 for the others) flags it.
// - cloud.offset: the centre of the first decoded block of points, rounded to whole metres,
//   so georeferenced coordinates keep sub-millimetre precision in float.
// - Attributes: intensity (as stored; NaN where isIntensityInvalid=1; limits reported in
//   metadata), colours scaled from colorLimits (or the field's range) to 8 bits,
//   rowIndex/columnIndex -> row/column with grid_rows/grid_columns = index extent (points are
//   not a full grid when invalid points were dropped: use row/column), normals (extension
//   fields *:normalX/Y/Z), returnIndex (0-based in E57, stored +1 like LAS) / returnCount,
//   timeStamp (NaN where isTimeStampInvalid=1), classification (any prefix). Other numeric
//   fields are kept as scalar fields under their E57 name. Images2D are skipped.
// - isColorInvalid = 1: colour 0 and color_invalid = 1 for that point; a scan without any
//   valid colour has no colour column.
// - A data3D without coordinates in its prototype is skipped with a "warning" metadata entry;
//   the file fails only when no scan has coordinates.
// - Every page read has its CRC-32C checked. Any inconsistency is a FileError naming the
//   file, what is wrong and where (byte offset, page, XML element path); counts are validated
//   against the file size before any allocation.
#include <cstddef>
#include <filesystem>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"
#include "model/dataset.hpp"

namespace plumb {

struct E57ReadOptions {
  /// Keep points whose invalid state is 1 (direction only), flagged in "direction_only".
  bool keep_direction_only = false;
};

Dataset readE57(const std::filesystem::path& path, const E57ReadOptions& options = {},
                Progress* progress = nullptr);

/// Streams the file to `sink` (io/stream/chunk_sink.hpp): scan by scan, in chunks decoded
/// exactly as readE57 decodes them (same offset and values), one compressed-vector packet and
/// one chunk in memory at a time. The metadata, skipped scans and errors are readE57's.
void streamE57(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress = nullptr);

/// Reads an E57 image held in memory (fuzzing, embedded data). `name` is used in messages.
Dataset readE57FromMemory(const void* data, std::size_t size, const std::filesystem::path& name,
                          const E57ReadOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
