#pragma once
// Generated survey files for the level-of-detail cache tests, and the points they hold as
// the cache must store them (quantised in the dataset frame).
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <tuple>
#include <vector>

#include "io/lod/lod_cache.hpp"

namespace plumb::test {

/// A point as compared: quantised position, station, intensity (its bits: NaN equals NaN), colour.
using LodRecord = std::tuple<std::array<std::int64_t, 3>, std::uint16_t, std::uint32_t, Rgb8>;

/// Writes an E57 of `stations` posed scans (yaw and a national-grid translation near
/// x 651,000, y 6,860,000) of `per_station` points on the walls, floor and ceiling of a room,
/// with intensity and colour, plus a few exact duplicates. Returns its path.
std::filesystem::path writeSurvey(const std::filesystem::path& dir, int stations, std::size_t per_station,
                                  unsigned seed = 7);
/// The points of `file` (streamed, scan poses applied) quantised on `grid`, sorted.
std::vector<LodRecord> expectedRecords(const std::filesystem::path& file, const LodGrid& grid);
/// Points of `file` as readDataset gives them (finite or not).
std::size_t readPointCount(const std::filesystem::path& file);
/// Every point of every node of `cache` (in quanta from the grid origin), sorted; also
/// checks that each world coordinate is the quantised one.
std::vector<LodRecord> cachedRecords(const LodCache& cache);
/// Opens the cache, failing the test when it is not valid.
std::shared_ptr<const LodCache> openValid(const std::filesystem::path& source, const std::filesystem::path& root);

}  // namespace plumb::test
