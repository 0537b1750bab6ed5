// CGAL AABB-tree backend of the ray caster (the only file that includes CGAL headers).
//
// The tree is built once (constructor) over Simple_cartesian<double> (Epick-like, no exact
// constructions). AABB_tree::first_intersection() is not used for queries: in CGAL 5.5 it
// runs a best-first search with a heap allocated per ray and computes the full CGAL
// Ray_3/Triangle_3 intersection object (a variant) for every leaf it reaches without a leaf
// box test (~12-80 us per ray here). Instead the same tree is walked with
// AABB_tree::traversal_with_priority() and a closest-hit traits class: slab test of the
// node boxes clipped to (min_range, nearest hit so far], nearer child first, and a
// Moeller-Trumbore test in double on the leaves.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <tuple>
#include <utility>

#include "simulation/ray_caster_backends.hpp"

namespace plumb::sim {

namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

struct Query {
  Eigen::Vector3d origin, direction, inverse;  // inverse: 1/direction, huge for zero components
  double t_min;
};

// Traversal traits for AABB_tree::traversal_with_priority: nearest hit along the ray.
class ClosestHit {
 public:
  using Priority = double;
  ClosestHit(const Triangles& triangles, double t_max) : triangles_(triangles), t_(t_max) {}
  // Note: pieces of one split triangle share exact midpoints, so a ray through a piece edge
  // hits one of the two pieces (the same inclusive edge tests as for mesh edges).

  bool go_further() const { return true; }

  void intersection(const Query& q, const Primitive& p) {
    const auto i = static_cast<std::size_t>(p.id() - triangles_.cbegin());
    const K::Triangle_3& tri = triangles_[i];
    const auto v = [&](int k) { return Eigen::Vector3d(tri[k].x(), tri[k].y(), tri[k].z()); };
    const Eigen::Vector3d a = v(0), e1 = v(1) - a, e2 = v(2) - a;
    const Eigen::Vector3d pv = q.direction.cross(e2);
    const double det = e1.dot(pv);
    if (det == 0.0) return;  // ray parallel to the triangle's plane (Embree misses these too)
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = q.origin - a;
    const double u = s.dot(pv) * inv;
    if (u < 0.0 || u > 1.0) return;
    const Eigen::Vector3d qv = s.cross(e1);
    const double w = q.direction.dot(qv) * inv;
    if (w < 0.0 || u + w > 1.0) return;
    const double t = e2.dot(qv) * inv;
    if (t > q.t_min && t < t_) {
      t_ = t;
      hit_ = i;
    }
  }

  template <class Node>
  bool do_intersect(const Query& q, const Node& node) const {
    return std::get<0>(slab(q, node.bbox()));
  }
  template <class Node>
  std::pair<bool, Priority> do_intersect_with_priority(const Query& q, const Node& node) const {
    const auto [hit, entry, exit] = slab(q, node.bbox());
    // Higher priority = nearer box; among boxes the origin lies in (entry = t_min) the one the
    // ray leaves first, which usually holds the nearest surface.
    return {hit, -(entry + 1e-3 * exit)};
  }

  bool found() const { return hit_ != kNone; }
  std::size_t index() const { return hit_; }
  double distance() const { return t_; }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  // Whether the ray meets the box, entry and exit distances within [t_min, nearest hit so far].
  std::tuple<bool, double, double> slab(const Query& q, const CGAL::Bbox_3& b) const {
    double t0 = q.t_min, t1 = t_;
    for (int k = 0; k < 3; ++k) {
      double a = (b.min(k) - q.origin[k]) * q.inverse[k], c = (b.max(k) - q.origin[k]) * q.inverse[k];
      if (a > c) std::swap(a, c);
      t0 = std::max(t0, a);
      t1 = std::min(t1, c * (1.0 + 1e-12) + 1e-12);  // keep hits on the box faces
    }
    return {t0 <= t1, t0, t1};
  }

