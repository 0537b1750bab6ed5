// Streaming reads (io/stream): the chunks of E57 and LAS files are the points readDataset
// gives (same offset, same floats, same residuals and attributes), the streamed statistics are
// readDataset's, and streamed conversions write what the whole-file route writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <random>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/stream/point_convert.hpp"
#include "io/stream/point_stream.hpp"
#include "io/stream/stream_statistics.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

using test::sharedData;

// Keeps every chunk (tests only: the point of streaming is not to).
struct Collect final : ChunkSink {
  std::vector<std::vector<PointCloud>> scans;
  std::vector<StreamScanEnd> ends;
  void beginScan(const StreamScan&) override { scans.emplace_back(); }
  void chunk(const PointCloud& c) override { scans.back().push_back(c); }
  void endScan(const StreamScanEnd& e) override { ends.push_back(e); }
};

template <class V>
void expectSameRange(const V& whole, const V& part, std::size_t begin, const char* what) {
  if (whole.empty()) return;
  ASSERT_GE(part.size(), 1u) << what;
  for (std::size_t i = 0; i < part.size(); ++i) {
    const auto a = whole[begin + i], b = part[i];
    if constexpr (std::is_floating_point_v<decltype(a)>) {
      if (std::isnan(a) && std::isnan(b)) continue;
    }
    ASSERT_EQ(a, b) << what << " point " << begin + i;
  }
}

// Chunks of one scan against the scan read whole: offset, positions, residuals, attributes.
void expectSameScan(const PointCloud& whole, const std::vector<PointCloud>& chunks) {
  std::size_t begin = 0;
  for (const auto& c : chunks) {
    EXPECT_LE(c.size(), 4096u);
    ASSERT_EQ(c.offset, whole.offset);
    for (std::size_t i = 0; i < c.size(); ++i) {
      ASSERT_EQ(c.positions[i], whole.positions[begin + i]) << "point " << begin + i;
      if (whole.hasPositionResiduals()) {
        ASSERT_EQ(c.position_residuals[i], whole.position_residuals[begin + i]);
      } else if (c.hasPositionResiduals()) {
        ASSERT_LE(c.position_residuals[i].cwiseAbs().maxCoeff(), PointCloud::kResidualTolerance);
      }
    }
    expectSameRange(whole.intensity, c.intensity, begin, "intensity");
    expectSameRange(whole.colors, c.colors, begin, "colour");
    expectSameRange(whole.normals, c.normals, begin, "normal");
    expectSameRange(whole.row, c.row, begin, "row");
    expectSameRange(whole.column, c.column, begin, "column");
    expectSameRange(whole.timestamps, c.timestamps, begin, "time");
    expectSameRange(whole.return_index, c.return_index, begin, "return");
    expectSameRange(whole.classification, c.classification, begin, "class");
    expectSameRange(whole.point_source_id, c.point_source_id, begin, "point source");
    for (const auto& f : whole.scalar_fields) {
      const ScalarField* g = c.findScalarField(f.name);
      ASSERT_NE(g, nullptr) << f.name;
      expectSameRange(f.values, g->values, begin, f.name.c_str());
    }
    begin += c.size();
  }
  EXPECT_EQ(begin, whole.size());
}

const std::vector<std::string> kFiles = {
    "e57/A_B.e57",           "e57/bunnyInt19.e57",          "e57/testWithNormals.e57",
    "e57/tinyCartesianFloatRgb.e57", "e57/integer_intensity.e57", "e57/tiny_spherical.e57",
    "e57/libe57format_self_ColouredCubeFloat.e57", "e57/empty_pc.e57",
    "las/autzen_trim.las",   "las/1.2-with-color.las",      "las/extrabytes.las",
    "las/simple1_4.las",     "las/test1_4.las",             "pcd/room_scan1.pcd"};

StreamOptions smallChunks() {
  StreamOptions o;
  o.chunk_points = 1;  // raised to 4096: many chunks
  return o;
}

TEST(PointStream, ChunksAreTheWholeFileReadersPoints) {
  for (const auto& name : kFiles) {
    SCOPED_TRACE(name);
    const Dataset whole = readDataset(sharedData(name));
    Collect sink;
    streamDataset(sharedData(name), smallChunks(), sink);
    ASSERT_EQ(sink.scans.size(), whole.scans.size());
    for (std::size_t k = 0; k < whole.scans.size(); ++k) {
      expectSameScan(whole.scans[k].cloud, sink.scans[k]);
      EXPECT_EQ(sink.ends[k].points, whole.scans[k].cloud.size());
      EXPECT_EQ(sink.ends[k].fields, whole.scans[k].cloud.fieldNames());
    }
  }
}

