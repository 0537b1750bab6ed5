#include "synthetic_scenes.hpp"

#include <map>
#include <random>

namespace plumb::test {

PointCloud makeRoom(const RoomSpec& s) {
  PointCloud cloud;
  // World = room coordinates; positions are stored relative to an offset to exercise it.
  cloud.offset = Eigen::Vector3d(1000.0, 2000.0, 50.0);
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> noise(0.0, s.noise);
  const Eigen::Vector3d origin((s.min.x() + s.max.x()) / 2, (s.min.y() + s.max.y()) / 2, s.min.z() + 1.5);
  auto add = [&](const Eigen::Vector3d& p) {
    cloud.positions.push_back(p.cast<float>());
    if (s.sensor_origins) cloud.sensor_origins.push_back(origin.cast<float>());
  };
  // Face axis a (fixed at value v), sampled over the other two axes.
  auto face = [&](int a, double v, bool is_window_wall) {
    const int b = (a + 1) % 3, c = (a + 2) % 3;
    for (double x = s.min[b] + s.spacing / 2; x < s.max[b]; x += s.spacing)
      for (double y = s.min[c] + s.spacing / 2; y < s.max[c]; y += s.spacing) {
        Eigen::Vector3d p;
        p[a] = v + noise(rng);
        p[b] = x;
        p[c] = y;
        if (is_window_wall && p.y() > kWindow[0] && p.y() < kWindow[1] && p.z() > kWindow[2] &&
            p.z() < kWindow[3])
          continue;
        add(p);
      }
  };
  for (int a = 0; a < 3; ++a) {
    face(a, s.min[a], false);
    face(a, s.max[a], a == 0 && s.window);
  }
  if (s.window && s.outside) {
    // Rays from the origin through the window, hitting a plane at x = max.x + 3.
    const double X = s.max.x() + 3.0;
    for (double y = kWindow[0] + 0.01; y < kWindow[1]; y += 0.02)
      for (double z = kWindow[2] + 0.01; z < kWindow[3]; z += 0.02) {
        const Eigen::Vector3d w(s.max.x(), y, z);
        const Eigen::Vector3d d = w - origin;
        add(origin + d * ((X - origin.x()) / d.x()));
      }
  }
  for (auto& p : cloud.positions) p -= cloud.offset.cast<float>();
  for (auto& o : cloud.sensor_origins) o -= cloud.offset.cast<float>();
  return cloud;
}

TriangleMesh makeBoxMesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int n) {
  TriangleMesh mesh;
  std::map<std::array<long, 3>, std::uint32_t> index;
  auto vertex = [&](const Eigen::Vector3d& p) {
    const std::array<long, 3> k{std::lround(p.x() * 1e6), std::lround(p.y() * 1e6), std::lround(p.z() * 1e6)};
    auto [it, inserted] = index.emplace(k, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (inserted) mesh.vertices.push_back(p);
    return it->second;
  };
  for (int a = 0; a < 3; ++a)
    for (int side = 0; side < 2; ++side) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          auto P = [&](int ii, int jj) {
            Eigen::Vector3d p;
            p[a] = side ? max[a] : min[a];
            p[b] = min[b] + (max[b] - min[b]) * ii / n;
            p[c] = min[c] + (max[c] - min[c]) * jj / n;
            return vertex(p);
          };
          const auto v00 = P(i, j), v10 = P(i + 1, j), v11 = P(i + 1, j + 1), v01 = P(i, j + 1);
          if (side) {
            mesh.triangles.push_back({v00, v10, v11});
            mesh.triangles.push_back({v00, v11, v01});
          } else {
            mesh.triangles.push_back({v00, v11, v10});
            mesh.triangles.push_back({v00, v01, v11});
          }
        }
    }
  return mesh;
}

}  // namespace plumb::test