  const Triangles& triangles_;
  double t_;
  std::size_t hit_ = kNone;
};

class CgalCaster final : public RayCaster::Impl {
 public:
  CgalCaster(const TriangleMesh& m, const std::vector<bool>& skip) : Impl(m) {
    std::vector<std::uint32_t> kept;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if ((skip.empty() || !skip[t]) && planes[t].normal != Eigen::Vector3d::Zero()) kept.push_back(static_cast<std::uint32_t>(t));
    // Large triangles (slabs, long walls) give huge, overlapping node boxes in CGAL's
    // median-split tree, so every ray visits most of the tree. Split them (longest edge at its
    // midpoint) down to an edge length L; the pieces keep their triangle's index. L starts at
    // 1/50 of the model diagonal and grows until the pieces are at most 4x the triangles.
    const double diagonal = m.bounds().empty() ? 0.0 : (m.bounds().max - m.bounds().min).norm();
    double limit = diagonal / 50.0;
    while (limit > 0.0) {
      std::size_t pieces = 0;
      for (auto t : kept) pieces += split(m, t, limit, nullptr);
      if (pieces <= 4 * kept.size() + 1000) break;
      limit *= 1.5;
    }
    for (auto t : kept) split(m, t, limit, this);
    if (!triangles_.empty()) {
      tree_.insert(triangles_.cbegin(), triangles_.cend());
      tree_.build();
    }
  }

  RayHit cast(const Ray& ray, double max_range, double min_range) const override {
    RayHit hit;
    if (triangles_.empty()) return hit;
    Query q{ray.origin, ray.direction, Eigen::Vector3d(), min_range};
    for (int k = 0; k < 3; ++k) q.inverse[k] = ray.direction[k] != 0.0 ? 1.0 / ray.direction[k] : 1e300;
    ClosestHit traits(triangles_, std::min(max_range * (1 + 1e-6), 1e300));
    tree_.traversal_with_priority(q, traits);
    if (!traits.found()) return hit;
    const std::uint32_t t = index_[traits.index()];
    const double d = refineDistance(t, ray, traits.distance());
    if (d <= min_range || d > max_range) return hit;
    hit.distance = d;
    hit.triangle = t;
    return hit;
  }

 private:
  // Splits mesh triangle t into pieces with edges <= limit (limit 0: no split); appends them
  // to `out` if given; returns the number of pieces.
  static std::size_t split(const TriangleMesh& m, std::uint32_t t, double limit, CgalCaster* out) {
    const auto& tri = m.triangles[t];
    return splitTriangle(m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]], t, limit, out, 0);
  }
  static std::size_t splitTriangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                                   std::uint32_t t, double limit, CgalCaster* out, int depth) {
    const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
    const double longest = std::max({ab, bc, ca});
    if (limit <= 0.0 || longest <= limit * limit || depth >= 24) {
      if (out) {
        out->triangles_.emplace_back(K::Point_3(a.x(), a.y(), a.z()), K::Point_3(b.x(), b.y(), b.z()),
                                     K::Point_3(c.x(), c.y(), c.z()));
        out->index_.push_back(t);
      }
      return 1;
    }
    if (longest == ab) {
      const Eigen::Vector3d mid = 0.5 * (a + b);
      return splitTriangle(a, mid, c, t, limit, out, depth + 1) + splitTriangle(mid, b, c, t, limit, out, depth + 1);
    }
    if (longest == bc) {
      const Eigen::Vector3d mid = 0.5 * (b + c);
      return splitTriangle(a, b, mid, t, limit, out, depth + 1) + splitTriangle(a, mid, c, t, limit, out, depth + 1);
    }
    const Eigen::Vector3d mid = 0.5 * (c + a);
    return splitTriangle(a, b, mid, t, limit, out, depth + 1) + splitTriangle(mid, b, c, t, limit, out, depth + 1);
  }

  Triangles triangles_;
  std::vector<std::uint32_t> index_;  ///< mesh triangle of each piece
  Tree tree_;
};

}  // namespace

std::unique_ptr<RayCaster::Impl> makeCgalCaster(const TriangleMesh& mesh, const std::vector<bool>& skip) {
  return std::make_unique<CgalCaster>(mesh, skip);
}

}  // namespace plumb::sim
