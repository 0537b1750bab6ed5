#pragma once
// TLS stations inside the rooms of any model (imported IFC files have no room list): points
// 1.5 m above a floor from which every ray of a coarse sphere hits the model (no miss: the
// point is enclosed) and no surface is closer than `min_clearance`.
#include <Eigen/Core>

#include <vector>

#include "model/bim_model.hpp"
#include "simulation/ray_caster.hpp"

namespace plumb::verdict {

struct StationSearch {
  double grid_step = 1.0;       ///< m between candidate columns in plan
  double height = 1.5;          ///< m above the floor found below
  double min_clearance = 0.8;   ///< m to the nearest surface
  double min_separation = 3.0;  ///< m between chosen stations
  int max_stations = 3;
};

/// Unit directions spread evenly over the sphere (Fibonacci lattice).
std::vector<Eigen::Vector3d> sphereDirections(int n);

/// Points `height` above each upward-facing surface (|n_z| > 0.9, at least height + 0.3 m
/// below the one above) met by a vertical ray through (x, y) cast down from z = `top`.
std::vector<Eigen::Vector3d> floorsBelow(const RayCaster& caster, double x, double y, double top,
                                         double height);

/// Distance to the nearest surface over the rays `dirs` from p, or -1 when a ray escapes.
double clearance(const RayCaster& caster, const Eigen::Vector3d& p,
                 const std::vector<Eigen::Vector3d>& dirs);

/// Stations sorted by clearance (roomiest first), at most s.max_stations, each at least
/// s.min_separation from the others. Empty when the model has no enclosed room.
std::vector<Eigen::Vector3d> findRoomStations(const BimModel& model, const StationSearch& s = {});

}  // namespace plumb::verdict
