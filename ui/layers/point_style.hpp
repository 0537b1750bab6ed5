#pragma once
// How a point layer is drawn: colour source, point size.
#include <string>
#include <vector>

namespace plumb::ui {

/// Dataset: one colour per dataset (file) across the scene. Its value follows the others, so
/// the values saved before it existed keep their meaning.
enum class PointColorMode { Rgb, Intensity, Elevation, Scan, ScalarField, Distance, Dataset };

inline const std::vector<std::string>& pointColorModeNames() {
  static const std::vector<std::string> names{"RGB", "Intensity", "Elevation", "Scan",
                                              "Scalar field", "Distance", "Dataset"};
  return names;
}

struct PointStyle {
  PointColorMode mode = PointColorMode::Rgb;
  std::string scalar_field;  ///< used by ScalarField
  double point_size = 2.0;   ///< pixels
};

}  // namespace plumb::ui
