#pragma once
// The CPU side of a dataset layer's display data, built off the UI thread (in the loading task
// or a follow-up task): each scan's points in their random order with the initial colours, and
// the bounds. DatasetLayer then only wraps these buffers in VTK objects (no copy), on the UI
// thread.
#include <memory>
#include <vector>

#include "common/progress.hpp"
#include "model/dataset.hpp"
#include "ui/layers/point_geometry.hpp"
#include "ui/layers/point_style.hpp"

namespace plumb::ui {

struct PreparedScan {
  PermutedPoints points;  ///< random order of scanOrderSeed(scan index), coloured
  Bounds local_bounds;    ///< of the scan's finite local (offset-relative) positions
};

struct PreparedDataset {
  std::vector<PreparedScan> scans;  ///< one per scan of the dataset, in order
  PointStyle style;                 ///< the style the colours were computed for
  Bounds bounds;                    ///< Dataset::bounds() (dataset frame)
  Bounds framing;                   ///< robustBounds of the points (dataset frame): what views frame
};

/// RGB when any scan has colours, elevation otherwise.
PointStyle initialStyle(const Dataset& data);
/// Whether any scan of `data` carries RGB colours / intensities (what the colour modes can show).
bool anyScanHasColors(const Dataset& data);
bool anyScanHasIntensity(const Dataset& data);
/// Builds everything for `data` drawn with initialStyle (deterministic). Thread safe; reports
/// to `progress` and throws Canceled between scans and passes when it is cancelled.
PreparedDataset prepareDataset(const std::shared_ptr<const Dataset>& data,
                               Progress* progress = nullptr);

}  // namespace plumb::ui
