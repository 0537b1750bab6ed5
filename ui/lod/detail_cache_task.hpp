#pragma once
// The level-of-detail cache of a dataset opened as a subsample (issue 16): opened when it is
// still valid for the file, built in a background task (progress, cancel) when it is missing
// or stale, then shown as the dataset's DetailLayer child.
#include <cstdint>
#include <filesystem>

namespace plumb::ui {

struct AppContext;
class DatasetLayer;
class Task;

/// Where the desktop keeps its caches: $PLUMB_LOD_CACHE_DIR when set, else the user's cache
/// folder (QStandardPaths::CacheLocation)/lod.
std::filesystem::path lodCacheRoot();

/// Opens or builds the cache of `layer`'s file in a task of app.tasks and adds its DetailLayer
/// under `layer` (if the layer still exists then). A build's buckets take an eighth of
/// `budget_share` (the bytes the file was opened within, loadShare; 64 MB .. 1 GB). Logs
/// whether it was reused or built, its size and time. Returns the task.
Task* startDetailCache(AppContext& app, DatasetLayer& layer, std::uint64_t budget_share);

}  // namespace plumb::ui
