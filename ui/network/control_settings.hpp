#pragma once
// The control survey of a network run as the Network dock takes it (plumb-cli network
// --control, --targets, --crs / --grid-scale, --target-sigma): the two files, the grid's scale
// (a number, a CRS whose factor PROJ computes, or nothing for 1) and the target sigma. Loaded
// with the core's readers, so a bad line is refused with the same message naming file and line.
#include <memory>
#include <string>
#include <vector>

#include "registration/network/control_points.hpp"

namespace plumb::ui {

struct ControlSettings {
  std::string control;  ///< control and check points: name, E, N, H[, control|check]
  std::string targets;  ///< target observations: station, point, x, y, z (station frame)
  std::string grid;     ///< "" (scale 1), a scale factor ("0.99988") or a CRS ("EPSG:32632")
  double target_sigma = 0.002;  ///< m, one coordinate of a target observation

  bool empty() const { return control.empty() && targets.empty(); }
};

/// The survey of `settings` as plumb-cli network's loadControl builds it, its observations
/// checked against `station_names` (checkObservations); null when no file is given (the grid
/// field alone is then ignored: it belongs to the files). Throws InputError / FileError.
std::shared_ptr<const ControlSurvey> loadControlSurvey(const ControlSettings& settings,
                                                       const std::vector<std::string>& station_names);

}  // namespace plumb::ui