TEST(PointStream, StatisticsAreReadDatasets) {
  for (const auto& name : kFiles) {
    SCOPED_TRACE(name);
    const Dataset whole = readDataset(sharedData(name));
    const DatasetStatistics s = datasetStatistics(sharedData(name), smallChunks());
    EXPECT_EQ(s.format, whole.format);
    EXPECT_EQ(s.points, whole.pointCount());
    EXPECT_EQ(s.bounds.min, whole.bounds().min);
    EXPECT_EQ(s.bounds.max, whole.bounds().max);
    auto sorted = [](auto v) { std::sort(v.begin(), v.end()); return v; };
    EXPECT_EQ(sorted(s.metadata), sorted(whole.metadata));
    ASSERT_EQ(s.scans.size(), whole.scans.size());
    for (std::size_t k = 0; k < whole.scans.size(); ++k) {
      const PointCloud& c = whole.scans[k].cloud;
      EXPECT_EQ(s.scans[k].fields, c.fieldNames());
      EXPECT_EQ(s.scans[k].grid_rows, c.grid_rows);
      EXPECT_EQ(s.scans[k].grid_columns, c.grid_columns);
      const auto finite = std::count_if(c.positions.begin(), c.positions.end(), [](const auto& p) { return p.allFinite(); });
      EXPECT_EQ(s.scans[k].finite_points, static_cast<std::uint64_t>(finite));
    }
  }
}

// Three stations with poses, float intensity in 0..1 and a grid: what the simulator writes.
Dataset stations(std::size_t per_scan) {
  Dataset d;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  for (int k = 0; k < 3; ++k) {
    Scan s;
    s.name = "station " + std::to_string(k);
    s.pose = RigidTransform::fromQuaternion(Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * k, Eigen::Vector3d::UnitZ())),
                                            Eigen::Vector3d(1000.0 + 7 * k, 2000.0, 50.0));
    s.has_pose = true;
    for (std::size_t i = 0; i < per_scan; ++i) {
      s.cloud.positions.push_back(Eigen::Vector3f(u(rng), u(rng), u(rng) / 4));
      s.cloud.intensity.push_back(static_cast<float>(0.05 + 0.9 * (u(rng) + 20) / 40));
      s.cloud.row.push_back(static_cast<std::int32_t>(i / 100));
      s.cloud.column.push_back(static_cast<std::int32_t>(i % 100));
    }
    d.scans.push_back(std::move(s));
  }
  return d;
}

// Every point of `a` is the point of `b` at the same index to `tolerance`, same intensity.
void expectSamePoints(const Dataset& a, const Dataset& b, double tolerance) {
  const PointCloud x = a.merged(), y = b.merged();
  ASSERT_EQ(x.size(), y.size());
  double worst = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    worst = std::max(worst, (x.world(i) - y.world(i)).cwiseAbs().maxCoeff());
    ASSERT_EQ(x.intensity[i], y.intensity[i]) << i;
  }
  EXPECT_LE(worst, tolerance);
  EXPECT_EQ(x.fieldNames(), y.fieldNames());
}

