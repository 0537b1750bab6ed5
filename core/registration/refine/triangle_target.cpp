// The model surface as a refinement target: visibility by ray casting, closest points on the
// visible triangles (triangle_target.hpp).
#include "registration/refine/triangle_target.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "simulation/mesh_closest_points.hpp"
#include "simulation/ray_caster.hpp"

namespace plumb::refine_detail {

namespace {

/// Closest point on a set of triangles of the caster's mesh, with the triangle's normal as
/// the plane.
class TriangleSurface final : public TargetSurface {
 public:
  TriangleSurface(const RayCaster& caster, const std::vector<std::uint32_t>& chosen, bool facing_rule)
      : caster_(caster), closest_(caster.mesh().vertices, caster.mesh().triangles, chosen),
        facing_rule_(facing_rule) {}

  bool nearest(const Eigen::Vector3d& x, double max_d, Eigen::Vector3d& q,
               Eigen::Vector3d& n) const override {
    MeshClosestPoints::Closest c;
    if (!closest_.closest(x, c) || (c.point - x).squaredNorm() > max_d * max_d) return false;
    n = caster_.triangleNormal(c.triangle);
    if (n.squaredNorm() < 0.5) return false;  // degenerate triangle
    if (facing_rule_ && n.dot(x - c.point) < -kFacingTolerance) return false;
    q = c.point;
    return true;
  }

 private:
  const RayCaster& caster_;
  MeshClosestPoints closest_;
  bool facing_rule_;
};

TriangleMesh localCopy(const TriangleMesh& mesh, const Eigen::Vector3d& origin) {
  TriangleMesh local;
  local.triangles = mesh.triangles;
  local.vertices.reserve(mesh.vertices.size());
  for (const auto& v : mesh.vertices) local.vertices.push_back(v - origin);
  return local;
}

}  // namespace

VisibleSet visibleTriangles(const RayCaster& caster, const SourceRays& src, const Eigen::Matrix3d& R,
                            const Eigen::Vector3d& t) {
  const auto t0 = std::chrono::steady_clock::now();
  VisibleSet out;
  std::vector<Ray> rays;
  rays.reserve(src.origins.size());
  for (std::size_t i = 0; i < src.origins.size() && i < src.points.size(); ++i) {
    const Eigen::Vector3d o = R * src.origins[i] + t;
    const Eigen::Vector3d d = R * (src.points[i] - src.origins[i]);
    const double len = d.norm();
    if (!(len > 1e-6)) continue;
    rays.push_back({o, d / len});
  }
  std::vector<RayHit> hits;
  caster.castAll(rays, hits);
  std::vector<char> seen(caster.mesh().triangles.size(), 0);
  for (std::size_t r = 0; r < hits.size(); ++r) {
    if (!hits[r].hit()) continue;
    ++out.hits;
    out.back_facing += caster.triangleNormal(hits[r].triangle).dot(rays[r].direction) > 0;
    seen[hits[r].triangle] = 1;
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (seen[k]) out.triangles.push_back(std::uint32_t(k));
  out.rays = rays.size();
  out.seconds = secondsSince(t0);
  return out;
}

TriangleTarget::TriangleTarget(const TriangleMesh& mesh, const Eigen::Vector3d& origin) {
  if (mesh.triangles.empty()) throw InputError("refinement: the model has no triangles");
  caster_ = std::make_unique<RayCaster>(localCopy(mesh, origin));
}

TriangleTarget::~TriangleTarget() = default;

std::size_t TriangleTarget::triangleCount() const { return caster_->mesh().triangles.size(); }

std::unique_ptr<TargetSurface> TriangleTarget::visibleSurface(const VisibleSet& visible) const {
  return std::make_unique<TriangleSurface>(*caster_, visible.triangles, false);
}

std::unique_ptr<TargetSurface> TriangleTarget::everySurface() const {
  return std::make_unique<TriangleSurface>(*caster_, MeshClosestPoints::all(triangleCount()), false);
}

std::unique_ptr<TargetSurface> TriangleTarget::frontFacingSurface() const {
  return std::make_unique<TriangleSurface>(*caster_, MeshClosestPoints::all(triangleCount()), true);
}

}  // namespace plumb::refine_detail
