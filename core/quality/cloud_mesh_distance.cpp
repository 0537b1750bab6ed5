// Cloud-to-mesh distances: closest points on the triangles (simulation/mesh_closest_points.hpp,
// CGAL's AABB tree), signed by the closest triangle's winding normal.
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"
#include "simulation/mesh_closest_points.hpp"

namespace plumb {

DistanceResult cloudToMeshDistances(const PointCloud& source, const RigidTransform& source_to_world,
                                    const TriangleMesh& mesh, const RigidTransform& mesh_to_world,
                                    const DistanceParams& params, Progress* progress) {
  validateParams(DistanceParams::schema(), params);
  if (mesh.triangles.empty()) throw InputError("distance: the model has no triangles");
  reportProgress(progress, 0.0, "distance: AABB tree");
  // Measured in the mesh frame, relative to the mesh's box centre (small coordinates).
  const Eigen::Vector3d centre = mesh.bounds().center();
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) vertices.push_back(v - centre);
  const MeshClosestPoints tree(vertices, mesh.triangles, MeshClosestPoints::all(mesh.triangles.size()));
  if (tree.size() == 0) throw InputError("distance: every triangle of the model is degenerate");
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
                          MeshClosestPoints::Closest c;
                          tree.closest(q, c);
                          const double d = (c.point - q).norm();
                          if (d > params.max_distance) continue;
                          const bool behind = params.signed_distances &&
                                              (q - c.point).dot(mesh.triangleNormal(c.triangle)) < 0;
                          r.distances[i] = float(behind ? -d : d);
                        }
                      });
  }
  summarizeDistances(r);
  reportProgress(progress, 1.0, "distance: done");
  return r;
}

}  // namespace plumb
