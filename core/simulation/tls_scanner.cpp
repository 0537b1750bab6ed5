#include "simulation/tls_scanner.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "simulation/pulse_random.hpp"

namespace plumb {

const ParamSchema<TlsParams>& TlsParams::schema() {
  static const ParamSchema<TlsParams> s =
      ParamSchema<TlsParams>("tls")
          .real(&TlsParams::azimuth_step_deg, "azimuth-step", "Azimuth step", "deg", 0.01, 10,
                "Angle between columns (horizontal resolution)")
          .real(&TlsParams::elevation_step_deg, "elevation-step", "Elevation step", "deg", 0.01, 10,
                "Angle between rows (vertical resolution)")
          .real(&TlsParams::elevation_min_deg, "elevation-min", "Lowest elevation", "deg", -90, 90,
                "Lowest beam elevation (negative: below horizontal)")
          .real(&TlsParams::elevation_max_deg, "elevation-max", "Highest elevation", "deg", -90, 90,
                "Highest beam elevation")
          .real(&TlsParams::min_range, "min-range", "Minimum range", "m", 0, 10, "Closer returns are discarded", true)
          .real(&TlsParams::max_range, "max-range", "Maximum range", "m", 1, 1000, "Farther surfaces give no return")
          .real(&TlsParams::noise_mm, "noise-mm", "Range noise", "mm", 0, 100, "Gaussian range noise (sigma)")
          .boolean(&TlsParams::incidence_dropout, "incidence-dropout", "Incidence dropout",
                   "Drop grazing returns (probability rising to 1 at 90 degrees)", true)
          .real(&TlsParams::dropout_start_deg, "dropout-start", "Dropout start", "deg", 0, 90,
                "Incidence angle where dropout starts", true)
          .boolean(&TlsParams::keep_misses, "keep-misses", "Keep misses",
                   "Keep pulses without return as NaN points (organized grid)", true)
          .real(&TlsParams::heading_deg, "heading", "Heading", "deg", -360, 360, "Scanner yaw about Z", true);
  return s;
}

namespace {

constexpr double kDeg = M_PI / 180.0;

struct Pulse {
  Eigen::Vector3f position;
  float intensity;
  std::int32_t column;
};

/// The scan grid: its size and the per-column azimuth trig tables.
struct TlsGrid {
  std::int32_t columns, rows;
  std::vector<double> cos_az, sin_az;
};

TlsGrid tlsGrid(const TlsParams& p) {
  TlsGrid g;
  g.columns = std::max<std::int32_t>(1, static_cast<std::int32_t>(std::lround(360.0 / p.azimuth_step_deg)));
  g.rows = std::max<std::int32_t>(
      1, static_cast<std::int32_t>(std::floor((p.elevation_max_deg - p.elevation_min_deg) / p.elevation_step_deg + 1e-9)) + 1);
  g.cos_az.resize(static_cast<std::size_t>(g.columns));
  g.sin_az.resize(g.cos_az.size());
  for (std::int32_t col = 0; col < g.columns; ++col) {
    const double az = col * p.azimuth_step_deg * kDeg;
    g.cos_az[static_cast<std::size_t>(col)] = std::cos(az);
    g.sin_az[static_cast<std::size_t>(col)] = std::sin(az);
  }
  return g;
}

/// Traces the rows of the grid from one station.
struct RowTracer {
  const TlsParams& p;
  const TlsGrid& grid;
  const RayCaster& caster;
  const Eigen::Vector3d& station;
  const Eigen::Matrix3d& R;
  std::uint64_t seed;
  double sigma = p.noise_mm * 1e-3;
  double dropout_scale = 1.0 / std::max(1e-9, 90.0 - p.dropout_start_deg);

