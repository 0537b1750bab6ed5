#pragma once
// Scenes of the refinement tests (test_icp_refinement.cpp, test_refinement.cpp): boxes as
// meshes and noisy point samples of them.
#include <cstdint>
#include <random>
#include <vector>

#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "unit/registration/synthetic_building.hpp"

namespace plumb::test {

/// Boxes as triangle meshes (12 triangles each).
inline TriangleMesh boxesMesh(const std::vector<test::Room>& rooms) {
  TriangleMesh m;
  for (const auto& r : rooms) {
    const std::uint32_t base = m.vertices.size();
    for (int k = 0; k < 8; ++k)
      m.vertices.emplace_back(k & 1 ? r.max.x() : r.min.x(), k & 2 ? r.max.y() : r.min.y(),
                              k & 4 ? r.max.z() : r.min.z());
    const int f[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                          {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
    for (const auto& t : f) m.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  return m;
}

inline PointCloud noisyScan(const TriangleMesh& mesh, double spacing, double noise, std::uint64_t seed) {
  PointCloud c = sampleMeshSurface(mesh, spacing, seed);
  std::mt19937_64 rng(seed + 100);
  std::normal_distribution<float> n(0.0f, float(noise));
  for (auto& p : c.positions) p += Eigen::Vector3f(n(rng), n(rng), n(rng));
  c.normals.clear();
  return c;
}

}  // namespace plumb::test
