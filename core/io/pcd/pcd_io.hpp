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
#include <filesystem>

#include "common/progress.hpp"
#include "model/dataset.hpp"

namespace plumb {

/// Throws FileError (file, what, where) for malformed headers, truncated data, bad LZF blocks.
Dataset readPcd(const std::filesystem::path& path, Progress* progress = nullptr);

/// The header and size checks readPcd runs before PCL reads the file: throws FileError when
/// the header is malformed or the data section cannot hold what it declares. (fuzz_pcd.)
void checkPcdHeader(const std::filesystem::path& path);

struct PcdWriteOptions {
  bool compressed = true;  ///< binary_compressed (LZF); false: binary
};

/// Writes x y z as F4 when the cloud's offset is zero, else as F8 world coordinates; rgb
/// packed in an F4 (PCL convention); organized clouds keep WIDTH/HEIGHT. Atomic.
void writePcd(const std::filesystem::path& path, const PointCloud& cloud,
              const PcdWriteOptions& options = {}, Progress* progress = nullptr);

}  // namespace plumb
