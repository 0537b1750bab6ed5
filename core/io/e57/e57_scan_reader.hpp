#pragma once
// Turns the decoded records of one data3D entry into a Scan (rules in e57_reader.hpp).
#include "common/progress.hpp"
#include "io/e57/e57_pages.hpp"
#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_xml.hpp"
#include "model/dataset.hpp"

namespace plumb::e57 {

/// True when the prototype of `info` has cartesianX/Y/Z or sphericalRange/Azimuth/Elevation.
bool hasCoordinates(const ScanInfo& info);

/// Reads the points of `info` (scan number `index`) from `file`. Adds facts to `metadata`.
Scan readScan(PagedReader& file, const ScanInfo& info, std::size_t index,
              const E57ReadOptions& options, Progress* progress,
              std::vector<std::pair<std::string, std::string>>& metadata);

}  // namespace plumb::e57
