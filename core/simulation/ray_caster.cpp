#include "simulation/ray_caster.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "common/error.hpp"
#include "simulation/ray_caster_backends.hpp"

namespace plumb {

RayCaster::Impl::Impl(const TriangleMesh& m) : mesh(m) {
  planes.resize(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Eigen::Vector3d n = m.triangleNormal(t);
    planes[t] = {n, n.dot(m.vertices[m.triangles[t][0]])};
  }
}

void RayCaster::Impl::castBatch(const Ray* rays, std::size_t n, RayHit* hits, double max_range,
                                double min_range, bool) const {
  for (std::size_t i = 0; i < n; ++i) hits[i] = cast(rays[i], max_range, min_range);
}

double RayCaster::Impl::refineDistance(std::uint32_t t, const Ray& ray, double approx) const {
  const Plane& p = planes[t];
  const double denom = p.normal.dot(ray.direction);
  const double d = (p.offset - p.normal.dot(ray.origin)) / denom;
  return std::abs(d - approx) < 1e-3 * (1.0 + std::abs(approx)) ? d : approx;  // NaN/inf: approx
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
  // Fixed chunks (not TBB's thread-dependent split points) so a ray is always traced in the
  // same packet whatever the thread count: results are bit-identical for 1 or N threads.
  constexpr std::size_t kChunk = 256;
  const std::size_t chunks = (rays.size() + kChunk - 1) / kChunk;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 4), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c) {
      const std::size_t begin = c * kChunk, n = std::min(kChunk, rays.size() - begin);
      impl_->castBatch(rays.data() + begin, n, hits.data() + begin, max_range, min_range, false);
    }
  });
}

void RayCaster::castBatch(const Ray* rays, std::size_t n, RayHit* hits, double max_range, double min_range) const {
  impl_->castBatch(rays, n, hits, max_range, min_range, true);
}

const TriangleMesh& RayCaster::mesh() const { return impl_->mesh; }

const Eigen::Vector3d& RayCaster::triangleNormal(std::uint32_t t) const { return impl_->planes[t].normal; }

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
