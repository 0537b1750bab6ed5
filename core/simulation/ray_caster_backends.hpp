#pragma once
// Internal: the ray caster's backend interface. CGAL lives in cgal_ray_caster.cpp, Embree in
// embree_ray_caster.cpp (compiled only with PLUMB_HAVE_EMBREE).
#include <cstddef>
#include <memory>
#include <vector>

#include "simulation/ray_caster.hpp"

namespace plumb {

struct RayCaster::Impl {
  /// Plane of a triangle: unit normal n and offset with n . x = offset (zero normal for
  /// degenerate triangles). One contiguous table so refining a hit touches one cache line
  /// instead of three scattered vertices.
  struct Plane {
    Eigen::Vector3d normal;
    double offset;
  };

  explicit Impl(const TriangleMesh& m);
  virtual ~Impl() = default;
  /// Nearest hit with distance in (min_range, max_range].
  virtual RayHit cast(const Ray& ray, double max_range, double min_range) const = 0;
  /// hits[i] for rays[i], i < n (backends may trace them as packets; `coherent`: the rays are
  /// in scan order, neighbours with nearby origins and directions).
  virtual void castBatch(const Ray* rays, std::size_t n, RayHit* hits, double max_range, double min_range,
                         bool coherent) const;

  /// Exact (double) distance along the ray to the plane of triangle t, or `approx` (the
  /// backend's own distance) when the ray grazes the plane and the two disagree.
  double refineDistance(std::uint32_t t, const Ray& ray, double approx) const;

  TriangleMesh mesh;
  std::vector<Plane> planes;  ///< per triangle of mesh
};

namespace sim {
std::unique_ptr<RayCaster::Impl> makeCgalCaster(const TriangleMesh& mesh, const std::vector<bool>& skip);
std::unique_ptr<RayCaster::Impl> makeEmbreeCaster(const TriangleMesh& mesh, const std::vector<bool>& skip);
}  // namespace sim

}  // namespace plumb
