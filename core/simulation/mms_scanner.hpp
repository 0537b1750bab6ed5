#pragma once
// Mobile mapping system (outdoor): a vehicle drives along a trajectory with a rotating 2D
// profiler. Each revolution is one scan line in the plane spanned by the vehicle's up and
// lateral axes (tilted by `tilt_deg` about the lateral axis), `pulses_per_line` pulses per
// revolution. Rays pass through window openings (glass is transparent to the caster unless
// the caller builds it opaque) and hit interior walls: the 2021 paper's interior points.
//
// Output: one Scan in the model frame (pose identity, has_pose true) with per-point sensor
// origins (cloud.sensor_origins), timestamps (s), row = line index, column = pulse index
// (grid_rows = lines, grid_columns = pulses per line: the MMS line/pulse topology),
// intensity, classification (2 ground, 6 building). Deterministic for a seed.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/dataset.hpp"
#include "model/trajectory.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb {

struct MmsParams {
  double speed = 3.0;              ///< m/s, 0.1..40 (used for automatic trajectories)
  double line_rate_hz = 50.0;      ///< profiler revolutions per second, 1..500
  int pulses_per_line = 720;       ///< pulses per revolution, 16..20000
  double tilt_deg = 0.0;           ///< profiler plane tilt about the lateral axis, -60..60
  double max_range = 60.0;         ///< m, 1..1000
  double min_range = 0.5;          ///< m, 0..10
  double noise_mm = 10.0;          ///< Gaussian range noise sigma, mm, 0..200
  double sensor_height = 2.5;      ///< m above ground, automatic trajectories, 0.5..10
  double street_offset = 7.0;      ///< m from the outer walls, automatic trajectories, 1..100

  static const ParamSchema<MmsParams>& schema();
};

/// A closed loop around a building outline (counter-clockwise polygon, z ignored), offset
/// outwards by params.street_offset (parallel to the walls, mitred corners), at
/// params.sensor_height, driven at params.speed starting at time `t0`.
Trajectory streetTrajectory(const std::vector<Eigen::Vector3d>& outline, const MmsParams& params,
                            double t0 = 0.0);

/// Simulates the profiler along the whole trajectory. Scan name "mms".
Scan simulateMms(const ScanScene& scene, const Trajectory& trajectory, const MmsParams& params,
                 std::uint64_t seed, Progress* progress = nullptr);

}  // namespace plumb
