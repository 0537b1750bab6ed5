#include "features/bim/plane_union.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <cmath>
#include <iterator>

namespace plumb::bim_detail {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon2 = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<Kernel>;

Ring toRing(const Polygon2& p) {
  Ring r;
  r.reserve(p.size());
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v)
    r.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
  return r;
}

/// Coordinates rounded to the micrometre: a vertex the file repeats with a rounding difference
/// (one copy per element) becomes one point, so touching triangles share their edges exactly.
Kernel::Point_2 snapped(const Eigen::Vector2d& p) {
  return {std::round(p.x() * 1e6) * 1e-6, std::round(p.y() * 1e6) * 1e-6};
}

}  // namespace

Ring withoutCollinearVertices(Ring ring, double tolerance) {
  bool changed = true;
  while (changed && ring.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
      const Eigen::Vector2d& a = ring[(i + ring.size() - 1) % ring.size()];
      const Eigen::Vector2d& b = ring[i];
      const Eigen::Vector2d& c = ring[(i + 1) % ring.size()];
      const Eigen::Vector2d ac = c - a;
      const double len = ac.norm();
      const Eigen::Vector2d ab = b - a;
      const double off = len > 0 ? std::abs(ac.x() * ab.y() - ac.y() * ab.x()) / len : ab.norm();
      const bool between = ab.dot(ac) >= -tolerance * len && (b - c).dot(a - c) >= -tolerance * len;
      if (off <= tolerance && between) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  return ring;
}

std::vector<PolygonWithHoles> unionOfTriangles(
    const std::vector<std::array<Eigen::Vector2d, 3>>& triangles) {
  std::vector<Polygon2> polygons;
  polygons.reserve(triangles.size());
  for (const auto& t : triangles) {
    Polygon2 p;
    for (const auto& v : t) p.push_back(snapped(v));
    const auto orientation = p.orientation();
    if (orientation == CGAL::COLLINEAR) continue;
    if (orientation == CGAL::CLOCKWISE) p.reverse_orientation();
    polygons.push_back(std::move(p));
  }
  std::vector<PolygonWithHoles> out;
  if (polygons.empty()) return out;
  CGAL::Polygon_set_2<Kernel> set;
  set.join(polygons.begin(), polygons.end());  // aggregated (divide and conquer) union
  std::vector<PolygonWithHoles2> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  constexpr double kCollinear = 1e-6;  // metres
  for (const auto& part : parts) {
    PolygonWithHoles pwh;
    pwh.outer = withoutCollinearVertices(toRing(part.outer_boundary()), kCollinear);
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h)
      pwh.holes.push_back(withoutCollinearVertices(toRing(*h), kCollinear));
    out.push_back(std::move(pwh));
  }
  return out;
}

}  // namespace plumb::bim_detail
