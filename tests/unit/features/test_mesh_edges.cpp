#include <gtest/gtest.h>

#include <cmath>

#include "features/mesh_edges/mesh_edges.hpp"
#include "features/mesh_edges/poisson_disk.hpp"
#include "synthetic_scenes.hpp"

namespace plumb {
namespace {

bool sameSegment(const Segment3D& s, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return ((s.a - a).norm() < 1e-9 && (s.b - b).norm() < 1e-9) ||
         ((s.a - b).norm() < 1e-9 && (s.b - a).norm() < 1e-9);
}

TEST(MeshEdges, SubdividedBoxGivesExactlyItsTwelveEdges) {
  const Eigen::Vector3d lo(0, 0, 0), hi(4, 3, 2.5);
  for (int n : {1, 5}) {
    const auto mesh = test::makeBoxMesh(lo, hi, n);
    const auto r = extractSharpEdges(mesh);
    ASSERT_EQ(r.segments.size(), 12u) << n;
    EXPECT_EQ(r.sharp_edge_count, std::size_t(12 * n));
    for (int axis = 0; axis < 3; ++axis)
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
          const int b = (axis + 1) % 3, c = (axis + 2) % 3;
          Eigen::Vector3d p, q;
          p[axis] = lo[axis];
          q[axis] = hi[axis];
          p[b] = q[b] = i ? hi[b] : lo[b];
          p[c] = q[c] = j ? hi[c] : lo[c];
          int found = 0;
          for (const auto& s : r.segments) found += sameSegment(s, p, q);
          EXPECT_EQ(found, 1) << p.transpose() << " -> " << q.transpose();
        }
  }
}

TEST(MeshEdges, UnweldedTrianglesAndAngleThreshold) {
  // Unshared vertices (as many exporters write them) are welded first.
  auto shared = test::makeBoxMesh({0, 0, 0}, {1, 1, 1}, 2);
  TriangleMesh soup;
  for (const auto& t : shared.triangles) {
    const auto base = static_cast<std::uint32_t>(soup.vertices.size());
    for (auto v : t) soup.vertices.push_back(shared.vertices[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_EQ(extractSharpEdges(soup).segments.size(), 12u);
  MeshEdgeParams p;
  p.angle_threshold_deg = 95;  // box edges turn by 90 degrees: none is sharp
  EXPECT_TRUE(extractSharpEdges(soup, p).segments.empty());
}

TEST(PoissonDisk, SamplesRespectTheRadiusAndCoverTheMesh) {
  const auto mesh = test::makeBoxMesh({0, 0, 0}, {2, 1, 1}, 3);
  PoissonDiskParams p;
  p.radius = 0.1;
  const PointCloud c = samplePoissonDisk(mesh, p);
  ASSERT_GT(c.size(), 100u);
  ASSERT_TRUE(c.hasNormals());
  double min_d2 = 1e9;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      min_d2 = std::min(min_d2, double((c.positions[i] - c.positions[j]).squaredNorm()));
  EXPECT_GE(std::sqrt(min_d2), 0.1 - 1e-5);
  // Maximal-ish: a disk packing covers at least ~half the density of the hexagonal packing.
  const double area = mesh.area();
  EXPECT_GT(double(c.size()), 0.5 * area / (0.1 * 0.1 * std::sqrt(3.0) / 2 * 4));
  // All on the surface of the box.
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d w = c.world(i);
    const double d = std::min({std::abs(w.x()), std::abs(w.x() - 2), std::abs(w.y()), std::abs(w.y() - 1),
                               std::abs(w.z()), std::abs(w.z() - 1)});
    EXPECT_LT(d, 1e-5);
  }
  const PointCloud again = samplePoissonDisk(mesh, p);
  EXPECT_EQ(again.positions, c.positions);
}

}  // namespace
}  // namespace plumb

namespace plumb {
namespace {

TEST(MeshEdges, TJunctionsAreSplitSoFlatFacesGiveNoEdges) {
  // Two coplanar squares side by side in z = 0: the left one is one quad (2 triangles), the
  // right one is split in two along x, so its vertex (1, 0.5) sits on the left quad's edge.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}, {1, 0.5, 0}, {2, 0.5, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 7}, {1, 7, 6}, {6, 7, 5}, {6, 5, 2}};
  MeshEdgeParams p;
  p.include_boundary = false;
  EXPECT_TRUE(extractSharpEdges(m, p).segments.empty());
  // With boundaries: the outline only, chained into the 4 sides of the 2 x 1 rectangle.
  p.include_boundary = true;
  const auto r = extractSharpEdges(m, p);
  ASSERT_EQ(r.segments.size(), 4u);
  double total = 0;
  for (const auto& s : r.segments) total += s.length();
  EXPECT_NEAR(total, 6.0, 1e-12);
}

}  // namespace
}  // namespace plumb