  /// The pulses of `row` (one batch: Embree ray packets; rows are coherent), in column order.
  void trace(std::int32_t row, std::vector<Pulse>& out) const {
    const double el = (p.elevation_max_deg - row * p.elevation_step_deg) * kDeg;
    const double cos_el = std::cos(el), sin_el = std::sin(el);
    std::vector<Eigen::Vector3d> local(static_cast<std::size_t>(grid.columns));
    std::vector<Ray> rays(local.size());
    std::vector<RayHit> hits(local.size());
    for (std::size_t col = 0; col < local.size(); ++col) {
      local[col] = Eigen::Vector3d(cos_el * grid.cos_az[col], cos_el * grid.sin_az[col], sin_el);
      rays[col] = {station, R * local[col]};
    }
    caster.castBatch(rays.data(), rays.size(), hits.data(), p.max_range, p.min_range);
    out.reserve(static_cast<std::size_t>(grid.columns));
    for (std::int32_t col = 0; col < grid.columns; ++col) {
      const auto c = static_cast<std::size_t>(col);
      addPulse(row, col, hits[c], rays[c], local[c], out);
    }
  }

  /// The return of `hit` (noise, dropout, intensity), a NaN point for a miss kept, or nothing.
  void addPulse(std::int32_t row, std::int32_t col, const RayHit& hit, const Ray& ray,
                const Eigen::Vector3d& local, std::vector<Pulse>& out) const {
    const auto c = static_cast<std::size_t>(col);
    bool keep = hit.hit();
    double cos_inc = 1.0, range = 0.0;
    if (keep) {
      sim::PulseRandom rng(seed, static_cast<std::uint64_t>(row) * static_cast<std::uint64_t>(grid.columns) + c);
      cos_inc = std::abs(caster.triangleNormal(hit.triangle).dot(ray.direction));
      const double u = rng.uniform();
      if (p.incidence_dropout) {
        const double inc = std::acos(std::min(1.0, cos_inc)) / kDeg;
        if (inc > p.dropout_start_deg && u < (inc - p.dropout_start_deg) * dropout_scale) keep = false;
      }
      range = hit.distance + sigma * rng.normal();
    }
    if (keep) {
      out.push_back({(local * range).cast<float>(),
                     static_cast<float>(std::clamp(cos_inc * std::exp(-range / p.max_range), 0.0, 1.0)), col});
    } else if (p.keep_misses) {
      out.push_back({Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()), 0.0f, col});
    }
  }
};

/// The scan of the station's grid, its points row by row.
Scan assembleScan(const std::vector<std::vector<Pulse>>& per_row, const TlsGrid& grid,
                  const Eigen::Matrix3d& R, const Eigen::Vector3d& station) {
  Scan scan;
  scan.name = "tls";
  scan.description = "simulated static scan";
  scan.pose = RigidTransform(R, station);
  scan.has_pose = true;
  auto& cloud = scan.cloud;
  cloud.grid_rows = grid.rows;
  cloud.grid_columns = grid.columns;
  std::size_t total = 0;
  for (const auto& r : per_row) total += r.size();
  cloud.positions.reserve(total);
  cloud.intensity.reserve(total);
  cloud.row.reserve(total);
  cloud.column.reserve(total);
  for (std::int32_t row = 0; row < grid.rows; ++row)
    for (const auto& pulse : per_row[static_cast<std::size_t>(row)]) {
      cloud.positions.push_back(pulse.position);
      cloud.intensity.push_back(pulse.intensity);
      cloud.row.push_back(row);
      cloud.column.push_back(pulse.column);
    }
  return scan;
}

}  // namespace

Scan simulateTls(const ScanScene& scene, const Eigen::Vector3d& station, const TlsParams& p,
                 std::uint64_t seed, Progress* progress) {
  const TlsGrid grid = tlsGrid(p);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(p.heading_deg * kDeg, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const RowTracer tracer{p, grid, scene.caster(), station, R, seed};
  std::vector<std::vector<Pulse>> per_row(static_cast<std::size_t>(grid.rows));
  const std::int32_t chunk = 16;
  for (std::int32_t r0 = 0; r0 < grid.rows; r0 += chunk) {
    checkCanceled(progress);
    reportProgress(progress, static_cast<double>(r0) / grid.rows, "TLS scan");
    tbb::parallel_for(r0, std::min(grid.rows, r0 + chunk), [&](std::int32_t row) {
      tracer.trace(row, per_row[static_cast<std::size_t>(row)]);
    });
  }
  Scan scan = assembleScan(per_row, grid, R, station);
  reportProgress(progress, 1.0, "TLS scan");
  return scan;
}

}  // namespace plumb
