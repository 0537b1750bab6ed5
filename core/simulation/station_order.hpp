#pragma once
// The order a surveyor sets up stations in: each next station the nearest one not yet set up
// (a walk through the building), starting from the first. Used by `simulate --tls-walk` so
// that a network's sequence neighbours are stations that overlap (docs/NETWORK.md).
#include <Eigen/Core>

#include <vector>

namespace plumb {

/// `stations` reordered as a nearest-neighbour walk from stations[0] (ties: lowest index).
std::vector<Eigen::Vector3d> walkOrder(const std::vector<Eigen::Vector3d>& stations);

}  // namespace plumb
