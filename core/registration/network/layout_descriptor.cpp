#include "registration/network/layout_descriptor.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {
namespace {

constexpr double kLevelTolerance = 10.0;  // deg

/// Horizontal extent of a vertical polygon's outer ring.
double horizontalLength(const PlanarPolygon& p) {
  if (p.rings.empty()) return 0.0;
  const Eigen::Vector3d along = p.normal.cross(Eigen::Vector3d::UnitZ()).normalized();
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& uv : p.rings[0]) {
    const double s = p.to3d(uv).dot(along);
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  return hi > lo ? hi - lo : 0.0;
}

int lengthBin(double length) {
  const double b = 2.0 * std::log2(std::max(length, 1e-3) / 0.5) + 1.0;  // half octaves from 0.5 m
  return std::clamp(static_cast<int>(std::floor(b)), 0, LayoutDescriptor::kBins - 1);
}

}  // namespace

LayoutDescriptor layoutDescriptor(const FeatureSet& features) {
  LayoutDescriptor d;
  double total = 0.0;
  for (const auto& p : features.planes) {
    if (p.isHorizontal(kLevelTolerance)) d.largest_horizontal_area = std::max(d.largest_horizontal_area, p.area);
    if (!p.isVertical(kLevelTolerance)) continue;
    d.wall_lengths[static_cast<std::size_t>(lengthBin(horizontalLength(p)))] += p.area;
    total += p.area;
  }
  if (total > 0)
    for (auto& w : d.wall_lengths) w /= total;
  return d;
}

double layoutSimilarity(const LayoutDescriptor& a, const LayoutDescriptor& b) {
  double intersection = 0.0;
  for (int i = 0; i < LayoutDescriptor::kBins; ++i) intersection += std::min(a.wall_lengths[i], b.wall_lengths[i]);
  const double hi = std::max(a.largest_horizontal_area, b.largest_horizontal_area);
  const double area = hi > 0 ? std::min(a.largest_horizontal_area, b.largest_horizontal_area) / hi : 0.0;
  return 0.7 * intersection + 0.3 * area;
}

}  // namespace plumb
