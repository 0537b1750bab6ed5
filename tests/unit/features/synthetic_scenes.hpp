#pragma once
// Small synthetic scenes for the feature tests: an axis-aligned room (box) sampled on a grid,
// with Gaussian noise along the face normal, a window hole in the +X wall and optionally a
// surface 3 m outside that window (what an indoor scanner sees through it).
#include <Eigen/Core>

#include <array>
#include <cstdint>

#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"

namespace plumb::test {

struct RoomSpec {
  Eigen::Vector3d min{0, 0, 0};
  Eigen::Vector3d max{6, 4, 3};
  double spacing = 0.03;  ///< grid spacing on each face, m
  double noise = 0.003;   ///< sigma along the normal, m
  bool window = true;     ///< hole in the +X wall: y in [1.4, 2.6], z in [0.9, 2.3]
  bool outside = true;    ///< a vertical surface at x = max.x + 3 behind the window
  bool sensor_origins = true;  ///< per-point origin = room centre at z = 1.5
  std::uint64_t seed = 7;
};

/// Window rectangle in the +X wall: y0, y1, z0, z1.
inline constexpr std::array<double, 4> kWindow{1.4, 2.6, 0.9, 2.3};

PointCloud makeRoom(const RoomSpec& spec);

/// A closed box mesh with each face split into n x n quads (2 triangles each).
TriangleMesh makeBoxMesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int n);

}  // namespace plumb::test
