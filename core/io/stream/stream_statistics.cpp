#include "io/stream/stream_statistics.hpp"

#include <cmath>
#include <limits>

#include "io/stream/point_stream.hpp"

namespace plumb {
namespace {

// Bounds of one scan two ways, as readDataset's scan would give them: with the residual
// column (kept when some residual exceeds PointCloud::kResidualTolerance) or without it.
struct ScanBounds {
  Bounds exact, rounded;
  bool residuals_kept = false;

  void add(const PointCloud& c, const RigidTransform& pose) {
    // A pose that only translates (any static station without rotation) moves every point by
    // the same vector: the extremes of the local coordinates, moved once, are the extremes of
    // the moved points (rounding is monotonic), at a fraction of the cost.
    if (pose.rotation() == Eigen::Matrix3d::Identity()) addTranslated(c, pose.isIdentity() ? Eigen::Vector3d::Zero() : pose.translation());
    else addRotated(c, pose);
  }

  void addRotated(const PointCloud& c, const RigidTransform& pose) {
    const bool identity = pose.isIdentity();
    const bool has_residuals = c.hasPositionResiduals();
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (!c.positions[i].allFinite()) continue;
      // Identity pose without residuals: PointCloud::bounds's float pass (offset + float).
      const Eigen::Vector3d p = c.offset + c.positions[i].cast<double>();
      rounded.extend(identity ? p : pose.apply(p));
      if (!has_residuals) continue;
      noteResidual(c.position_residuals[i]);
      const Eigen::Vector3d w = c.world(i);
      exact.extend(identity ? w : pose.apply(w));
    }
  }

  void addTranslated(const PointCloud& c, const Eigen::Vector3d& t) {
    const bool has_residuals = c.hasPositionResiduals();
    Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity()), hi = -lo;
    Bounds local;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Eigen::Vector3f& p = c.positions[i];
      if (!p.allFinite()) continue;
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      if (!has_residuals) continue;
      noteResidual(c.position_residuals[i]);
      local.extend(c.local(i));
    }
    if (!(lo.x() <= hi.x())) return;
    rounded.extend(Eigen::Vector3d(c.offset + lo.cast<double>() + t));
    rounded.extend(Eigen::Vector3d(c.offset + hi.cast<double>() + t));
    if (local.empty()) return;
    exact.extend(Eigen::Vector3d(c.offset + local.min + t));
    exact.extend(Eigen::Vector3d(c.offset + local.max + t));
  }

  void noteResidual(const Eigen::Vector3f& r) {
    if (!(r.cwiseAbs().maxCoeff() <= static_cast<float>(PointCloud::kResidualTolerance))) residuals_kept = true;
  }
  Bounds result() const { return residuals_kept ? exact : rounded; }
};

class StatisticsSink final : public ChunkSink {
 public:
  explicit StatisticsSink(DatasetStatistics& out) : out_(out) {}

  void beginScan(const StreamScan& scan) override {
    ScanStatistics s;
    s.name = scan.scan.name;
    s.has_pose = scan.scan.has_pose;
    s.pose = scan.scan.pose;
    out_.scans.push_back(std::move(s));
    bounds_ = {};
  }
  void chunk(const PointCloud& points) override {
    ScanStatistics& s = out_.scans.back();
    for (const auto& p : points.positions) s.finite_points += p.allFinite();
    bounds_.add(points, s.pose);
  }
  void endScan(const StreamScanEnd& end) override {
    ScanStatistics& s = out_.scans.back();
    s.points = end.points;
    s.fields = end.fields;
    s.grid_rows = end.grid_rows;
    s.grid_columns = end.grid_columns;
    s.bounds = bounds_.result();
    out_.points += s.points;
    out_.bounds.extend(s.bounds);
  }
  void end(const StreamOutline& outline) override {
    out_.source = outline.dataset.source;
    out_.format = outline.dataset.format;
    out_.coordinate_system = outline.dataset.coordinate_system;
    out_.metadata = outline.dataset.metadata;
  }

 private:
  DatasetStatistics& out_;
  ScanBounds bounds_;
};

}  // namespace

DatasetStatistics datasetStatistics(const std::filesystem::path& path, const StreamOptions& options,
                                    Progress* progress) {
  DatasetStatistics out;
  StatisticsSink sink(out);
  streamDataset(path, options, sink, progress);
  return out;
}

DatasetStatistics datasetStatistics(Dataset data) {
  DatasetStatistics out;
  StatisticsSink sink(out);
  streamInMemory(std::move(data), StreamOptions{}, sink);
  return out;
}

}  // namespace plumb
