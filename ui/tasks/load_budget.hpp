#pragma once
// Opening a file within the memory budget (issue 16): a point file whose display would exceed
// the budget (kDisplayBytesPerPoint a point) is not read whole but streamed into a per-scan
// voxel subsample (io/stream/stream_subsample.hpp) that fits; the layer says so
// (DatasetLayer::subsampledFrom) and exports stream the whole file again.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>

#include "io/stream/stream_subsample.hpp"

namespace plumb::ui {

struct AppContext;

/// Planning figure of the desktop, bytes per point of a dataset opened whole: its columns
/// (~26 B), the drawn buffers (bench_ui: 165 B a point once drawn in full detail) and the
/// registration's working set when it is a registration input (~105 B).
inline constexpr std::uint64_t kDisplayBytesPerPoint = 300;

/// The memory budget in bytes: the Registration dock's "memory" group (its defaults before the
/// dock exists).
std::uint64_t memoryBudget(const AppContext& app);

/// Bytes the open point layers hold by the planning figure: their points (the subsample's, for
/// a file opened as one) times kDisplayBytesPerPoint.
std::uint64_t heldBytes(const AppContext& app);

/// What each of `point_files` files opened together may take: the budget less heldBytes and
/// the shares of files still loading (AppContext::loads_reserved), split
/// evenly, so that a campaign of several files opened one after the other or together stays
/// within the one budget. Never 0 (0 means "no budget" to planLoad): with nothing left, a file
/// opens as the smallest subsample (kMinSubsamplePoints). 0 when there is no budget.
std::uint64_t loadShare(const AppContext& app, std::size_t point_files);

/// The subsample to open `path` with to stay within `budget` bytes (subsampleToFit at
/// kDisplayBytesPerPoint; `voxel` is its starting voxel, metres), or nullopt to read it whole:
/// a model, a file whose estimate fits, or no budget (0). Throws readDataset's FileErrors.
std::optional<SubsampleParams> planLoad(const std::filesystem::path& path, std::uint64_t budget, double voxel);

}  // namespace plumb::ui
