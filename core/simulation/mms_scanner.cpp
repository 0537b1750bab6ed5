#include "simulation/mms_scanner.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "simulation/pulse_random.hpp"

namespace plumb {

const ParamSchema<MmsParams>& MmsParams::schema() {
  static const ParamSchema<MmsParams> s =
      ParamSchema<MmsParams>("mms")
          .real(&MmsParams::speed, "speed", "Vehicle speed", "m/s", 0.1, 40, "Speed on automatic trajectories")
          .real(&MmsParams::line_rate_hz, "line-rate", "Line rate", "Hz", 1, 500, "Profiler revolutions per second")
          .integer(&MmsParams::pulses_per_line, "pulses-per-line", "Pulses per line", "", 16, 20000,
                   "Pulses per profiler revolution")
          .real(&MmsParams::tilt_deg, "tilt", "Profiler tilt", "deg", -60, 60,
                "Tilt of the profiler plane about the lateral axis", true)
          .real(&MmsParams::max_range, "max-range", "Maximum range", "m", 1, 1000, "Farther surfaces give no return")
          .real(&MmsParams::min_range, "min-range", "Minimum range", "m", 0, 10, "Closer returns are discarded", true)
          .real(&MmsParams::noise_mm, "noise-mm", "Range noise", "mm", 0, 200, "Gaussian range noise (sigma)")
          .real(&MmsParams::sensor_height, "sensor-height", "Sensor height", "m", 0.5, 10,
                "Profiler height above ground on automatic trajectories")
          .real(&MmsParams::street_offset, "street-offset", "Street offset", "m", 1, 100,
                "Distance from the building outline to the automatic trajectory");
  return s;
}

Scan simulateMms(const ScanScene& scene, const Trajectory& trajectory, const MmsParams& p,
                 std::uint64_t seed, Progress* progress) {
  const auto lines = static_cast<std::int32_t>(std::floor(trajectory.duration() * p.line_rate_hz)) + 1;
  const std::int32_t pulses = p.pulses_per_line;
  const double sigma = p.noise_mm * 1e-3, tilt = p.tilt_deg * M_PI / 180.0;
  const double t0 = trajectory.times.empty() ? 0.0 : trajectory.times.front();
  const auto& caster = scene.caster();
  Scan scan;
  scan.name = "mms";
  scan.description = "simulated mobile mapping";
  scan.has_pose = true;  // identity: points are in the model frame
  auto& cloud = scan.cloud;
  if (!trajectory.positions.empty()) cloud.offset = trajectory.positions.front().array().round().matrix();

  struct Pulse {
    Eigen::Vector3f position, origin;
    double time;
    float intensity;
    std::int32_t column;
    std::uint8_t cls;
  };
  std::vector<std::vector<Pulse>> per_line(static_cast<std::size_t>(lines));
  const std::int32_t chunk = 64;
  for (std::int32_t l0 = 0; l0 < lines; l0 += chunk) {
    checkCanceled(progress);
    reportProgress(progress, static_cast<double>(l0) / lines, "MMS scan");
    tbb::parallel_for(l0, std::min(lines, l0 + chunk), [&](std::int32_t line) {
      // One profiler revolution is traced as one batch (Embree: ray packets).
      std::vector<Ray> rays(static_cast<std::size_t>(pulses));
      std::vector<RayHit> hits(rays.size());
      std::vector<double> times(rays.size());
      for (std::int32_t k = 0; k < pulses; ++k) {
        const auto i = static_cast<std::size_t>(k);
        times[i] = t0 + (line + static_cast<double>(k) / pulses) / p.line_rate_hz;
        Eigen::Vector3d pos, heading;
        trajectory.sample(times[i], pos, heading);
        const Eigen::Vector3d lateral = Eigen::Vector3d::UnitZ().cross(heading);
        const Eigen::Vector3d up = std::cos(tilt) * Eigen::Vector3d::UnitZ() + std::sin(tilt) * heading;
        const double phi = 2.0 * M_PI * k / pulses;
        rays[i] = {pos, (std::cos(phi) * lateral + std::sin(phi) * up).normalized()};
      }
      caster.castBatch(rays.data(), rays.size(), hits.data(), p.max_range, p.min_range);
      auto& out = per_line[static_cast<std::size_t>(line)];
      for (std::int32_t k = 0; k < pulses; ++k) {
        const auto i = static_cast<std::size_t>(k);
        const RayHit& hit = hits[i];
        if (!hit.hit()) continue;
        const Ray& ray = rays[i];
        sim::PulseRandom rng(seed, static_cast<std::uint64_t>(line) * static_cast<std::uint64_t>(pulses) + i);
        const double range = hit.distance + sigma * rng.normal();
        const double cos_inc = std::abs(caster.triangleNormal(hit.triangle).dot(ray.direction));
        out.push_back({(ray.origin + range * ray.direction - cloud.offset).cast<float>(), (ray.origin - cloud.offset).cast<float>(), times[i],
                       static_cast<float>(std::clamp(cos_inc * std::exp(-range / p.max_range), 0.0, 1.0)), k,
                       static_cast<std::uint8_t>(scene.isGround(hit.triangle) ? 2 : 6)});
      }
    });
  }
  std::size_t total = 0;
  for (const auto& l : per_line) total += l.size();
  cloud.reserve(total);
  for (std::int32_t line = 0; line < lines; ++line)
    for (const auto& q : per_line[static_cast<std::size_t>(line)]) {
      cloud.positions.push_back(q.position);
      cloud.sensor_origins.push_back(q.origin);
      cloud.timestamps.push_back(q.time);
      cloud.intensity.push_back(q.intensity);
      cloud.row.push_back(line);
      cloud.column.push_back(q.column);
      cloud.classification.push_back(q.cls);
    }
  cloud.grid_rows = lines;
  cloud.grid_columns = pulses;
  reportProgress(progress, 1.0, "MMS scan");
  return scan;
}

}  // namespace plumb
