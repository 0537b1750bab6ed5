#pragma once
// Where a model's stairs are: the bounds of each element whose IFC type starts with "IfcStair"
// (IfcStair, IfcStairFlight), from its triangles.
#include <vector>

#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"

namespace plumb::bimst {

/// One box per stair element that has triangles.
std::vector<Bounds> stairBounds(const BimModel& model);

/// True when a station standing `height` above its floor is on or beside a stair: the floor
/// within [min.z - margin, max.z + margin] of a box and the station within `reach` of the box
/// in plan.
bool nearStair(const std::vector<Bounds>& stairs, const Eigen::Vector3d& station, double height,
               double reach, double margin);

}  // namespace plumb::bimst
