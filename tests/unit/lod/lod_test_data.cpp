#include "lod_test_data.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>

#include "io/io.hpp"
#include "io/stream/point_stream.hpp"
#include "support/test_support.hpp"

namespace plumb::test {

std::filesystem::path writeSurvey(const std::filesystem::path& dir, int stations, std::size_t per_station,
                                  unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Dataset d;
  for (int k = 0; k < stations; ++k) {
    Scan s;
    s.name = "station " + std::to_string(k);
    s.pose = RigidTransform::fromYaw(0.7 * k, Eigen::Vector3d(651000.25 + 4.5 * k, 6860000.75 - 2.0 * k, 101.5));
    s.has_pose = true;
    for (std::size_t i = 0; i < per_station; ++i) {
      // Walls of a 12 x 8 x 3 m room around the station, floor and ceiling.
      Eigen::Vector3d p(12 * u(rng) - 6, 8 * u(rng) - 4, 3 * u(rng) - 1.5);
      const int face = static_cast<int>(i % 6);
      if (face < 2) p.x() = face == 0 ? -6 : 6;
      else if (face < 4) p.y() = face == 2 ? -4 : 4;
      else p.z() = face == 4 ? -1.5 : 1.5;
      s.cloud.positions.push_back(p.cast<float>());
      s.cloud.intensity.push_back(static_cast<float>(std::floor(u(rng) * 4000)));
      s.cloud.colors.push_back(Rgb8{static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                                    static_cast<std::uint8_t>(rng())});
    }
    for (int dup = 0; dup < 20; ++dup) {  // exact copies of earlier points
      s.cloud.positions.push_back(s.cloud.positions[dup]);
      s.cloud.intensity.push_back(s.cloud.intensity[dup]);
      s.cloud.colors.push_back(s.cloud.colors[dup]);
    }
    d.scans.push_back(std::move(s));
  }
  std::filesystem::create_directories(dir);
  const auto path = dir / "survey.e57";
  writeDataset(path, d);
  return path;
}

namespace {

/// Each chunk's points in the dataset frame, applying the scan's pose to the exact
/// coordinate (the chunks keep residuals below 1 µm that readDataset drops, which can move a
/// value across a half quantum, so the reference reads the same values the cache was given).
struct ExpectedSink final : ChunkSink {
  const LodGrid& grid;
  std::vector<LodRecord>& out;
  RigidTransform pose;
  std::uint16_t station = 0;
  ExpectedSink(const LodGrid& g, std::vector<LodRecord>& o) : grid(g), out(o) {}
  void beginScan(const StreamScan& s) override {
    pose = s.scan.pose;
    station = static_cast<std::uint16_t>(s.index);
  }
  void chunk(const PointCloud& c) override {
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Eigen::Vector3d w = pose.rotation() * c.world(i) + pose.translation();
      if (!w.allFinite()) continue;
      std::array<std::int64_t, 3> q{};
      for (int a = 0; a < 3; ++a) q[a] = std::llround((w[a] - grid.origin[a]) / grid.quantum);
      const float intensity = c.hasIntensity() ? c.intensity[i] : std::nanf("");
      out.emplace_back(q, station, std::bit_cast<std::uint32_t>(intensity), c.hasColors() ? c.colors[i] : Rgb8{});
    }
  }
};

}  // namespace

std::vector<LodRecord> expectedRecords(const std::filesystem::path& file, const LodGrid& grid) {
  std::vector<LodRecord> out;
  ExpectedSink sink(grid, out);
  streamDataset(file, {}, sink);
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t readPointCount(const std::filesystem::path& file) { return readDataset(file).pointCount(); }

std::vector<LodRecord> cachedRecords(const LodCache& cache) {
  const LodHierarchy& h = cache.hierarchy();
  std::vector<LodRecord> out;
  for (const LodNode& n : h.nodes) {
    const LodNodePoints pts = cache.readNode(n.id);
    EXPECT_EQ(pts.size(), n.point_count);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Eigen::Vector3d w = pts.world(i);
      std::array<std::int64_t, 3> q{};
      for (int a = 0; a < 3; ++a) q[a] = std::llround((w[a] - h.grid.origin[a]) / h.grid.quantum);
      // The exact world value is the quantised one (to double rounding).
      EXPECT_NEAR(w.x(), h.grid.origin.x() + q[0] * h.grid.quantum, 1e-8);
      const float intensity = pts.intensity.empty() ? std::nanf("") : pts.intensity[i];
      out.emplace_back(q, pts.station[i], std::bit_cast<std::uint32_t>(intensity), pts.rgb.empty() ? Rgb8{} : pts.rgb[i]);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::shared_ptr<const LodCache> openValid(const std::filesystem::path& source, const std::filesystem::path& root) {
  const LodCacheOpenResult r = openLodCache(source, root);
  EXPECT_TRUE(r.valid()) << r.reason;
  return r.cache;
}

}  // namespace plumb::test
