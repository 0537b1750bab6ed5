#pragma once
// Named buildings small enough for fast tests (each generates in milliseconds):
//   two-rooms      1 storey, 2 rooms 4x5 m, ext 0.4 m / int 0.15 m walls, 5 windows, 2 doors
//   house          2 storeys, 2x2 rooms (9 x 8 m), windows on every façade, furniture
//   office-floor   1 storey, 4 offices + 2 m corridor row + 4 offices, furniture
//   l-shaped       1 storey, L footprint (3x2 cells, one missing), ext walls 0.45 m
//   u-shaped       1 storey, U footprint (3x2 cells, middle-top missing)
//   non-manhattan  1 storey, 2x2 rooms on a 60-degree parallelogram plan
//   big-office     5 storeys, 9x3 cells: ~50k triangles, for benchmarks
// Each preset also suggests scanner stations (room centres at 1.5 m above the floor).
#include <Eigen/Core>

#include <string>
#include <vector>

#include "simulation/building_spec.hpp"

namespace plumb {

/// Names of all presets, in the order above.
std::vector<std::string> buildingPresetNames();
/// One-line description of a preset, for `plumb-cli simulate --list-presets`.
std::string buildingPresetDescription(const std::string& name);
/// The spec of a preset; throws InputError listing the valid names if unknown.
BuildingSpec buildingPreset(const std::string& name);
/// Centres of the rooms of storey `storey` at `height` above its finished floor: good TLS
/// stations. Works for any spec (model frame).
std::vector<Eigen::Vector3d> roomCentres(const BuildingSpec& spec, int storey = 0,
                                         double height = 1.5);

}  // namespace plumb
