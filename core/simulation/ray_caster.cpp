#include "simulation/ray_caster.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "common/error.hpp"
#include "simulation/ray_caster_backends.hpp"

namespace plumb {

double sim::distanceToTrianglePlane(const TriangleMesh& mesh, std::uint32_t t, const Ray& ray) {
  const auto& tri = mesh.triangles[t];
  const Eigen::Vector3d& a = mesh.vertices[tri[0]];
  const Eigen::Vector3d n = (mesh.vertices[tri[1]] - a).cross(mesh.vertices[tri[2]] - a);
  const double denom = n.dot(ray.direction);
  return denom == 0.0 ? 0.0 : n.dot(a - ray.origin) / denom;
}

RayCaster::RayCaster(const TriangleMesh& mesh, std::vector<bool> skip, RayCasterBackend backend)
    : backend_(backend) {
  if (!skip.empty() && skip.size() != mesh.triangles.size())
    throw InputError("ray caster: skip mask has " + std::to_string(skip.size()) + " entries for " +
                     std::to_string(mesh.triangles.size()) + " triangles");
  if (backend == RayCasterBackend::Embree) {
    if (!embreeAvailable()) throw InputError("ray caster: Embree backend not compiled in");
    impl_ = sim::makeEmbreeCaster(mesh, skip);
  } else {
    impl_ = sim::makeCgalCaster(mesh, skip);
  }
}

RayCaster::~RayCaster() = default;

RayHit RayCaster::cast(const Ray& ray, double max_range, double min_range) const {
  return impl_->cast(ray, max_range, min_range);
}

void RayCaster::castAll(const std::vector<Ray>& rays, std::vector<RayHit>& hits, double max_range,
                        double min_range) const {
  hits.resize(rays.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 512),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        hits[i] = impl_->cast(rays[i], max_range, min_range);
                    });
}

const TriangleMesh& RayCaster::mesh() const { return impl_->mesh; }

bool RayCaster::embreeAvailable() {
#ifdef PLUMB_HAVE_EMBREE
  return true;
#else
  return false;
#endif
}

RayCasterBackend RayCaster::defaultBackend() {
  return embreeAvailable() ? RayCasterBackend::Embree : RayCasterBackend::Cgal;
}

std::string RayCaster::backendName(RayCasterBackend b) {
  return b == RayCasterBackend::Embree ? "embree" : "cgal-aabb";
}

}  // namespace plumb
