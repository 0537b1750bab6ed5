#pragma once
// Streamed conversion to E57 (docs/IO.md): each scan is gathered from its chunks, moved by
// the transform through its pose (T * pose; the points stay in the scan frame, as
// convertDataset does) and written by E57StreamWriter as soon as it ends, then released. The
// E57 prototype needs a scan's bounds and limits before its first value, so one scan is the
// unit held in memory: the largest station, never the campaign.
#include <filesystem>

#include "io/stream/point_convert.hpp"

namespace plumb {

/// Converts `in` (any point file streamDataset reads) to the E57 file `out`, or one E57 file
/// per scan (params.split). Errors as convertPointFile; an error leaves no output of the
/// failing file (earlier scans of a split stay).
ConvertResult convertToE57Streamed(const std::filesystem::path& in, const std::filesystem::path& out,
                                   const ConvertParams& params, Progress* progress = nullptr);

}  // namespace plumb
