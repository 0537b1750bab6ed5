#pragma once
// The intensity range of each scan of a point file, gathered in one streamed pass: what a LAS
// conversion needs before its first record when the intensity is fractional and the file
// declares no limits (writeLas then scales by the data's own min/max, las_point_fields.hpp).
#include <filesystem>
#include <limits>
#include <vector>

#include "common/progress.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

struct ScanIntensityRange {
  double lo = std::numeric_limits<double>::infinity();  ///< of the finite values
  double hi = -std::numeric_limits<double>::infinity();
  bool integral = true;  ///< every finite value a whole number within 0..65535
  void extend(const ScanIntensityRange& o);
};

/// One entry per scan (StreamScan::index order); scans without intensity keep the defaults.
std::vector<ScanIntensityRange> intensityRanges(const std::filesystem::path& path, const StreamOptions& options,
                                                Progress* progress = nullptr);

}  // namespace plumb
