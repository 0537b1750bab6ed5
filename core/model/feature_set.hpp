#pragma once
// Features detected in a scan or a model, shared by the extractors (core/features) and the
// registration methods (core/registration). World coordinates, metres.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

/// A planar polygon (2021 §2): plane n·x = d with |n| = 1, and its alpha-shape boundary.
struct PlanarPolygon {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double offset = 0.0;  ///< d in n·x = d
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  std::size_t inlier_count = 0;
  double area = 0.0;  ///< m^2, of the polygon (outer ring minus holes)
  /// 2D frame of the plane: x = origin + s*u_axis + t*v_axis (u, v, normal orthonormal).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v_axis = Eigen::Vector3d::UnitY();
  /// rings[0] is the outer boundary (counter-clockwise in (u,v)), then holes (clockwise).
  std::vector<std::vector<Eigen::Vector2d>> rings;
  std::vector<std::uint32_t> inliers;  ///< indices into the source cloud (may be empty)

  Eigen::Vector3d to3d(const Eigen::Vector2d& uv) const {
    return origin + uv.x() * u_axis + uv.y() * v_axis;
  }
  Eigen::Vector2d to2d(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = p - origin;
    return {q.dot(u_axis), q.dot(v_axis)};
  }
  double signedDistance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
  /// Angle between the normal and the horizontal plane is < tol: the plane is vertical.
  bool isVertical(double tolerance_deg) const;
  bool isHorizontal(double tolerance_deg) const;
  void transform(const RigidTransform& t);
};

/// A 3D line segment (2023 §II). Direction has no meaningful sign.
struct Segment3D {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double support = 0.0;  ///< points supporting it (scans) or 0 (exact model edges)

  double length() const { return (b - a).norm(); }
  Eigen::Vector3d direction() const { return (b - a).normalized(); }
  Eigen::Vector3d midpoint() const { return 0.5 * (a + b); }
  void transform(const RigidTransform& t) {
    a = t.apply(a);
    b = t.apply(b);
  }
};

/// A rectangular opening (window/door) in a façade (2021 §3.1, 2023 §III-A).
struct Opening {
  /// Corners in the façade plane, counter-clockwise seen from outside the building:
  /// bottom-left, bottom-right, top-right, top-left (edges are horizontal and vertical).
  std::array<Eigen::Vector3d, 4> corners{};
  int facade = -1;  ///< index into FeatureSet::planes of the façade (or wall) it lies in
  std::size_t evidence_count = 0;  ///< points supporting it

  double width() const { return (corners[1] - corners[0]).norm(); }
  double height() const { return (corners[3] - corners[0]).norm(); }
  std::array<Segment3D, 4> edges() const;
  void transform(const RigidTransform& t) {
    for (auto& c : corners) c = t.apply(c);
  }
};

struct FeatureSet {
  std::vector<PlanarPolygon> planes;
  std::vector<int> facades;  ///< indices into planes of the façades (large vertical planes)
  std::vector<Opening> openings;
  std::vector<Segment3D> segments;

  void transform(const RigidTransform& t);
};

/// Box of every feature: plane polygons (their rings), opening corners, segment end points.
Bounds featureBounds(const FeatureSet& features);

}  // namespace plumb
