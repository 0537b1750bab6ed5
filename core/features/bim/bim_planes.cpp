// Step 1 of bim_features.hpp: coplanar triangles grouped and merged into polygons.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "features/bim/bim_features.hpp"
#include "features/bim/plane_union.hpp"
#include "features/planes/plane_fit.hpp"
#include "features/planes/polygon_2d.hpp"

namespace plumb {

namespace {

struct TrianglePlane {
  std::uint32_t triangle = 0;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double area = 0.0;
};

/// The non-degenerate triangles, largest first (index order among equals: deterministic).
std::vector<TrianglePlane> trianglePlanes(const TriangleMesh& mesh) {
  std::vector<TrianglePlane> out;
  out.reserve(mesh.triangleCount());
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const double area = mesh.triangleArea(t);
    const Eigen::Vector3d n = mesh.triangleNormal(t);
    if (!(area > 1e-10) || !n.allFinite() || n.squaredNorm() < 0.5) continue;
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d c =
        (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] + mesh.vertices[tri[2]]) / 3.0;
    out.push_back({static_cast<std::uint32_t>(t), n, c, area});
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const TrianglePlane& a, const TrianglePlane& b) { return a.area > b.area; });
  return out;
}

std::uint64_t cellKey(long x, long y, long z) {
  const auto part = [](long v) { return static_cast<std::uint64_t>(v + (1L << 20)) & 0x1FFFFF; };
  return (part(x) << 42) | (part(y) << 21) | part(z);
}

/// Normal clusters: greedily, largest triangle first, each triangle joins the cluster whose
/// first normal is closest within the tolerance (a hash grid on the unit normal finds the
/// candidates), else starts one. Returns indices into `tp` per cluster.
std::vector<std::vector<std::size_t>> normalClusters(const std::vector<TrianglePlane>& tp,
                                                     double tolerance_deg) {
  const double tol = tolerance_deg * M_PI / 180.0, cos_tol = std::cos(tol);
  const double cell = std::max(tol, 1e-6);
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;  // cell -> clusters
  std::vector<Eigen::Vector3d> first;
  std::vector<std::vector<std::size_t>> clusters;
  for (std::size_t i = 0; i < tp.size(); ++i) {
    const Eigen::Vector3d q = tp[i].normal / cell;
    const long cx = std::lround(q.x()), cy = std::lround(q.y()), cz = std::lround(q.z());
    std::size_t best = clusters.size();
    double best_dot = cos_tol;
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(cellKey(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (std::size_t c : it->second)
            if (const double d = first[c].dot(tp[i].normal); d >= best_dot) best_dot = d, best = c;
        }
    if (best == clusters.size()) {
      first.push_back(tp[i].normal);
      clusters.emplace_back();
      grid[cellKey(cx, cy, cz)].push_back(best);
    }
    clusters[best].push_back(i);
  }
  return clusters;
}

/// Splits a normal cluster by plane offset (sorted, a gap above `tolerance` starts a plane).
std::vector<std::vector<std::size_t>> offsetGroups(const std::vector<TrianglePlane>& tp,
                                                   std::vector<std::size_t> cluster,
                                                   double tolerance) {
  const Eigen::Vector3d n = tp[cluster.front()].normal;
  std::stable_sort(cluster.begin(), cluster.end(), [&](std::size_t a, std::size_t b) {
    return n.dot(tp[a].centroid) < n.dot(tp[b].centroid);
  });
  std::vector<std::vector<std::size_t>> groups;
  double last = -1e300;
  for (std::size_t i : cluster) {
    const double d = n.dot(tp[i].centroid);
    if (groups.empty() || d - last > tolerance) groups.emplace_back();
    groups.back().push_back(i);
    last = d;
  }
  return groups;
}

/// The plane of a group: area-weighted normal and centroid, frame as the scan polygons'.
PlanarPolygon groupPlane(const std::vector<TrianglePlane>& tp, const std::vector<std::size_t>& g) {
  PlanarPolygon p;
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (std::size_t i : g) {
    n += tp[i].area * tp[i].normal;
    c += tp[i].area * tp[i].centroid;
    area += tp[i].area;
  }
  p.normal = n.normalized();
  p.centroid = c / area;
  p.offset = p.normal.dot(p.centroid);
  setPlaneFrame(p);
  return p;
}

/// Area-weighted centroid of the rings (holes clockwise: negative area), plane coordinates.
Eigen::Vector2d ringsCentroid(const std::vector<std::vector<Eigen::Vector2d>>& rings, double* area) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double a = 0.0;
  for (const auto& r : rings)
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Eigen::Vector2d& p = r[i];
      const Eigen::Vector2d& q = r[(i + 1) % r.size()];
      const double cross = p.x() * q.y() - q.x() * p.y();
      a += 0.5 * cross;
      sum += cross * (p + q) / 6.0;
    }
  *area = a;
  return std::abs(a) > 0 ? Eigen::Vector2d(sum / a) : Eigen::Vector2d::Zero();
}

/// The group's triangles merged in its plane, one polygon per connected part.
void addGroupPolygons(const TriangleMesh& mesh, const std::vector<TrianglePlane>& tp,
                      const std::vector<std::size_t>& g, double min_area,
                      std::vector<PlanarPolygon>& out) {
  const PlanarPolygon plane = groupPlane(tp, g);
  std::vector<std::array<Eigen::Vector2d, 3>> tris;
  tris.reserve(g.size());
  for (std::size_t i : g) {
    const auto& t = mesh.triangles[tp[i].triangle];
    tris.push_back({plane.to2d(mesh.vertices[t[0]]), plane.to2d(mesh.vertices[t[1]]),
                    plane.to2d(mesh.vertices[t[2]])});
  }
  for (auto& part : bim_detail::unionOfTriangles(tris)) {
    PlanarPolygon p = plane;
    p.rings.push_back(std::move(part.outer));
    for (auto& h : part.holes) p.rings.push_back(std::move(h));
    const Eigen::Vector2d c = ringsCentroid(p.rings, &p.area);
    if (!(p.area >= min_area) || p.rings.front().size() < 3) continue;
    p.centroid = p.to3d(c);
    out.push_back(std::move(p));
  }
}

}  // namespace

std::vector<PlanarPolygon> bimPlanes(const BimModel& model, const BimFeatureParams& params,
                                     Progress* progress) {
  validateParams(BimFeatureParams::schema(), params);
  const std::vector<TrianglePlane> tp = trianglePlanes(model.mesh);
  std::vector<std::vector<std::size_t>> groups;
  for (auto& cluster : normalClusters(tp, params.angle_tolerance_deg))
    for (auto& g : offsetGroups(tp, std::move(cluster), params.distance_tolerance))
      groups.push_back(std::move(g));
  std::vector<PlanarPolygon> out;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    if (k % 64 == 0) {
      checkCanceled(progress);
      reportProgress(progress, double(k) / double(groups.size()), "BIM planes");
    }
    addGroupPolygons(model.mesh, tp, groups[k], params.min_polygon_area, out);
  }
  // Largest first, as the scan side lists them.
  std::stable_sort(out.begin(), out.end(),
                   [](const PlanarPolygon& a, const PlanarPolygon& b) { return a.area > b.area; });
  return out;
}

}  // namespace plumb
