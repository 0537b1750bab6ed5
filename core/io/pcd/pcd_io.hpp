#pragma once
// PCD (PCL's point cloud format) through PCL's PCDReader/PCDWriter: ascii, binary and
// binary_compressed; x y z (F4 or F8), normal_x/y/z, rgb/rgba (packed), intensity; every
// other single-valued field is kept as a ScalarField (multi-valued fields such as
// histograms are skipped and listed in the dataset metadata).
//
// Organized clouds (HEIGHT > 1): all WIDTH x HEIGHT points are kept, including NaN points
// (grid holes), so index = row * grid_columns + column; grid_rows/grid_columns and the
// row/column attributes are set. Consumers drop NaN points with PointCloud::removeNonFinite()
// when they do not need the grid. Unorganized clouds (HEIGHT == 1): points with a non-finite
// coordinate are removed on reading.
// The VIEWPOINT is recorded in the metadata ("viewpoint": tx ty tz qw qx qy qz) and not
// applied to the points (PCL does not apply it either).
//
// Isolation (issue 12): readPcd checks the header and the data size itself (pcd_header.hpp),
// then runs PCL's reader in the plumb-import helper process (plumb-import --pcd FILE,
// io/isolation/), which sends the layout and the raw records back over a pipe
// (pcd_stream.hpp); they are converted where they arrive (pcd_convert.hpp), without PCL.
// A crash inside PCL, the time limit (kPcdBaseSeconds + file size / kPcdBytesPerSecond, or
// PLUMB_IMPORT_TIMEOUT seconds) and the memory limit (3/4 of the physical memory, or
// PLUMB_IMPORT_MEMORY_MB) end in a FileError naming the file, PCL and what happened; Plumb
// itself is unaffected. Cancelling the Progress kills the helper.
#include <filesystem>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"
#include "model/dataset.hpp"

namespace plumb {

/// The helper's time limit for a PCD file: 60 s + 1 s per 5 MB.
constexpr double kPcdBaseSeconds = 60;
constexpr double kPcdBytesPerSecond = 5e6;

/// Throws FileError (file, what, where) for malformed headers, truncated data, bad LZF blocks.
Dataset readPcd(const std::filesystem::path& path, Progress* progress = nullptr);

/// Streaming (issue 16, io/stream/point_stream.hpp): binary and binary_compressed data are read
/// by Plumb itself a chunk of records at a time (pcd_records.hpp: the records where they lie,
/// or one streaming LZF decoder per field), after the same header checks, and converted as
/// readPcd converts them: same offset (the file's first finite points), same columns, same
/// values. Memory: one chunk, whatever the file's size. ASCII data, padding fields ("_") in
/// compressed data and 8-byte integer fields are not streamed: streamPcd returns false
/// without calling the sink, and the caller reads the file whole with readPcd (PCL's ASCII
/// parsing rules, which the two routes would both have to follow, stay PCL's).
bool streamPcd(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress = nullptr);
/// True when streamPcd streams `path` (its header is read and checked; throws FileError).
bool pcdStreamsInChunks(const std::filesystem::path& path);

/// The header and size checks readPcd runs before PCL reads the file: throws FileError when
/// the header is malformed or the data section cannot hold what it declares (pcd_header.hpp).
void checkPcdHeader(const std::filesystem::path& path);

struct PcdWriteOptions {
  bool compressed = true;  ///< binary_compressed (LZF); false: binary
};

/// Writes x y z as F4 when the cloud's offset is zero, else as F8 world coordinates; rgb
/// packed in an F4 (PCL convention); organized clouds keep WIDTH/HEIGHT. Atomic.
void writePcd(const std::filesystem::path& path, const PointCloud& cloud,
              const PcdWriteOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
