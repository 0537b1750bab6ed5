#pragma once
// TLS stations in the interior doorways of a generated building (issue 15): a station in each
// doorway sees both rooms it joins, which is how a campaign ties rooms together (two stations
// in the centres of identical offices joined by a door share too little to be registered:
// docs/NETWORK.md).
#include <Eigen/Core>

#include <vector>

#include "simulation/building_generator.hpp"

namespace plumb {

/// The centre of every interior door of storey `storey` (in the middle of its wall's
/// thickness), at `height` above that storey's finished floor, in the order of the model's
/// door elements. Doors in exterior walls are left out.
std::vector<Eigen::Vector3d> doorwayStations(const GeneratedBuilding& building, int storey = 0, double height = 1.5);

}  // namespace plumb