// Largest coordinate difference between the points of `a` and `b` (same order).
double worstDifference(const Dataset& a, const Dataset& b) {
  const PointCloud x = a.merged(), y = b.merged();
  EXPECT_EQ(x.size(), y.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    worst = std::max(worst, (x.world(i) - y.world(i)).cwiseAbs().maxCoeff());
  return worst;
}

// The source's points moved by `t`: all scans, or scan `k` alone.
Dataset expected(const Dataset& source, const RigidTransform& t, std::optional<std::size_t> k) {
  Dataset d;
  for (std::size_t s = 0; s < source.scans.size(); ++s)
    if (!k || *k == s) d.scans.push_back(source.scans[s]);
  for (auto& scan : d.scans) scan.pose = t * scan.pose;
  return d;
}

TEST(PointConvert, StreamedOutputsAreTheWholeFileOutputs) {
  const auto dir = test::scratchDir("point_convert_stream");
  const auto e57 = dir / "stations.e57";
  writeDataset(e57, stations(20000));
  const Dataset source = readDataset(e57);
  ConvertParams params;
  params.stream = smallChunks();
  params.transform = RigidTransform::fromQuaternion(Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX())),
                                                    Eigen::Vector3d(5.0, -3.0, 1.0));
  for (const char* ext : {".las", ".ply", ".e57"}) {
    for (bool split : {false, true}) {
      SCOPED_TRACE(std::string(ext) + (split ? " split" : ""));
      params.split = split;
      params.allow_streaming = true;
      const ConvertResult streamed = convertPointFile(e57, dir / (std::string("s") + ext), params);
      params.allow_streaming = false;
      const ConvertResult whole = convertPointFile(e57, dir / (std::string("w") + ext), params);
      EXPECT_TRUE(streamed.streamed);
      EXPECT_FALSE(whole.streamed);
      ASSERT_EQ(streamed.files.size(), split ? 3u : 1u);
      ASSERT_EQ(streamed.files.size(), whole.files.size());
      for (std::size_t f = 0; f < whole.files.size(); ++f) {
        EXPECT_EQ(streamed.files[f].points, whole.files[f].points);
        EXPECT_EQ(streamed.files[f].report.notes, whole.files[f].report.notes);
        // LAS: the header offsets differ (first chunk / whole bounds), so a coordinate half-way
        // between two quanta may round to either (one quantum); the whole route also drops
        // residuals within 1 µm the stream keeps. PLY (float32 at ~2 km: steps of 0.12 mm):
        // both within the 0.1 mm claim of the source, so within 0.2 mm of each other. E57: both
        // routes quantize the same scan-frame coordinates (E57StreamWriter, scan by scan).
        const Dataset s = readDataset(streamed.files[f].path), w = readDataset(whole.files[f].path);
        const bool las = std::string(ext) == ".las";
        expectSamePoints(s, w, las ? 1e-4 + 2 * PointCloud::kResidualTolerance : 2 * kCoordinatePrecision);
        if (!las) {
          const Dataset truth = expected(source, params.transform, split ? std::optional<std::size_t>(f) : std::nullopt);
          EXPECT_LE(worstDifference(s, truth), kCoordinatePrecision);
          EXPECT_LE(worstDifference(w, truth), kCoordinatePrecision);
        }
      }
    }
  }
}

TEST(PointConvert, ScansWithDifferentFieldsAreMergedWhole) {
  const auto dir = test::scratchDir("point_convert_fallback");
  const ConvertResult r = convertPointFile(sharedData("e57/A_B_different_dims.e57"), dir / "m.las", {});
  EXPECT_FALSE(r.streamed);
  ASSERT_EQ(r.files.size(), 1u);
  EXPECT_EQ(readDataset(dir / "m.las").pointCount(), r.files[0].points);
}

TEST(PointConvert, CancelledStreamLeavesExistingOutputUntouched) {
  const auto dir = test::scratchDir("point_convert_cancel");
  const auto e57 = dir / "stations.e57";
  writeDataset(e57, stations(20000));
  test::writeAll(dir / "out.las", "previous content");
  Progress cancel;
  cancel = Progress([&cancel](double fraction, std::string_view) {
    if (fraction > 0.3) cancel.cancel();
  });
  ConvertParams params;
  params.stream = smallChunks();
  EXPECT_THROW(convertPointFile(e57, dir / "out.las", params, &cancel), Canceled);
  EXPECT_EQ(test::readAll(dir / "out.las"), "previous content");
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 2u);  // no temporary left behind
}

// Station 0 only translates (the bounds' fast path), 1 and 2 rotate; coordinates near 2 km
// keep residuals.
TEST(PointStream, StatisticsOfPosedStationsAreReadDatasets) {
  const auto dir = test::scratchDir("point_stream_stations");
  writeDataset(dir / "stations.e57", stations(20000));
  const Dataset whole = readDataset(dir / "stations.e57");
  const DatasetStatistics s = datasetStatistics(dir / "stations.e57", smallChunks());
  EXPECT_EQ(s.points, whole.pointCount());
  EXPECT_EQ(s.bounds.min, whole.bounds().min);
  EXPECT_EQ(s.bounds.max, whole.bounds().max);
  for (std::size_t k = 0; k < whole.scans.size(); ++k) {
    Dataset one;
    one.scans.push_back(whole.scans[k]);
    EXPECT_EQ(s.scans[k].bounds.min, one.bounds().min) << k;
    EXPECT_EQ(s.scans[k].bounds.max, one.bounds().max) << k;
  }
}

}  // namespace
}  // namespace plumb
