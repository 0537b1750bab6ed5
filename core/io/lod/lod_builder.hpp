#pragma once
// Builds the level-of-detail octree cache of a point file (docs/IO.md "Level-of-detail
// cache") in bounded memory: a first streamed pass finds the bounds and stations, a second
// quantises every point into the dataset frame (scan poses applied) and builds the octree,
// spilling to temporary bucket files what does not fit LodCacheParams::memory_budget_mb.
// The cache is written in a temporary folder renamed into place at the end, so a cancelled
// or failed build leaves no cache (and the previous one, if any, is replaced only then).
#include <filesystem>

#include "common/progress.hpp"
#include "io/lod/lod_params.hpp"

namespace plumb {

/// Builds (or rebuilds) the cache of `source` in lodCacheDirectory(source, cache_root).
/// Throws FileError for unreadable input (readDataset's messages) or an unwritable cache,
/// InputError for bad parameters or a file spanning more than 2^31 quanta, Canceled.
LodCacheBuildResult buildLodCache(const std::filesystem::path& source, const std::filesystem::path& cache_root,
                                  const LodCacheParams& params = {}, Progress* progress = nullptr);

}  // namespace plumb
