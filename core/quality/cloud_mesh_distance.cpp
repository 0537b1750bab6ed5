// Cloud-to-mesh distances with CGAL's AABB tree (closest point on the triangles). Kept in its
// own translation unit: the CGAL headers are heavy.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"

namespace plumb {

namespace {
using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
}  // namespace

DistanceResult cloudToMeshDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                    const TriangleMesh& mesh, const RigidTransform& mesh_to_world,
                                    const DistanceParams& params, Progress* progress) {
  if (mesh.triangles.empty()) throw InputError("distance: the model has no triangles");
  reportProgress(progress, 0.0, "distance: AABB tree");
  // Measured in the mesh frame, relative to the mesh's box centre (small coordinates).
  const Eigen::Vector3d centre = mesh.bounds().center();
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  auto point = [&](std::uint32_t v) {
    const Eigen::Vector3d p = mesh.vertices[v] - centre;
    return K::Point_3(p.x(), p.y(), p.z());
  };
  for (const auto& t : mesh.triangles) {
    Triangle tri(point(t[0]), point(t[1]), point(t[2]));
    if (!tri.is_degenerate()) triangles.push_back(tri);
  }
  if (triangles.empty()) throw InputError("distance: every triangle of the model is degenerate");
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  checkCanceled(progress);
  const RigidTransform s2m = mesh_to_world.inverse() * source_to_world;
  const Eigen::Matrix3d R = s2m.rotation();
  const Eigen::Vector3d t = s2m.apply(source.offset) - centre;
  DistanceResult r;
  r.distances.assign(source.size(), std::numeric_limits<float>::quiet_NaN());
  const std::size_t chunk = 1 << 15;
  const std::size_t chunks = (source.size() + chunk - 1) / chunk;
  for (std::size_t c = 0; c < chunks; ++c) {
    checkCanceled(progress);
    reportProgress(progress, 0.1 + 0.85 * double(c) / double(chunks), "distance: closest points");
    const std::size_t end = std::min(source.size(), (c + 1) * chunk);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(c * chunk, end, 1024),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (!source.positions[i].allFinite()) continue;
                          const Eigen::Vector3d q = R * source.positions[i].cast<double>() + t;
                          const double d =
                              std::sqrt(tree.squared_distance(K::Point_3(q.x(), q.y(), q.z())));
                          if (d <= params.max_distance) r.distances[i] = float(d);
                        }
                      });
  }
  summarizeDistances(r);
  reportProgress(progress, 1.0, "distance: done");
  return r;
}

}  // namespace plumb
