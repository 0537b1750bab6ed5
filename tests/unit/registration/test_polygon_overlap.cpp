// The raster overlap used by the 2021 score must be within 1% of exact polygon Boolean
// operations (CGAL 2D regularized Boolean set operations, exact kernel).
#include <gtest/gtest.h>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <random>

#include "registration/planes/polygon_raster.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWH = CGAL::Polygon_with_holes_2<K>;

namespace {
// A star-ish simple polygon with a hole, in the plane z = 0.
PlanarPolygon randomPolygon(std::mt19937_64& rng, const Eigen::Vector2d& c) {
  std::uniform_real_distribution<double> r(2.0, 4.0);
  PlanarPolygon p;
  p.normal = Eigen::Vector3d::UnitZ();
  p.offset = 0;
  p.origin = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector2d> outer;
  const int n = 9;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    outer.push_back(c + r(rng) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  p.rings.push_back(outer);
  std::vector<Eigen::Vector2d> hole;
  for (int k = n - 1; k >= 0; --k) {  // clockwise
    const double a = 2 * M_PI * k / n;
    hole.push_back(c + 0.8 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  p.rings.push_back(hole);
  return p;
}

PolygonWH toCgal(const PlanarPolygon& p) {
  Polygon2 outer;
  for (const auto& q : p.rings[0]) outer.push_back(K::Point_2(q.x(), q.y()));
  PolygonWH pwh(outer);
  for (std::size_t r = 1; r < p.rings.size(); ++r) {
    Polygon2 h;
    for (const auto& q : p.rings[r]) h.push_back(K::Point_2(q.x(), q.y()));
    if (h.orientation() != CGAL::CLOCKWISE) h.reverse_orientation();
    pwh.add_hole(h);
  }
  return pwh;
}

double exactOverlap(const PlanarPolygon& a, const PlanarPolygon& b) {
  std::vector<PolygonWH> out;
  CGAL::intersection(toCgal(a), toCgal(b), std::back_inserter(out));
  double area = 0;
  for (const auto& pwh : out) {
    area += CGAL::to_double(pwh.outer_boundary().area());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) area += CGAL::to_double(h->area());
  }
  return area;
}
}  // namespace

TEST(PolygonOverlap, RasterWithinOnePercentOfExactBooleanOps) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> shift(-2.5, 2.5);
  int compared = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const PlanarPolygon a = randomPolygon(rng, {0, 0});
    const PlanarPolygon b = randomPolygon(rng, {shift(rng), shift(rng)});
    const double exact = exactOverlap(a, b);
    if (exact < 1.0) continue;
    const PolygonRaster ra(a, 256, 1 << 20), rb(b, 256, 1 << 20);
    const double approx = overlapArea(ra, rb, RigidTransform());
    EXPECT_NEAR(approx, exact, 0.01 * exact) << "trial " << trial;
    ++compared;
  }
  EXPECT_GE(compared, 10);
}

TEST(PolygonOverlap, RasterAreaOfRectangleWithHole) {
  const PlanarPolygon p =
      test::makeRectPolygon({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 4, 3, {{1, 1, 2, 2}});
  const PolygonRaster r(p, 256);
  EXPECT_NEAR(r.area(), 11.0, 0.11);
  EXPECT_TRUE(r.inside({0.5, 0.5}));
  EXPECT_FALSE(r.inside({1.5, 1.5}));  // in the hole
  EXPECT_FALSE(r.inside({4.5, 0.5}));
}
