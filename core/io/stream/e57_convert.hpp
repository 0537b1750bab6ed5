#pragma once
// Streamed conversion to E57 (docs/IO.md): each scan is gathered from its chunks, moved by
// the transform through its pose (T * pose; the points stay in the scan frame, as
// convertDataset does) and written by E57StreamWriter as soon as it ends, then released. The
// E57 prototype needs a scan's bounds and limits before its first value, so one scan is the
// unit held in memory: the largest station, never the campaign.
#include <filesystem>

#include "io/stream/point_convert.hpp"

namespace plumb {
class E57StreamWriter;
}

namespace plumb {

/// Converts `in` (any point file streamDataset reads) to the E57 file `out`, or one E57 file
/// per scan (params.split). Errors as convertPointFile; an error leaves no output of the
/// failing file (earlier scans of a split stay).
ConvertResult convertToE57Streamed(const std::filesystem::path& in, const std::filesystem::path& out,
                                   const ConvertParams& params, Progress* progress = nullptr);

/// A scan's new name and pose (scan frame -> output frame) for appendRePosedScans.
struct ScanHeader {
  std::string name;
  RigidTransform pose;
};

/// Streams every scan k of `in` into `writer` under headers[k]'s name and pose: the points
/// stay in the scan's frame, only the pose changes (the network's registered stations at full
/// resolution, one scan held at a time). Throws FileError as streamDataset, and naming `in`
/// when it no longer holds headers.size() scans.
void appendRePosedScans(const std::filesystem::path& in, E57StreamWriter& writer,
                        const std::vector<ScanHeader>& headers, const StreamOptions& options = {},
                        Progress* progress = nullptr);

}  // namespace plumb
