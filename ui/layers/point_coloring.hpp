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

/// The scale of the distance colours: signed distances on the diverging ramp over [-max, max]
/// (white at 0), unsigned ones on the distance ramp over [0, max].
struct DistanceScale {
  double max = 1.0;  ///< metres, > 0
  bool signed_values = false;
  double lo() const { return signed_values ? -max : 0.0; }
  RampKind ramp() const { return signed_values ? RampKind::Diverging : RampKind::Distance; }
  /// Where the distance v lies on the ramp (0 at lo(), 1 at max; not clamped).
  double at(double v) const { return (v - lo()) / (max - lo()); }
};

/// Mode actually used: RGB without colours, intensity without intensity, or a missing scalar
/// field fall back to elevation.
PointColorMode effectiveMode(const PointCloud& cloud, const PointStyle& style);
/// What `cloud` lacks for `style` when effectiveMode falls back ("RGB colours",
/// "intensities", "the scalar field 'x'"); empty when it shows the style as asked (the
/// Distance mode is the layer's business, not judged here).
std::string missingColourData(const PointCloud& cloud, const PointStyle& style);
/// Writes one colour per point of `cloud` into `out` (out.size() == cloud.size()).
/// Distance colours on `scale`; NaN (no match) grey (darker for signed distances, whose zero
/// is near white).
void fillDistanceColors(std::span<const float> distances, const DistanceScale& scale, std::span<Rgb> out);
void fillPointColors(const PointCloud& cloud, const PointColoring& coloring, std::span<Rgb> out);

}  // namespace plumb::ui
