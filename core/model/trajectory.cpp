#include "model/trajectory.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "common/error.hpp"

namespace plumb {
namespace {

/// Segment index i with times[i] <= t < times[i+1] (clamped to the first/last segment).
std::size_t segmentAt(const std::vector<double>& times, double t) {
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t i = it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin()) - 1;
  return std::min(i, times.size() - 2);
}

std::string seconds(double a, double b) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(3);
  s << "[" << a << ", " << b << "] s";
  return s.str();
}

std::string datasetName(const Dataset& d) {
  return d.source.empty() ? std::string("dataset") : d.source.string();
}

/// Points more than `tolerance` outside [t0, t1] (NaN times count), and the finite time range.
struct TimeCheck {
  std::size_t points = 0, outside = 0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  TimeCheck& operator+=(const TimeCheck& o) {
    points += o.points;
    outside += o.outside;
    min = std::min(min, o.min);
    max = std::max(max, o.max);
    return *this;
  }
};

TimeCheck checkTimes(const std::vector<double>& times, double t0, double t1, double tolerance) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, times.size(), 1 << 16), TimeCheck{},
      [&](const tbb::blocked_range<std::size_t>& r, TimeCheck c) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const double t = times[i];
          ++c.points;
          if (!(t >= t0 - tolerance && t <= t1 + tolerance)) ++c.outside;
          if (std::isfinite(t)) {
            c.min = std::min(c.min, t);
            c.max = std::max(c.max, t);
          }
        }
        return c;
      },
      [](TimeCheck a, const TimeCheck& b) { return a += b; });
}

}  // namespace

Eigen::Vector3d Trajectory::position(double t) const {
  if (times.empty()) return Eigen::Vector3d::Zero();
  if (times.size() == 1) return positions[0];
  const std::size_t i = segmentAt(times, t);
  const double f = std::clamp((t - times[i]) / (times[i + 1] - times[i]), 0.0, 1.0);
  return positions[i] + f * (positions[i + 1] - positions[i]);
}

void Trajectory::sample(double t, Eigen::Vector3d& pos, Eigen::Vector3d& heading) const {
  heading = Eigen::Vector3d::UnitX();
  pos = position(t);
  if (times.size() < 2) return;
  const std::size_t i = segmentAt(times, t);
  // Heading of the first segment with horizontal motion at or before i (else after).
  auto horizontal = [this, &heading](std::size_t k) {
    Eigen::Vector3d d = positions[k + 1] - positions[k];
    d.z() = 0;
    if (d.norm() <= 1e-9) return false;
    heading = d.normalized();
    return true;
  };
  for (std::size_t k = i + 1; k-- > 0;)
    if (horizontal(k)) return;
  for (std::size_t k = i + 1; k + 1 < positions.size(); ++k)
    if (horizontal(k)) return;
}

Trajectory readTrajectory(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open trajectory file");
  Trajectory traj;
  std::string line;
  std::uint64_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ss(line);
    double v[4];
    int count = 0;
    while (count < 4 && ss >> v[count]) ++count;
    if (count == 0 && ss.eof()) continue;
    std::string rest;
    if (count != 4 || (ss >> rest))
      throw FileError(path, "expected 4 numbers 't x y z'", atLine(number));
    if (!traj.times.empty() && !(v[0] > traj.times.back()))
      throw FileError(path, "times must increase strictly", atLine(number));
    traj.times.push_back(v[0]);
    traj.positions.emplace_back(v[1], v[2], v[3]);
  }
  if (traj.times.size() < 2) throw FileError(path, "a trajectory needs at least 2 poses");
  return traj;
}

void setSensorOriginsFromTrajectory(Dataset& d, const Trajectory& t,
                                    const std::filesystem::path& trajectory_file) {
  if (t.times.size() < 2 || t.positions.size() != t.times.size())
    throw FileError(trajectory_file, "a trajectory needs at least 2 poses (one position per time)");
  for (std::size_t i = 1; i < t.times.size(); ++i)
    if (!(t.times[i] > t.times[i - 1]))
      throw FileError(trajectory_file, "times must increase strictly", {std::nullopt, std::nullopt,
                      "sample " + std::to_string(i)});
  // Check every scan first so a failure leaves the dataset untouched.
  constexpr double kTolerance = 1.0;  // s beyond either end still accepted (clamped)
  const double t0 = t.times.front(), t1 = t.times.back();
  TimeCheck all;
  for (const auto& s : d.scans) {
    if (s.cloud.empty()) continue;
    if (!s.cloud.hasTimestamps())
      throw InputError(datasetName(d) + ": scan '" + s.name + "' has no per-point timestamps: "
                       "its sensor origins cannot come from the trajectory " + trajectory_file.string());
    all += checkTimes(s.cloud.timestamps, t0, t1, kTolerance);
  }
  if (all.outside > 0)
    throw FileError(trajectory_file,
                    std::to_string(all.outside) + " of " + std::to_string(all.points) + " points of " +
                        datasetName(d) + " have times more than 1 s outside the trajectory's time range "
                        "(points " + seconds(all.min, all.max) + ", trajectory " + seconds(t0, t1) +
                        "): different time bases? (e.g. GPS week seconds vs time since start)");
  for (auto& s : d.scans) {
    PointCloud& c = s.cloud;
    if (c.empty()) continue;
    // dataset frame -> scan frame, then relative to the cloud's offset (like positions).
    const RigidTransform to_scan = s.pose.inverse();
    const Eigen::Vector3d offset = c.offset;
    c.sensor_origins.resize(c.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, c.size(), 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i)
                          c.sensor_origins[i] =
                              (to_scan.apply(t.position(c.timestamps[i])) - offset).cast<float>();
                      });
  }
}

}  // namespace plumb
