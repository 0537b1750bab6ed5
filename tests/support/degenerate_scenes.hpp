#pragma once
// Scenes that leave degrees of freedom free (issue 13's degenerate suite): a single plane, two
// parallel planes, a corridor without openings or end walls, a single line. Shared by the
// refinement unit test and bench_verdict's degenerate suite.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

#include "model/point_cloud.hpp"

namespace plumb::test {

/// An axis-aligned rectangle: {origin, edge u, edge v}.
using Rectangle = std::array<Eigen::Vector3d, 3>;

struct DegenerateScene {
  const char* name;
  std::vector<Rectangle> rects;
  int free_directions;  ///< translations and rotations the data leaves free
};

/// Uniform points on each rectangle with 3 mm Gaussian noise; deterministic for a seed.
PointCloud noisyRectangles(const std::vector<Rectangle>& rects, int per_rect, std::uint64_t seed);

/// Single plane, two parallel planes, corridor without openings, single line (a 6 mm pole).
std::vector<DegenerateScene> degenerateScenes();

}  // namespace plumb::test
