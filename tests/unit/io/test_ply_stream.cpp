// Streaming PLY reads (streamPlyVertices through streamDataset): the chunks are readPly's
// vertices value for value, for binary (little and big endian, float and double coordinates,
// fixed-size and list-carrying records) and ASCII files larger than the reader's 64 KiB block,
// so records straddle block boundaries; a PLY with faces is a model and is not streamed.
#include <gtest/gtest.h>

#include <random>
#include <cstring>
#include <sstream>

#include "common/error.hpp"

#include "io/io.hpp"
#include "io/stream/point_convert.hpp"
#include "io/stream/point_stream.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

struct Collect final : ChunkSink {
  StreamOutline outline;
  std::vector<PointCloud> chunks;
  std::vector<StreamScanEnd> ends;
  void begin(const StreamOutline& o) override { outline = o; }
  void chunk(const PointCloud& c) override { chunks.push_back(c); }
  void endScan(const StreamScanEnd& e) override { ends.push_back(e); }
};

// `n` points with normals, colours, intensity and a scalar field, `far` metres from the origin
// (1e6: double coordinates), on a grid of 100 columns.
Dataset cloud(std::size_t n, double far, double intensity_step = 1.0) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  PointCloud c;
  c.offset = Eigen::Vector3d(far, far / 2, 0);
  ScalarField quality{"quality", {}};
  for (std::size_t i = 0; i < n; ++i) {
    c.positions.push_back(Eigen::Vector3f(u(rng), u(rng), u(rng)));
    c.normals.push_back(Eigen::Vector3f(u(rng), u(rng), 1).normalized());
    c.colors.push_back(Rgb8{std::uint8_t(i % 256), std::uint8_t(i / 7 % 256), std::uint8_t(9)});
    c.intensity.push_back(static_cast<float>(0.5 * (intensity_step != 1.0) + intensity_step * double(i % 1000)));
    quality.values.push_back(static_cast<float>(u(rng)));
  }
  c.scalar_fields.push_back(std::move(quality));
  c.grid_rows = static_cast<std::int32_t>(n / 100);
  c.grid_columns = 100;
  return Dataset::fromCloud(std::move(c), "cloud");
}

void expectChunksAreTheFile(const std::filesystem::path& path) {
  SCOPED_TRACE(path.filename().string());
  const PointCloud whole = readDataset(path).scans.at(0).cloud;
  StreamOptions o;
  o.chunk_points = 4096;
  Collect sink;
  streamDataset(path, o, sink);
  ASSERT_EQ(sink.outline.scans.size(), 1u);
  EXPECT_EQ(sink.outline.scans[0].record_count, whole.size());
  EXPECT_EQ(sink.outline.scans[0].fields, whole.fieldNames());
  ASSERT_EQ(sink.ends.size(), 1u);
  EXPECT_EQ(sink.ends[0].points, whole.size());
  EXPECT_EQ(sink.ends[0].fields, whole.fieldNames());
  EXPECT_EQ(sink.ends[0].grid_rows, whole.grid_rows);
  EXPECT_EQ(sink.ends[0].grid_columns, whole.grid_columns);
  PointCloud joined;
  for (const auto& c : sink.chunks) {
    ASSERT_LE(c.size(), 4096u);
    ASSERT_EQ(c.offset, whole.offset);
    if (joined.empty()) joined = c;
    else joined.append(c);
  }
  ASSERT_EQ(joined.size(), whole.size());
  ASSERT_GT(sink.chunks.size(), 2u);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    ASSERT_EQ(joined.positions[i], whole.positions[i]) << i;
    ASSERT_LE((joined.world(i) - whole.world(i)).cwiseAbs().maxCoeff(), PointCloud::kResidualTolerance) << i;
    if (whole.hasNormals()) {
      ASSERT_EQ(joined.normals[i], whole.normals[i]) << i;
    }
    if (whole.hasColors()) {
      ASSERT_EQ(joined.colors[i], whole.colors[i]) << i;
    }
    if (whole.hasIntensity()) {
      ASSERT_EQ(joined.intensity[i], whole.intensity[i]) << i;
    }
  }
  for (const auto& f : whole.scalar_fields) {
    const ScalarField* g = joined.findScalarField(f.name);
    ASSERT_NE(g, nullptr) << f.name;
    for (std::size_t i = 0; i < whole.size(); ++i) ASSERT_EQ(g->values[i], f.values[i]) << f.name << " " << i;
  }
}

