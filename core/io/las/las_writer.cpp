#include "io/las/las_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "io/las/las_point_fields.hpp"
#include "io/las/las_stream_writer.hpp"

namespace plumb {
namespace {
using namespace las;

/// A scan's dataset-frame coordinates must be finite and representable to `scale` beside a
/// double header offset (|coordinate| / scale < 2^53); a pose translation of 1e308 is not.
void checkScanRange(const std::filesystem::path& path, const Scan& scan, double scale) {
  const Bounds b = scan.cloud.bounds();
  if (b.empty()) return;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c((corner & 1) ? b.max.x() : b.min.x(), (corner & 2) ? b.max.y() : b.min.y(),
                            (corner & 4) ? b.max.z() : b.min.z());
    const Eigen::Vector3d w = scan.pose.apply(c);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(w[a]) || std::abs(w[a]) / scale >= 9007199254740992.0)
        throw FileError(path, std::string("scan '") + scan.name + "': its pose puts " + "XYZ"[a] +
                                  " at " + std::to_string(w[a]) + " m, outside what LAS scaled " +
                                  "integers can hold at scale " + std::to_string(scale) +
                                  " m (|coordinate| / scale must stay below 2^53)");
  }
}

// The header offset: given, or the centre of the finite points' bounds rounded to 1 m.
Eigen::Vector3d chooseOffset(const Bounds& bounds, const LasWriteOptions& options) {
  if (options.offset) return *options.offset;
  if (!bounds.empty()) return bounds.center().array().round();
  return Eigen::Vector3d::Zero();
}

// The intensity scale intensityMap decides from the whole cloud (empty: written as stored).
std::optional<LasStreamFormat::IntensityScale> intensityScale(const PointCloud& cloud, const Dataset& data) {
  const auto range = intensityRange(cloud, knownIntensityLimits(data));
  if (!range) return std::nullopt;
  return LasStreamFormat::IntensityScale{range->lo, range->hi, range->source};
}

bool adjustedGpsTime(const Dataset& data) {
  for (const auto& [k, v] : data.metadata)
    if (k == "GPS time" && v == "adjusted standard GPS time") return true;
  return false;
}

}  // namespace

std::optional<std::pair<double, double>> lasIntensityLimits(const Dataset& data) {
  return knownIntensityLimits(data);
}

void checkLasWriteOptions(const LasWriteOptions& options) {
  if (options.version_minor != 2 && options.version_minor != 4)
    throw InputError("LAS version 1." + std::to_string(options.version_minor) +
                     " cannot be written (1.2 or 1.4)");
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw InputError("LAS scale must be a positive number of metres");
}

void writeLas(const std::filesystem::path& path, const Dataset& data,
              const LasWriteOptions& options, Progress* progress) {
  checkLasWriteOptions(options);
  // One scan with an identity pose is written in place; otherwise scans are merged (a copy).
  for (const Scan& scan : data.scans) checkScanRange(path, scan, options.scale);
  PointCloud merged;
  const bool in_place = data.scans.size() == 1 && data.scans[0].pose.isIdentity();
  if (!in_place) merged = data.merged();
  const PointCloud& cloud = in_place ? data.scans[0].cloud : merged;
  LasStreamFormat format = lasFormatOf(cloud, options);
  format.offset = chooseOffset(cloud.bounds(), options);
  format.intensity_scale = intensityScale(cloud, data);
  format.coordinate_system = data.coordinate_system;
  format.adjusted_gps_time = adjustedGpsTime(data);
  LasStreamWriter writer(path, format, options);
  writer.write(cloud, progress);
  WriteReport report = writer.finish();
  if (options.report) *options.report = std::move(report);
}

}  // namespace plumb
