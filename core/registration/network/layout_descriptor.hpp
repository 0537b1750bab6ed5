#pragma once
// A station's layout descriptor (docs/NETWORK.md "Candidate pairs"): what its detected planes
// say about the space it stands in, independent of its pose (yaw and shift): the horizontal
// lengths of its walls (vertical planes) as an area-weighted histogram on a logarithmic scale,
// and the area of its largest horizontal plane (floor or ceiling). Stations that see the same
// walls have similar descriptors; so, unavoidably, do stations in identical rooms (whose links
// the network adjustment must then reject).
#include <array>

#include "model/feature_set.hpp"

namespace plumb {

struct LayoutDescriptor {
  /// Half-octave bins of wall length from 0.5 m (bin 0: below 0.71 m) to 32 m and above;
  /// area-weighted, summing to 1 (all zero without walls).
  static constexpr int kBins = 12;
  std::array<double, kBins> wall_lengths{};
  double largest_horizontal_area = 0.0;  ///< m^2
};

/// Walls are planes within 10 deg of vertical, horizontal planes within 10 deg of level.
LayoutDescriptor layoutDescriptor(const FeatureSet& features);

/// 0 (nothing alike) .. 1 (same): 0.7 x histogram intersection of the wall lengths + 0.3 x the
/// ratio of the smaller to the larger horizontal area.
double layoutSimilarity(const LayoutDescriptor& a, const LayoutDescriptor& b);

}  // namespace plumb
