#pragma once
// Exact geometric truth of a generated building, in the model frame (metres, Z up).
//
// - planes: every planar face of a wall or slab that is visible (wall faces with which side:
//   "exterior" = outer face of an exterior wall, "interior" = a face inside the building;
//   slab faces "top"/"bottom"; "other" for reveals, wall ends, furniture).
// - openings: every window/door, once per wall face it pierces ("exterior" and "interior"
//   faces of an exterior wall, two "interior" faces of an interior wall); corners follow
//   plumb::Opening: bottom-left, bottom-right, top-right, top-left, counter-clockwise seen
//   from the side the face looks at (from outside for "exterior").
// - sharp_edges: EXACTLY the sharp edges of the generated mesh: every mesh edge whose two
//   faces are not coplanar (the smallest turning angle is min(axis angle, 90) degrees, every
//   other mesh edge is exactly flat), merged into maximal collinear chains. Convex and concave
//   edges alike (room corners are concave).
// - glass_edges: the open boundary of each glass pane (mesh boundary edges of IfcWindow
//   triangles), kept apart from sharp_edges.
#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "model/feature_set.hpp"

namespace plumb {

struct TruthPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< unit, pointing out of the solid
  double offset = 0.0;                                ///< n·x = offset
  std::uint32_t element = 0;                          ///< index into BimModel::elements
  std::string element_type;                           ///< "IfcWall", "IfcSlab", ...
  std::string face;                                   ///< exterior|interior|top|bottom|other
  double area = 0.0;                                  ///< m², of the visible face pieces
};

struct TruthOpening {
  std::uint32_t element = 0;  ///< the IfcWindow/IfcDoor element
  std::string element_type;
  std::uint32_t wall = 0;     ///< the IfcWall element it pierces
  std::string face;           ///< "exterior" | "interior"
  Eigen::Vector3d face_normal = Eigen::Vector3d::UnitX();  ///< normal of that wall face
  std::array<Eigen::Vector3d, 4> corners{};                 ///< see header comment
  int storey = 0;
};

struct BuildingTruth {
  std::vector<TruthPlane> planes;
  std::vector<TruthOpening> openings;
  std::vector<Segment3D> sharp_edges;
  std::vector<Segment3D> glass_edges;
  double exterior_wall_thickness = 0.0;  ///< perpendicular, m
  double interior_wall_thickness = 0.0;
  double axis_angle_deg = 90.0;
  /// Street-level outline of the building (outer wall faces), counter-clockwise, z = 0.
  std::vector<Eigen::Vector3d> footprint;

  /// Truth planes whose face is `face` ("exterior" ...), pointers into planes.
  std::vector<const TruthPlane*> planesWithFace(const std::string& face) const;
};

}  // namespace plumb
