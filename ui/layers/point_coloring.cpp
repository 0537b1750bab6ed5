#include "ui/layers/point_coloring.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace plumb::ui {

PointColorMode effectiveMode(const PointCloud& cloud, const PointStyle& style) {
  switch (style.mode) {
    case PointColorMode::Rgb:
      return cloud.hasColors() ? PointColorMode::Rgb : PointColorMode::Elevation;
    case PointColorMode::Intensity:
      return cloud.hasIntensity() ? PointColorMode::Intensity : PointColorMode::Elevation;
    case PointColorMode::ScalarField: {
      const ScalarField* f = cloud.findScalarField(style.scalar_field);
      return f && f->values.size() == cloud.size() ? PointColorMode::ScalarField
                                                    : PointColorMode::Elevation;
    }
    case PointColorMode::Distance: return PointColorMode::Elevation;  // needs ScanLayer data
    default: return style.mode;
  }
}

std::string missingColourData(const PointCloud& cloud, const PointStyle& style) {
  if (effectiveMode(cloud, style) == style.mode) return {};
  switch (style.mode) {
    case PointColorMode::Rgb: return "RGB colours";
    case PointColorMode::Intensity: return "intensities";
    case PointColorMode::ScalarField: return "the scalar field '" + style.scalar_field + "'";
    default: return {};
  }
}

namespace {

/// out[i] = color(i) for every i, in parallel (each element on its own: deterministic).
template <class F>
void fillEach(std::span<Rgb> out, const F& color) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), std::size_t{1} << 14),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = color(i);
                    });
}

void fillFromValues(std::span<const float> values, double lo, double hi, RampKind ramp,
                    std::span<Rgb> out) {
  if (!(hi > lo)) std::tie(lo, hi) = robustRange(values);
  const double scale = 1.0 / (hi - lo);
  fillEach(out, [&](std::size_t i) {
    return rampColor(ramp, (static_cast<double>(values[i]) - lo) * scale);
  });
}

}  // namespace

void fillDistanceColors(std::span<const float> distances, const DistanceScale& scale, std::span<Rgb> out) {
  const Rgb unmatched = scale.signed_values ? Rgb{110, 110, 110} : Rgb{190, 190, 190};
  const RampKind ramp = scale.ramp();
  fillEach(out, [&](std::size_t i) {
    return std::isfinite(distances[i]) ? rampColor(ramp, scale.at(distances[i])) : unmatched;
  });
}

void fillPointColors(const PointCloud& cloud, const PointColoring& c, std::span<Rgb> out) {
  switch (effectiveMode(cloud, c.style)) {
    case PointColorMode::Rgb:
      std::copy(cloud.colors.begin(), cloud.colors.end(), out.begin());
      return;
    case PointColorMode::Intensity:
      fillFromValues(cloud.intensity, c.value_min, c.value_max, RampKind::Grey, out);
      return;
    case PointColorMode::ScalarField:
      fillFromValues(cloud.findScalarField(c.style.scalar_field)->values, c.value_min,
                     c.value_max, RampKind::Viridis, out);
      return;
    case PointColorMode::Scan:
      std::fill(out.begin(), out.end(), categoryColor(c.scan_index));
      return;
    case PointColorMode::Dataset:
      std::fill(out.begin(), out.end(), categoryColor(c.dataset_index));
      return;
    case PointColorMode::Elevation:
    case PointColorMode::Distance: break;
  }
  const double z0 = c.elevation_row.head<3>().dot(cloud.offset) + c.elevation_row[3];
  const Eigen::Vector3f row = c.elevation_row.head<3>().cast<float>();
  const double scale = c.z_max > c.z_min ? 1.0 / (c.z_max - c.z_min) : 1.0;
  fillEach(out, [&](std::size_t i) {
    const double z = z0 + static_cast<double>(row.dot(cloud.positions[i]));
    return rampColor(RampKind::Viridis, (z - c.z_min) * scale);
  });
}

}  // namespace plumb::ui