TEST(PlyStream, ChunksAreTheWholeFileReadersVertices) {
  const auto dir = test::scratchDir("ply_stream");
  WriteOptions ascii;
  ascii.binary = false;
  for (double far : {0.0, 1e6}) {
    const std::string tag = far > 0 ? "double" : "float";
    writeDataset(dir / ("binary_" + tag + ".ply"), cloud(20000, far));
    writeDataset(dir / ("ascii_" + tag + ".ply"), cloud(20000, far), ascii);
    ASSERT_GT(std::filesystem::file_size(dir / ("ascii_" + tag + ".ply")), 4u * 65536);  // many blocks
    EXPECT_TRUE(streamsInChunks(dir / ("binary_" + tag + ".ply")));
    expectChunksAreTheFile(dir / ("binary_" + tag + ".ply"));
    expectChunksAreTheFile(dir / ("ascii_" + tag + ".ply"));
  }
}

// Big-endian records with a list on each vertex (read record by record) and a uchar intensity.
TEST(PlyStream, BigEndianListCarryingVertices) {
  const auto dir = test::scratchDir("ply_stream_be");
  std::ostringstream s;
  const int n = 9000;
  s << "ply\nformat binary_big_endian 1.0\nelement vertex " << n
    << "\nproperty double x\nproperty double y\nproperty float z\nproperty uchar intensity\n"
       "property list uchar int tags\nend_header\n";
  auto put = [&s](auto v) {
    char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (std::size_t k = sizeof v; k-- > 0;) s.put(b[k]);
  };
  for (int i = 0; i < n; ++i) {
    put(500000.0 + i * 0.001);
    put(-3.25 * i);
    put(static_cast<float>(i % 17));
    s.put(static_cast<char>(i % 200));
    const std::uint8_t tags = static_cast<std::uint8_t>(i % 3);
    s.put(static_cast<char>(tags));
    for (int t = 0; t < tags; ++t) put(std::int32_t(t));
  }
  test::writeAll(dir / "be.ply", s.str());
  expectChunksAreTheFile(dir / "be.ply");
  Collect sink;
  streamDataset(dir / "be.ply", StreamOptions{}, sink);
  EXPECT_TRUE(sink.outline.scans.at(0).intensity_integral);  // uchar
}

// Float intensity without declared limits: writeLas scales by the data's min/max (or keeps
// whole numbers as stored); the streamed conversion gathers that range in a first pass and
// writes the same values and the same note.
TEST(PlyStream, FloatIntensityToLasIsTheWholeRoutes) {
  const auto dir = test::scratchDir("ply_stream_las");
  for (double step : {1.0, 0.25}) {
    SCOPED_TRACE(step);
    writeDataset(dir / "in.ply", cloud(20000, 0, step));
    ConvertParams params;
    params.stream.chunk_points = 4096;
    const ConvertResult streamed = convertPointFile(dir / "in.ply", dir / "s.las", params);
    params.allow_streaming = false;
    const ConvertResult whole = convertPointFile(dir / "in.ply", dir / "w.las", params);
    EXPECT_TRUE(streamed.streamed);
    ASSERT_EQ(streamed.files.size(), 1u);
    EXPECT_EQ(streamed.files[0].report.notes, whole.files.at(0).report.notes);
    const PointCloud a = readDataset(dir / "s.las").merged(), b = readDataset(dir / "w.las").merged();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.intensity[i], b.intensity[i]) << i;
  }
}

TEST(PlyStream, PlyWithFacesIsAModelNotAStream) {
  const auto dir = test::scratchDir("ply_stream_mesh");
  test::writeAll(dir / "tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_FALSE(streamsInChunks(dir / "tri.ply"));
  test::writeAll(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex many\nend_header\n");
  EXPECT_FALSE(streamsInChunks(dir / "bad.ply"));  // the whole reader reports what is wrong
  EXPECT_THROW(readDataset(dir / "bad.ply"), FileError);
  // A header without y and z: the stream's error is the whole reader's, naming the file.
  test::writeAll(dir / "no_yz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
  Collect sink;
  try {
    streamDataset(dir / "no_yz.ply", StreamOptions{}, sink);
    ADD_FAILURE() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("no_yz.ply"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no x, y and z"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace plumb
