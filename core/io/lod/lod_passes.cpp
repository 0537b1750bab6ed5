#include "io/lod/lod_passes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/error.hpp"

namespace plumb {

void LodSurveySink::beginScan(const StreamScan& scan) {
  pose_ = scan.scan.pose;
  if (stations.size() <= scan.index) stations.resize(scan.index + 1);
  stations[scan.index].name = scan.scan.name;
}

void LodSurveySink::chunk(const PointCloud& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = lodWorldPoint(points, i, pose_);
    if (!p.allFinite()) {
      ++skipped;
      continue;
    }
    bounds.extend(p);
    ++finite;
  }
}

void LodSurveySink::endScan(const StreamScanEnd& end) {
  if (stations.size() <= end.index) stations.resize(end.index + 1);
  const auto has = [&](const char* name) { return std::find(end.fields.begin(), end.fields.end(), name) != end.fields.end(); };
  stations[end.index].has_intensity = has("intensity");
  stations[end.index].has_rgb = has("red");
}

void LodQuantiseSink::beginScan(const StreamScan& scan) {
  if (scan.index > std::numeric_limits<std::uint16_t>::max())
    throw FileError(file_, "more than 65536 scans: the level-of-detail cache stores a 16-bit station index",
                    FileLocation{{}, {}, "scan " + std::to_string(scan.index)});
  pose_ = scan.scan.pose;
  station_ = static_cast<std::uint16_t>(scan.index);
}

void LodQuantiseSink::chunk(const PointCloud& points) {
  const bool intensity = station_ < stations_.size() && stations_[station_].has_intensity && points.hasIntensity();
  const bool rgb = station_ < stations_.size() && stations_[station_].has_rgb && points.hasColors();
  const double limit = static_cast<double>(grid_.nodeSide(0));
  batch_.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = lodWorldPoint(points, i, pose_);
    if (!p.allFinite()) continue;
    LodPoint lp;
    for (int a = 0; a < 3; ++a) {
      const double q = std::round((p[a] - grid_.origin[a]) / grid_.quantum);
      if (!(q >= 0 && q < limit))
        throw FileError(file_, "a point lies outside the bounds found by the first pass (was the file changed during "
                               "the cache build?)", FileLocation{{}, {}, "scan " + std::to_string(station_)});
      lp.q[a] = static_cast<std::uint32_t>(q);
    }
    lp.station = station_;
    lp.intensity = intensity ? points.intensity[i] : std::numeric_limits<float>::quiet_NaN();
    if (rgb) lp.rgb = points.colors[i];
    batch_.push_back(lp);
  }
  consume_(batch_);
}

}  // namespace plumb
