#pragma once
// The model surface as a refinement target (docs/ALGORITHMS.md §8, issue 14): point-to-triangle
// correspondences (closest point on the mesh, CGAL AABB tree: simulation/mesh_closest_points.hpp)
// against the triangles the scan's stations can see (after a first, coarse stage on every
// triangle: icp_refinement.cpp). Visibility: from each used source point's sensor origin,
// placed by the current pose, a ray (Embree, simulation/ray_caster.hpp) through the point; the
// first triangle hit is seen. Back faces, wall interiors and other rooms are never hit first, so
// they never attract points. Without sensor origins, every triangle is kept and a
// correspondence counts only when the point lies in front of its triangle (the normal faces
// the point, up to kFacingTolerance): a scan of one face of a thin wall cannot match the other.
#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

#include "model/bim_model.hpp"
#include "registration/refine/target_surface.hpp"

namespace plumb {
class RayCaster;
}

namespace plumb::refine_detail {

/// A point behind its closest triangle by more than this (m) does not match it (front-face
/// rule without sensor origins): generous for 3 mm scanner noise, well below a wall thickness.
constexpr double kFacingTolerance = 0.02;

/// Source points and their sensor origins (local frame, before the refinement's pose).
struct SourceRays {
  std::vector<Eigen::Vector3d> points;
  std::vector<Eigen::Vector3d> origins;  ///< empty when the scan has no sensor origins
};

/// What a visibility pass found.
struct VisibleSet {
  std::vector<std::uint32_t> triangles;  ///< sorted, unique
  std::size_t rays = 0;                  ///< rays cast
  std::size_t hits = 0;                  ///< rays that hit a triangle
  /// Hits on a triangle whose normal points away from the ray's origin (a mesh wound
  /// inconsistently, or a back face seen through a gap): kept, the triangle is seen.
  std::size_t back_facing = 0;
  double seconds = 0.0;
};

/// The triangles first hit by the rays from each origin through its point, both placed by
/// x -> R x + t.
VisibleSet visibleTriangles(const RayCaster& caster, const SourceRays& rays, const Eigen::Matrix3d& R,
                            const Eigen::Vector3d& t);

/// The model mesh in the local frame with its ray caster, prepared once per target.
class TriangleTarget {
 public:
  /// `origin`: world position of the local frame's origin. Throws InputError for a mesh
  /// without triangles.
  TriangleTarget(const TriangleMesh& mesh, const Eigen::Vector3d& origin);
  ~TriangleTarget();
  TriangleTarget(const TriangleTarget&) = delete;
  TriangleTarget& operator=(const TriangleTarget&) = delete;

  /// The surface of the triangles `visible` (the closest of them, its normal).
  std::unique_ptr<TargetSurface> visibleSurface(const VisibleSet& visible) const;
  /// Every triangle, a correspondence kept only when the point is in front of its triangle.
  std::unique_ptr<TargetSurface> frontFacingSurface() const;
  /// Every triangle, either side (the first, coarsest stage: the start may be far enough off
  /// for the visibility under it to be wrong).
  std::unique_ptr<TargetSurface> everySurface() const;
  const RayCaster& caster() const { return *caster_; }
  std::size_t triangleCount() const;

 private:
  std::unique_ptr<RayCaster> caster_;  ///< over the mesh in the local frame (its copy)
};

}  // namespace plumb::refine_detail
