#include "features/mesh_edges/poisson_disk.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <unordered_map>

#include "common/error.hpp"

namespace plumb {

const ParamSchema<PoissonDiskParams>& PoissonDiskParams::schema() {
  using P = PoissonDiskParams;
  static const auto s =
      ParamSchema<P>("poisson-disk")
          .real(&P::radius, "radius", "Sample distance", "m", 1e-6, 100,
                "minimum distance between samples")
          .real(&P::candidates_per_disk, "candidates", "Candidate density", "", 1, 100,
                "candidates per disk of the radius", true)
          .integer(&P::seed, "seed", "Random seed", "", 0, 9007199254740992.0, "", true);
  return s;
}

PointCloud samplePoissonDisk(const TriangleMesh& mesh, const PoissonDiskParams& params,
                             Progress* progress) {
  validateParams(PoissonDiskParams::schema(), params);
  PointCloud cloud;
  if (mesh.triangles.empty()) return cloud;
  const Bounds bounds = mesh.bounds();
  cloud.offset = bounds.min;
  const double r = params.radius;
  // 1. Area-uniform candidates (per-triangle count from the expected value, seeded).
  std::mt19937_64 rng(params.seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double density = params.candidates_per_disk / (M_PI * r * r);
  std::vector<Eigen::Vector3d> cand;
  std::vector<Eigen::Vector3f> cand_n;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const double area = mesh.triangleArea(t);
    if (!(area > 0)) continue;
    const double expected = area * density;
    std::size_t count = static_cast<std::size_t>(expected);
    if (U(rng) < expected - double(count)) ++count;
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d &A = mesh.vertices[tri[0]], &B = mesh.vertices[tri[1]], &C = mesh.vertices[tri[2]];
    const Eigen::Vector3f n = mesh.triangleNormal(t).cast<float>();
    for (std::size_t k = 0; k < count; ++k) {
      double u = U(rng), v = U(rng);
      if (u + v > 1) { u = 1 - u; v = 1 - v; }
      cand.push_back(A + u * (B - A) + v * (C - A));
      cand_n.push_back(n);
    }
    if (t % 4096 == 0) checkCanceled(progress);
  }
  reportProgress(progress, 0.5, "Poisson-disk elimination");
  // 2. Greedy elimination in a seeded random order, hashed grid of cell r.
  std::vector<std::size_t> order(cand.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  auto cellOf = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = (p - bounds.min) / r;
    return std::array<std::int64_t, 3>{std::int64_t(std::floor(q.x())), std::int64_t(std::floor(q.y())),
                                       std::int64_t(std::floor(q.z()))};
  };
  auto hash = [](const std::array<std::int64_t, 3>& c) {
    return (std::uint64_t(c[0] & 0x1FFFFF) << 42) | (std::uint64_t(c[1] & 0x1FFFFF) << 21) |
           std::uint64_t(c[2] & 0x1FFFFF);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  std::vector<std::size_t> kept;
  const double r2 = r * r;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& p = cand[order[k]];
    const auto c = cellOf(p);
    bool ok = true;
    for (int dx = -1; dx <= 1 && ok; ++dx)
      for (int dy = -1; dy <= 1 && ok; ++dy)
        for (int dz = -1; dz <= 1 && ok; ++dz) {
          auto it = grid.find(hash({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == grid.end()) continue;
          for (auto q : it->second)
            if ((cand[kept[q]] - p).squaredNorm() < r2) { ok = false; break; }
        }
    if (!ok) continue;
    grid[hash(c)].push_back(static_cast<std::uint32_t>(kept.size()));
    kept.push_back(order[k]);
    if (k % 65536 == 0) checkCanceled(progress);
  }
  cloud.reserve(kept.size());
  for (auto i : kept) {
    cloud.positions.push_back((cand[i] - cloud.offset).cast<float>());
    cloud.normals.push_back(cand_n[i]);
  }
  reportProgress(progress, 1.0, "Poisson-disk sampling");
  return cloud;
}

}  // namespace plumb
