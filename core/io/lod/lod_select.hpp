#pragma once
// Which nodes of a level-of-detail cache a view draws (docs/IO.md "Level-of-detail cache"):
// nodes whose box meets the view frustum, the largest on screen first, a parent always before
// its children, until the point budget is reached. A pure function of the hierarchy and view.
#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/lod/lod_hierarchy.hpp"

namespace plumb {

/// A camera in the cache's frame (the dataset frame, metres).
struct LodView {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  /// Projection * view, OpenGL clip conventions (-w <= x, y, z <= w inside). Planes are taken
  /// from it (Gribb-Hartmann), so any perspective or orthographic camera works.
  Eigen::Matrix4d view_projection = Eigen::Matrix4d::Identity();
  double viewport_height_px = 1000;
  /// Perspective: vertical field of view, radians. Orthographic: set metres_per_pixel.
  double fov_y_rad = 0.5235987755982988;  // 30 degrees
  /// Orthographic views: metres one pixel covers (> 0 selects it; fov is then unused).
  double metres_per_pixel = 0;
};

struct LodSelectParams {
  /// Most points the selected nodes hold together (default 2 million).
  std::size_t point_budget = 2'000'000;
  /// Children of a node are considered only while its sample spacing covers more than this
  /// many pixels on screen (finer detail would not be seen).
  double min_spacing_px = 1.0;
};

struct LodSelection {
  std::vector<std::uint32_t> nodes;  ///< in the order chosen: larger on screen first, parents before children
  std::uint64_t points = 0;          ///< their points together
  std::size_t culled = 0;            ///< nodes considered and left out as outside the frustum
  bool budget_reached = false;       ///< a visible node was left out for the budget
};

/// A perspective camera at `eye` looking at `target`, z up (gluLookAt and gluPerspective,
/// OpenGL clip conventions); `aspect` is width / height.
LodView lodPerspectiveView(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double fov_y_rad, double aspect,
                           double viewport_height_px, double near = 0.1, double far = 1e4);

/// Projected size on screen, pixels, of a length `size` (metres) at distance `distance`.
double lodPixels(const LodView& view, double size, double distance);
/// True when the box is entirely outside one of the view's six frustum planes.
bool lodOutsideFrustum(const LodView& view, const Bounds& box);

LodSelection selectLodNodes(const LodHierarchy& hierarchy, const LodView& view, const LodSelectParams& params = {});

}  // namespace plumb
