#pragma once
// Static terrestrial laser scanner (indoor stations). The scanner turns about its vertical
// axis (azimuth, columns) and sweeps elevation (rows); each pulse returns the first surface
// hit, with Gaussian range noise and an optional incidence-angle dropout.
//
// Output: one Scan whose points are in the scan frame (origin at the station, axes of the
// model rotated by `heading_deg` about Z) and whose pose = station pose (scan -> model).
// cloud.row/column hold the grid indices (row = elevation index from the top, column =
// azimuth index), grid_rows/grid_columns the full grid size; pulses without a return are
// dropped (keep_misses = false) or kept as NaN (organized). Intensity in [0,1] falls with
// incidence angle and range. Deterministic for a seed: each pulse's noise comes from a
// generator seeded with (seed, pulse index), never from thread order.
#include <Eigen/Core>

#include <cstdint>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/dataset.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb {

struct TlsParams {
  double azimuth_step_deg = 0.36;     ///< deg, 0.01..10 (1000 columns per turn)
  double elevation_step_deg = 0.36;   ///< deg, 0.01..10
  double elevation_min_deg = -60.0;   ///< deg below horizontal, -90..90
  double elevation_max_deg = 90.0;    ///< deg, -90..90, > min
  double min_range = 0.3;             ///< m, 0..10: closer returns are discarded
  double max_range = 80.0;            ///< m, 1..1000
  double noise_mm = 2.0;              ///< Gaussian range noise sigma, mm, 0..100
  bool incidence_dropout = false;     ///< drop grazing returns (see dropout_start_deg)
  /// Incidence angle (deg, 0..90) where dropout starts; the drop probability rises linearly
  /// from 0 there to 1 at 90 degrees.
  double dropout_start_deg = 75.0;
  bool keep_misses = false;  ///< keep no-return pulses as NaN points (organized grid)
  double heading_deg = 0.0;  ///< scanner yaw about Z, deg, -360..360

  static const ParamSchema<TlsParams>& schema();
};

/// Scans the caster's mesh from `station` (model frame). Scan name "tls-<index>".
Scan simulateTls(const ScanScene& scene, const Eigen::Vector3d& station,
                 const TlsParams& params, std::uint64_t seed, Progress* progress = nullptr);

}  // namespace plumb
