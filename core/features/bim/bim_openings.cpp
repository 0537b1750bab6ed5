// Step 3 of bim_features.hpp: openings from IfcWindow / IfcDoor elements on their host wall
// faces, or from the holes of vertical polygons when the model names no such element.
#include <cmath>
#include <limits>
#include <optional>

#include "features/bim/bim_features.hpp"

namespace plumb {

namespace {

bool isOpeningElement(const BimElement& e) {
  return e.type.rfind("IfcWindow", 0) == 0 || e.type.rfind("IfcDoor", 0) == 0;
}

/// Vertex positions of each opening element (empty for the other elements).
std::vector<std::vector<Eigen::Vector3d>> openingElementVertices(const BimModel& m) {
  std::vector<std::vector<Eigen::Vector3d>> out(m.elements.size());
  if (m.triangle_element.size() != m.mesh.triangleCount()) return out;
  std::vector<bool> wanted(m.elements.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) wanted[e] = isOpeningElement(m.elements[e]);
  for (std::size_t t = 0; t < m.mesh.triangleCount(); ++t) {
    const auto e = m.triangle_element[t];
    if (e >= wanted.size() || !wanted[e]) continue;
    for (auto v : m.mesh.triangles[t]) out[e].push_back(m.mesh.vertices[v]);
  }
  return out;
}

/// The (u, v) box of points in a polygon's plane frame.
void planeBox(const PlanarPolygon& p, const std::vector<Eigen::Vector3d>& pts, Eigen::Vector2d& lo,
              Eigen::Vector2d& hi) {
  lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const auto& x : pts) {
    const Eigen::Vector2d q = p.to2d(x);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
}

/// Corners of the box [lo, hi] in a vertical polygon's frame (u = Z x n: to the right seen
/// from the side the face looks at, v up): bottom-left, bottom-right, top-right, top-left.
Opening rectangleOn(const PlanarPolygon& p, int plane, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  Opening o;
  o.corners = {p.to3d(lo), p.to3d({hi.x(), lo.y()}), p.to3d(hi), p.to3d({lo.x(), hi.y()})};
  o.facade = plane;
  return o;
}

/// The element's vertices on the face (its reveals meet the face along the opening's edges:
/// exact on an oblique wall too), else all of them (a frame set inside the wall).
std::vector<Eigen::Vector3d> onFace(const PlanarPolygon& p, const std::vector<Eigen::Vector3d>& pts,
                                    const BimFeatureParams& params) {
  std::vector<Eigen::Vector3d> on;
  for (const auto& x : pts)
    if (std::abs(p.signedDistance(x)) <= params.distance_tolerance) on.push_back(x);
  return on.size() >= 4 ? on : pts;
}

/// The box of the outer ring of a polygon, plane coordinates.
void ringBox(const PlanarPolygon& p, Eigen::Vector2d& lo, Eigen::Vector2d& hi) {
  lo = hi = p.rings.front().front();
  for (const auto& v : p.rings.front()) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
}

/// A vertical wall face the element lies behind: how well it hosts it (lower is better:
/// the element's depth along the normal plus its distance behind the face), or nullopt.
std::optional<double> hostCost(const PlanarPolygon& p, const std::vector<Eigen::Vector3d>& pts,
                               const Eigen::Vector3d& centre, const BimFeatureParams& params) {
  if (p.rings.empty() || !p.isVertical(params.vertical_tolerance_deg)) return std::nullopt;
  const double s = p.signedDistance(centre);  // < 0: behind the face (inside the wall)
  if (s > params.distance_tolerance + 0.01 || s < -params.max_wall_thickness) return std::nullopt;
  // The wall face reaches around the element (its box holds the element's and is larger): not
  // the element's own faces (a glass pane, a panel).
  Eigen::Vector2d rlo, rhi, elo, ehi;
  ringBox(p, rlo, rhi);
  planeBox(p, pts, elo, ehi);
  constexpr double kMargin = 0.01;  // metres
  if ((elo.array() < rlo.array() - kMargin).any() || (ehi.array() > rhi.array() + kMargin).any())
    return std::nullopt;
  if ((rhi - rlo).prod() < 1.5 * (ehi - elo).prod()) return std::nullopt;
  double dmin = std::numeric_limits<double>::infinity(), dmax = -dmin;
  for (const auto& x : pts) {
    const double d = p.signedDistance(x);
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
  }
  return (dmax - dmin) + std::abs(s);
}

/// The element's rectangle on its best host face and on the nearest opposite face.
void addElementOpenings(const std::vector<PlanarPolygon>& planes,
                        const std::vector<Eigen::Vector3d>& pts, const BimFeatureParams& params,
                        BimOpeningResult& out) {
  Eigen::Vector3d lo = pts.front(), hi = lo;
  for (const auto& x : pts) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  std::vector<std::optional<double>> cost(planes.size());
  int first = -1;
  for (std::size_t i = 0; i < planes.size(); ++i) {
    cost[i] = hostCost(planes[i], pts, centre, params);
    if (cost[i] && (first < 0 || *cost[i] < *cost[std::size_t(first)])) first = int(i);
  }
  if (first < 0) {
    ++out.without_host;
    return;
  }
  const double cos_tol = std::cos(params.vertical_tolerance_deg * M_PI / 180.0);
  int second = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < planes.size(); ++i) {
    if (!cost[i] || planes[i].normal.dot(planes[std::size_t(first)].normal) > -cos_tol) continue;
    const double s = std::abs(planes[i].signedDistance(centre));
    if (s < nearest) nearest = s, second = int(i);
  }
  for (int f : {first, second}) {
    if (f < 0) continue;
    Eigen::Vector2d a, b;
    planeBox(planes[std::size_t(f)], onFace(planes[std::size_t(f)], pts, params), a, b);
    out.openings.push_back(rectangleOn(planes[std::size_t(f)], f, a, b));
  }
}

/// Holes of vertical polygons within the size limits (models without typed openings).
void addHoleOpenings(const std::vector<PlanarPolygon>& planes, const BimFeatureParams& params,
                     BimOpeningResult& out) {
  for (std::size_t i = 0; i < planes.size(); ++i) {
    const PlanarPolygon& p = planes[i];
    if (!p.isVertical(params.vertical_tolerance_deg)) continue;
    for (std::size_t h = 1; h < p.rings.size(); ++h) {
      Eigen::Vector2d lo = p.rings[h].front(), hi = lo;
      for (const auto& v : p.rings[h]) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
      const Eigen::Vector2d size = hi - lo;
      if (size.minCoeff() < params.min_opening_size || size.maxCoeff() > params.max_opening_size)
        continue;
      out.openings.push_back(rectangleOn(p, int(i), lo, hi));
    }
  }
}

}  // namespace

BimOpeningResult bimOpenings(const BimModel& model, const std::vector<PlanarPolygon>& planes,
                             const BimFeatureParams& params) {
  validateParams(BimFeatureParams::schema(), params);
  BimOpeningResult out;
  const auto vertices = openingElementVertices(model);
  for (const auto& pts : vertices) {
    if (pts.size() < 3) continue;
    ++out.elements;
    addElementOpenings(planes, pts, params, out);
  }
  bool typed = false;
  for (const auto& e : model.elements) typed = typed || isOpeningElement(e);
  if (!typed) {
    out.from_holes = true;
    addHoleOpenings(planes, params, out);
  }
  return out;
}

}  // namespace plumb
