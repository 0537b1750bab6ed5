// Closest points on mesh triangles with CGAL's AABB tree (mesh_closest_points.hpp). The CGAL
// headers stay in this translation unit.
#include "simulation/mesh_closest_points.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <numeric>

namespace plumb {

namespace {
using K = CGAL::Simple_cartesian<double>;
using Triangle = K::Triangle_3;
using AabbTree = CGAL::AABB_tree<
    CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>>>;

K::Point_3 point(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

struct MeshClosestPoints::Tree {
  std::vector<Triangle> triangles;   ///< the chosen, non-degenerate triangles
  std::vector<std::uint32_t> index;  ///< their index in the mesh
  AabbTree tree;
};

MeshClosestPoints::MeshClosestPoints(const std::vector<Eigen::Vector3d>& vertices,
                                     const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                     const std::vector<std::uint32_t>& chosen)
    : tree_(std::make_unique<Tree>()) {
  tree_->triangles.reserve(chosen.size());
  for (std::uint32_t t : chosen) {
    const auto& v = triangles[t];
    const Triangle tri(point(vertices[v[0]]), point(vertices[v[1]]), point(vertices[v[2]]));
    if (tri.is_degenerate()) continue;
    tree_->triangles.push_back(tri);
    tree_->index.push_back(t);
  }
  if (tree_->triangles.empty()) return;
  tree_->tree.rebuild(tree_->triangles.begin(), tree_->triangles.end());
  tree_->tree.accelerate_distance_queries();  // built now: queries are then read-only
}

MeshClosestPoints::~MeshClosestPoints() = default;

bool MeshClosestPoints::closest(const Eigen::Vector3d& x, Closest& out) const {
  if (tree_->triangles.empty()) return false;
  const auto [p, id] = tree_->tree.closest_point_and_primitive(point(x));
  out.point = Eigen::Vector3d(p.x(), p.y(), p.z());
  out.triangle = tree_->index[std::size_t(id - tree_->triangles.begin())];
  return true;
}

std::size_t MeshClosestPoints::size() const { return tree_->triangles.size(); }

std::vector<std::uint32_t> MeshClosestPoints::all(std::size_t n) {
  std::vector<std::uint32_t> out(n);
  std::iota(out.begin(), out.end(), 0u);
  return out;
}

}  // namespace plumb
