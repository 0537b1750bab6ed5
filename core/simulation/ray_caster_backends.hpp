#pragma once
// Internal: the ray caster's backend interface. CGAL lives in cgal_ray_caster.cpp, Embree in
// embree_ray_caster.cpp (compiled only with PLUMB_HAVE_EMBREE).
#include <memory>
#include <vector>

#include "simulation/ray_caster.hpp"

namespace plumb {

struct RayCaster::Impl {
  TriangleMesh mesh;
  virtual ~Impl() = default;
  /// Nearest hit with distance in (min_range, max_range].
  virtual RayHit cast(const Ray& ray, double max_range, double min_range) const = 0;
};

namespace sim {
std::unique_ptr<RayCaster::Impl> makeCgalCaster(const TriangleMesh& mesh, const std::vector<bool>& skip);
std::unique_ptr<RayCaster::Impl> makeEmbreeCaster(const TriangleMesh& mesh, const std::vector<bool>& skip);
/// Exact (double) distance along the ray to the plane of triangle t; used to refine hits.
double distanceToTrianglePlane(const TriangleMesh& mesh, std::uint32_t t, const Ray& ray);
}  // namespace sim

}  // namespace plumb
