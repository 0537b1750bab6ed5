#pragma once
// Small 2D helpers shared by the polygon and opening code (plane (u,v) coordinates, metres).
#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace plumb {

/// Shoelace area: positive for counter-clockwise rings.
double ringSignedArea(const std::vector<Eigen::Vector2d>& ring);
/// Even-odd point-in-ring test.
bool ringContains(const std::vector<Eigen::Vector2d>& ring, const Eigen::Vector2d& p);
/// Connected components of points, two points being linked when they fall in 8-adjacent
/// cells of a grid of size `cell` (a fast approximation of "closer than cell"). Components are
/// listed in a deterministic order; each holds indices into pts.
std::vector<std::vector<std::size_t>> gridComponents(const std::vector<Eigen::Vector2d>& pts,
                                                     double cell);

}  // namespace plumb
