#pragma once
// Bounds that frame the data, not its outliers (issue 17: a few returns 100 m away made the
// default camera frame 140 m of ground around a house). The exact bounds stay what `info` and
// the Properties extent report; views and zooms frame the robust ones.
#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "model/dataset.hpp"

namespace plumb {

/// The box holding every sample but the `tail` fraction at each end of each axis, widened by
/// `margin` times its size on each side (at least 1 cm). Non-finite samples are ignored; empty
/// when none is finite. `tail` in [0, 0.25].
Bounds robustBounds(std::vector<Eigen::Vector3d> samples, double tail = 0.01, double margin = 0.05);

/// Up to about `max_samples` points of `data` in the dataset frame, at a regular stride over each
/// scan (every scan in proportion to its size).
std::vector<Eigen::Vector3d> datasetSamples(const Dataset& data, std::size_t max_samples = 100000);

}  // namespace plumb
