#pragma once
// A sensor trajectory: timed positions of a moving scanner (MMS vehicle), read from the text
// files surveyors export ("t x y z" per line), and the per-point sensor origins it gives a
// mobile scan that carries timestamps but no origins (LAS, E57 from other tools). The
// openings method (2023 paper §III) ray-traces from those origins.
#include <Eigen/Core>

#include <filesystem>
#include <vector>

#include "model/dataset.hpp"

namespace plumb {

/// A timed polyline; the vehicle heading follows the polyline direction.
struct Trajectory {
  std::vector<double> times;               ///< s, strictly increasing
  std::vector<Eigen::Vector3d> positions;  ///< sensor positions (model / dataset frame)
  double duration() const { return times.empty() ? 0.0 : times.back() - times.front(); }
  /// Position linearly interpolated at time t (clamped to the ends; zero if empty).
  Eigen::Vector3d position(double t) const;
  /// Position and unit horizontal heading at time t (clamped to the ends).
  void sample(double t, Eigen::Vector3d& position, Eigen::Vector3d& heading) const;
};

/// Reads a trajectory text file: one "t x y z" per line (whitespace or comma separated,
/// '#' comments). Throws FileError naming the file and the line.
Trajectory readTrajectory(const std::filesystem::path& path);

/// Sets cloud.sensor_origins of every scan of `d` from its per-point timestamps: the origin of
/// a point is the trajectory position linearly interpolated at its time. The trajectory is in
/// the dataset frame (the frame of the points after each scan's pose); origins are stored in
/// the scan frame relative to the cloud's offset, like the points. Times up to 1 s outside the
/// trajectory take its end positions. `trajectory_file` only names the trajectory in errors.
/// Throws InputError naming the dataset if a scan has no timestamps, FileError naming the
/// trajectory file if it is unusable (< 2 samples, times not increasing) or if points lie more
/// than 1 s outside its time range (how many, both ranges: usually a time-base mismatch).
/// Leaves `d` unchanged when it throws.
void setSensorOriginsFromTrajectory(Dataset& d, const Trajectory& t,
                                    const std::filesystem::path& trajectory_file);

}  // namespace plumb
