// CGAL AABB-tree backend of the ray caster (the only file that includes CGAL headers).
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "simulation/ray_caster_backends.hpp"

namespace plumb::sim {

namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

class CgalCaster final : public RayCaster::Impl {
 public:
  CgalCaster(const TriangleMesh& m, const std::vector<bool>& skip) {
    mesh = m;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (!skip.empty() && skip[t]) continue;
      const auto& tri = m.triangles[t];
      const auto p = [&](int k) {
        const auto& v = m.vertices[tri[static_cast<std::size_t>(k)]];
        return K::Point_3(v.x(), v.y(), v.z());
      };
      const K::Triangle_3 triangle(p(0), p(1), p(2));
      if (triangle.is_degenerate()) continue;
      triangles_.push_back(triangle);
      index_.push_back(static_cast<std::uint32_t>(t));
    }
    if (!triangles_.empty()) {
      tree_.insert(triangles_.cbegin(), triangles_.cend());
      tree_.build();
    }
  }

  RayHit cast(const Ray& ray, double max_range, double min_range) const override {
    RayHit hit;
    if (triangles_.empty()) return hit;
    const Eigen::Vector3d o = ray.origin + min_range * ray.direction;
    const K::Ray_3 query(K::Point_3(o.x(), o.y(), o.z()),
                         K::Vector_3(ray.direction.x(), ray.direction.y(), ray.direction.z()));
    const auto result = tree_.first_intersection(query);
    if (!result) return hit;
    const auto t = index_[static_cast<std::size_t>(result->second - triangles_.cbegin())];
    double d = distanceToTrianglePlane(mesh, t, ray);
    if (const auto* s = boost::get<K::Segment_3>(&result->first)) {  // ray within the plane
      const Eigen::Vector3d a(s->source().x(), s->source().y(), s->source().z());
      const Eigen::Vector3d b(s->target().x(), s->target().y(), s->target().z());
      d = std::min((a - ray.origin).dot(ray.direction), (b - ray.origin).dot(ray.direction));
    }
    if (d <= min_range || d > max_range) return hit;
    hit.distance = d;
    hit.triangle = t;
    return hit;
  }

 private:
  Triangles triangles_;
  std::vector<std::uint32_t> index_;
  Tree tree_;
};

}  // namespace

std::unique_ptr<RayCaster::Impl> makeCgalCaster(const TriangleMesh& mesh, const std::vector<bool>& skip) {
  return std::make_unique<CgalCaster>(mesh, skip);
}

}  // namespace plumb::sim
