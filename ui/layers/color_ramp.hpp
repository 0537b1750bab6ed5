#pragma once
// Colour scales for points and the distance legend. No VTK, no Qt: plain functions.
#include <array>
#include <string>
#include <cstdint>
#include <span>
#include <utility>

namespace plumb::ui {

using Rgb = std::array<std::uint8_t, 3>;

enum class RampKind {
  Viridis,  ///< perceptually uniform; elevation, scalar fields, distances
  Grey,     ///< intensity
  Distance, ///< registration QA: blue (on the target) -> green -> yellow -> red (far)
  Diverging, ///< signed distances: blue (behind the target) -> white (on it) -> red (in front)
};

/// Colour of t in [0,1] (clamped) on the ramp.
Rgb rampColor(RampKind ramp, double t);
/// A distinct colour for category i (scans, planes, element types).
Rgb categoryColor(std::size_t i);
/// Colour of an IFC element type, the same in every model whatever the file's order: a fixed
/// colour for the common building elements (walls tan, slabs light grey, windows light blue, doors
/// brown...), a stable colour from the type name for the others, light grey for untyped.
Rgb ifcTypeColor(const std::string& type);
/// Robust value range: the `lo` and `hi` quantiles (e.g. 0.01, 0.99) of finite values, from a
/// sample of at most 100000 values. Returns {0,1} for no finite values; widens equal ends.
std::pair<double, double> robustRange(std::span<const float> values, double lo = 0.01,
                                      double hi = 0.99);

}  // namespace plumb::ui
