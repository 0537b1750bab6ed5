#pragma once
// Turns the decoded records of one data3D entry into a Scan (rules in e57_reader.hpp).
#include "common/progress.hpp"
#include "io/e57/e57_pages.hpp"
#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_xml.hpp"
#include "io/stream/chunk_sink.hpp"
#include "model/dataset.hpp"

namespace plumb::e57 {

/// True when the prototype of `info` has cartesianX/Y/Z or sphericalRange/Azimuth/Elevation.
bool hasCoordinates(const ScanInfo& info);

/// Reads the points of `info` (scan number `index`) from `file`. Adds facts to `metadata`.
Scan readScan(PagedReader& file, const ScanInfo& info, std::size_t index,
              const E57ReadOptions& options, Progress* progress,
              std::vector<std::pair<std::string, std::string>>& metadata);

/// What a stream consumer knows of scan number `index` (Dataset position `position`) before
/// its points; adds readScan's description of the scan (prototype, records, limits) to
/// `metadata`.
StreamScan streamScanHeader(PagedReader& file, const ScanInfo& info, std::size_t index,
                            std::size_t position, const E57ReadOptions& options,
                            std::vector<std::pair<std::string, std::string>>& metadata);

/// Hands the points of `info` to `sink` in chunks of at most max(chunk_points, one decoded
/// block) points, decoded as readScan decodes them (same offset, same values). Adds what
/// readScan adds to `metadata` after the points (invalid colours).
StreamScanEnd streamScan(PagedReader& file, const ScanInfo& info, std::size_t index,
                         std::size_t position, const E57ReadOptions& options, std::size_t chunk_points,
                         ChunkSink& sink, Progress* progress,
                         std::vector<std::pair<std::string, std::string>>& metadata);

}  // namespace plumb::e57
