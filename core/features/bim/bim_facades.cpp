// Step 2 of bim_features.hpp: façades are the large vertical polygons whose outward side
// sees outside the model.
#include <cmath>

#include "features/bim/bim_features.hpp"
#include "features/planes/polygon_2d.hpp"
#include "simulation/ray_caster.hpp"

namespace plumb {

namespace {

bool insidePolygon(const PlanarPolygon& p, const Eigen::Vector2d& q) {
  if (p.rings.empty() || !ringContains(p.rings.front(), q)) return false;
  for (std::size_t h = 1; h < p.rings.size(); ++h)
    if (ringContains(p.rings[h], q)) return false;
  return true;
}

/// Points of a regular 8 x 8 grid over the outer ring's box that lie in the polygon.
std::vector<Eigen::Vector3d> pointsOnPolygon(const PlanarPolygon& p) {
  constexpr int kSide = 8;
  Eigen::Vector2d lo = p.rings.front().front(), hi = lo;
  for (const auto& v : p.rings.front()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const Eigen::Vector2d q = lo + Eigen::Vector2d((i + 0.5) / kSide * (hi.x() - lo.x()),
                                                     (j + 0.5) / kSide * (hi.y() - lo.y()));
      if (insidePolygon(p, q)) out.push_back(p.to3d(q));
    }
  return out;
}

bool isFacadeCandidate(const PlanarPolygon& p, const BimFeatureParams& params) {
  return !p.rings.empty() && p.area >= params.min_facade_area &&
         p.isVertical(params.vertical_tolerance_deg);
}

}  // namespace

std::vector<int> bimFacades(const BimModel& model, const std::vector<PlanarPolygon>& planes,
                            const BimFeatureParams& params) {
  std::vector<int> out;
  bool any = false;
  for (const auto& p : planes) any = any || isFacadeCandidate(p, params);
  if (!any || model.mesh.triangleCount() == 0) return out;
  const RayCaster caster(model.mesh);
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const PlanarPolygon& p = planes[i];
    if (!isFacadeCandidate(p, params)) continue;
    const std::vector<Eigen::Vector3d> points = pointsOnPolygon(p);
    std::vector<Ray> rays;
    for (const auto& x : points) rays.push_back({x + 1e-3 * p.normal, p.normal});
    std::vector<RayHit> hits;
    caster.castAll(rays, hits);
    std::size_t escaped = 0;
    for (const auto& h : hits) escaped += h.hit() ? 0 : 1;
    if (!rays.empty() && double(escaped) >= params.facade_outside_ratio * double(rays.size()))
      out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace plumb
