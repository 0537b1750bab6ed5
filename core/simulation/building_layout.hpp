#pragma once
// Internal: the building's parts as boxes in plan-grid coordinates (u, v, z) before meshing.
// World position of (u, v, z) is (u + v cos(a), v sin(a), z), a = spec.axis_angle_deg.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "simulation/building_spec.hpp"

namespace plumb::sim {

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();  ///< (u, v, z)
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
};

struct LayoutWall {
  Box box;
  int axis = 0;          ///< plan coordinate that is constant along the wall: 0 = u, 1 = v
  double line = 0.0;     ///< that coordinate's value (wall centre line)
  double half = 0.0;     ///< half thickness in that coordinate (t / (2 sin a))
  int outside_sign = 0;  ///< +1 / -1: outside is towards larger / smaller coordinate; 0 interior
  int storey = 0;
  std::string name;
};

struct LayoutOpening {
  Box box;          ///< through the wall's full thickness
  bool door = false;
  int wall = 0;     ///< index into walls
  int storey = 0;
  std::string name;
};

struct LayoutPart {  ///< slabs (several boxes each) and furniture (one box)
  std::vector<Box> boxes;
  std::string name;
};

struct BuildingLayout {
  double cos_a = 0.0, sin_a = 1.0;
  std::vector<LayoutWall> walls;
  std::vector<LayoutOpening> openings;
  std::vector<LayoutPart> slabs;
  std::vector<LayoutPart> furniture;
  std::vector<Eigen::Vector2d> footprint_uv;  ///< outer wall faces, counter-clockwise

  Eigen::Vector3d toWorld(const Eigen::Vector3d& uvz) const {
    return {uvz.x() + uvz.y() * cos_a, uvz.y() * sin_a, uvz.z()};
  }
  /// Unit normal (world) of the plane "coordinate axis = const", pointing to increasing values.
  Eigen::Vector3d planeNormal(int axis) const;
  /// Scale s such that normal·x = s * coordinate on that plane.
  double planeScale(int axis) const;
};

/// Plan line positions (cumulative widths/depths, starting at 0).
std::vector<double> planLines(const std::vector<double>& sizes);
BuildingLayout layoutBuilding(const BuildingSpec& spec);

}  // namespace plumb::sim
