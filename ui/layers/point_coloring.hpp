#pragma once
// Per-point colours of a cloud for a PointStyle (computed on the CPU into the vertex colour
// buffer, once per style change; the mapper then draws them directly).
#include <Eigen/Core>

#include <span>
#include <string>

#include "model/point_cloud.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/point_style.hpp"

namespace plumb::ui {

struct PointColoring {
  PointStyle style;
  std::size_t scan_index = 0;  ///< colour of the Scan mode: the scan's number in the scene
  std::size_t dataset_index = 0;  ///< colour of the Dataset mode: the dataset's number in the scene
  /// Elevation: z = elevation_row . (offset + local, 1), mapped from [z_min, z_max].
  Eigen::Vector4d elevation_row = Eigen::Vector4d(0, 0, 1, 0);
  double z_min = 0.0;
  double z_max = 1.0;
  /// Intensity / scalar field range; computed from the cloud when min >= max.
  double value_min = 0.0;
  double value_max = 0.0;
};

/// Mode actually used: RGB without colours, intensity without intensity, or a missing scalar
/// field fall back to elevation.
PointColorMode effectiveMode(const PointCloud& cloud, const PointStyle& style);
/// What `cloud` lacks for `style` when effectiveMode falls back ("RGB colours",
/// "intensities", "the scalar field 'x'"); empty when it shows the style as asked (the
/// Distance mode is the layer's business, not judged here).
std::string missingColourData(const PointCloud& cloud, const PointStyle& style);
/// Writes one colour per point of `cloud` into `out` (out.size() == cloud.size()).
/// Distance colours: the distance ramp over [0, max_distance]; NaN (no match) light grey.
void fillDistanceColors(std::span<const float> distances, double max_distance, std::span<Rgb> out);
void fillPointColors(const PointCloud& cloud, const PointColoring& coloring, std::span<Rgb> out);

}  // namespace plumb::ui
