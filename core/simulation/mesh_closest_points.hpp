#pragma once
// Closest points on (a chosen subset of) a triangle mesh, with CGAL's AABB tree: the model
// surface of the refinement (registration/refine/triangle_target.hpp) and the cloud-to-mesh
// distances of the quality report (quality/cloud_mesh_distance.cpp). Coordinates are those the
// caller gives (keep them small: a local frame). Immutable after construction; queries are
// thread-safe.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace plumb {

class MeshClosestPoints {
 public:
  /// Tree over the triangles `chosen` (indices into `triangles`); degenerate ones are skipped.
  MeshClosestPoints(const std::vector<Eigen::Vector3d>& vertices,
                    const std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const std::vector<std::uint32_t>& chosen);
  ~MeshClosestPoints();
  MeshClosestPoints(const MeshClosestPoints&) = delete;
  MeshClosestPoints& operator=(const MeshClosestPoints&) = delete;

  struct Closest {
    Eigen::Vector3d point;       ///< closest point on the chosen triangles
    std::uint32_t triangle = 0;  ///< its triangle (index into `triangles`)
  };
  /// Closest point of x on the chosen triangles; false when there is none (all degenerate).
  bool closest(const Eigen::Vector3d& x, Closest& out) const;
  /// Non-degenerate triangles in the tree.
  std::size_t size() const;

  /// 0, 1, ..., n - 1: every triangle of a mesh of n.
  static std::vector<std::uint32_t> all(std::size_t n);

 private:
  struct Tree;  ///< CGAL types, defined in mesh_closest_points.cpp
  std::unique_ptr<Tree> tree_;
};

}  // namespace plumb
