#pragma once
// The two streamed passes of a cache build (lod_builder.cpp): the bounds and stations of the
// points in the dataset frame, then the points quantised on the cache's grid.
#include <cstdint>
#include <functional>
#include <vector>

#include "io/lod/lod_hierarchy.hpp"
#include "io/stream/chunk_sink.hpp"

namespace plumb {

/// Dataset-frame coordinate of a chunk's point i: the scan's pose applied in double to the
/// exact coordinate (both passes use this one expression, so they agree to the bit).
inline Eigen::Vector3d lodWorldPoint(const PointCloud& c, std::size_t i, const RigidTransform& pose) {
  return pose.apply(c.world(i));
}

/// Pass 1: bounds of the finite points, their count, the stations and their fields.
struct LodSurveySink final : ChunkSink {
  Bounds bounds;
  std::uint64_t finite = 0, skipped = 0;
  std::vector<LodStation> stations;
  void beginScan(const StreamScan& scan) override;
  void chunk(const PointCloud& points) override;
  void endScan(const StreamScanEnd& end) override;

 private:
  RigidTransform pose_;
};

/// Pass 2: each chunk's finite points as LodPoints on `grid`, handed to `consume`.
struct LodQuantiseSink final : ChunkSink {
  LodQuantiseSink(const LodGrid& grid, const std::vector<LodStation>& stations, std::filesystem::path file,
                  std::function<void(const std::vector<LodPoint>&)> consume)
      : grid_(grid), stations_(stations), file_(std::move(file)), consume_(std::move(consume)) {}
  void beginScan(const StreamScan& scan) override;
  void chunk(const PointCloud& points) override;

 private:
  LodGrid grid_;
  const std::vector<LodStation>& stations_;
  std::filesystem::path file_;
  std::function<void(const std::vector<LodPoint>&)> consume_;
  std::vector<LodPoint> batch_;
  RigidTransform pose_;
  std::uint16_t station_ = 0;
};

}  // namespace plumb
