#pragma once
// A scan's vertex colours for a point style, computed apart from its layer (e.g. in a
// background task): the job holds copies or shared ownership of all it reads, so it is thread
// safe and the layer may change or be destroyed meanwhile. The result is deterministic: the
// colours of the style in the layer's random point order.
#include <cstdint>
#include <memory>
#include <vector>

#include "common/progress.hpp"
#include "model/dataset.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/point_geometry.hpp"

namespace plumb::ui {

/// Seed of the random point order of scan `scan_index` (its PermutedPoints).
inline std::uint32_t scanOrderSeed(std::size_t scan_index) {
  return static_cast<std::uint32_t>(scan_index);
}

struct ScanColorJob {
  std::shared_ptr<const Dataset> data;
  std::size_t scan_index = 0;
  PointColoring coloring;
  /// Per-point distances of the Distance mode (null or wrong size: elevation instead).
  std::shared_ptr<const std::vector<float>> distances;
  DistanceScale distance_scale;

  /// Colours in the scan's random order (permuteColors with scanOrderSeed). Parallel (TBB);
  /// checks `progress` for cancellation between its passes.
  std::vector<Rgba> compute(Progress* progress = nullptr) const;
};

/// The job for scan `scan_index` drawn with `style`; `dataset_transform` (dataset frame ->
/// world) and [z_min, z_max] (world) place the Elevation ramp.
ScanColorJob makeScanColorJob(std::shared_ptr<const Dataset> data, std::size_t scan_index,
                              const RigidTransform& dataset_transform, const PointStyle& style,
                              double z_min, double z_max,
                              std::shared_ptr<const std::vector<float>> distances = {},
                              const DistanceScale& distance_scale = {});

}  // namespace plumb::ui
