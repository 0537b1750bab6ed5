// Streaming text reads (streamText through streamDataset): files of several 4 MiB blocks, so
// records straddle the block boundaries, give readText's points value for value (CSV with a
// header and double coordinates; space-separated XYZ RGB with comments and PTS count lines),
// and an error past the first block names the line readText names.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/stream/point_stream.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

struct Collect final : ChunkSink {
  StreamOutline outline;
  PointCloud joined;
  std::size_t chunks = 0;
  StreamScanEnd end;
  void begin(const StreamOutline& o) override { outline = o; }
  void chunk(const PointCloud& c) override {
    EXPECT_LE(c.size(), 4096u);
    ++chunks;
    if (joined.empty()) joined = c;
    else joined.append(c);
  }
  void endScan(const StreamScanEnd& e) override { end = e; }
};

void expectStreamIsReadText(const std::filesystem::path& path) {
  SCOPED_TRACE(path.filename().string());
  ASSERT_GT(std::filesystem::file_size(path), 2u * (4u << 20));  // three blocks or more
  EXPECT_TRUE(streamsInChunks(path));
  const Dataset whole = readDataset(path);
  const PointCloud& w = whole.scans.at(0).cloud;
  StreamOptions o;
  o.chunk_points = 4096;
  Collect sink;
  streamDataset(path, o, sink);
  EXPECT_EQ(sink.outline.dataset.metadata, whole.metadata);
  EXPECT_EQ(sink.outline.scans.at(0).fields, w.fieldNames());
  EXPECT_EQ(sink.end.fields, w.fieldNames());
  EXPECT_EQ(sink.end.points, w.size());
  ASSERT_EQ(sink.joined.size(), w.size());
  EXPECT_EQ(sink.joined.offset, w.offset);
  for (std::size_t i = 0; i < w.size(); ++i) {
    ASSERT_EQ(sink.joined.world(i), w.world(i)) << i;  // both exact to the double parsed
    if (w.hasIntensity()) {
      ASSERT_EQ(sink.joined.intensity[i], w.intensity[i]) << i;
    }
    if (w.hasColors()) {
      ASSERT_EQ(sink.joined.colors[i], w.colors[i]) << i;
    }
  }
  for (const auto& f : w.scalar_fields) {
    const ScalarField* g = sink.joined.findScalarField(f.name);
    ASSERT_NE(g, nullptr) << f.name;
    for (std::size_t i = 0; i < w.size(); ++i) ASSERT_EQ(g->values[i], f.values[i]) << f.name << i;
  }
}

TEST(TextStream, CsvWithHeaderAndDoubleCoordinates) {
  const auto dir = test::scratchDir("text_stream_csv");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 50.0);
  std::ostringstream s;
  s.precision(12);
  s << "x,y,z,intensity,quality\n";
  for (int i = 0; i < 250000; ++i)
    s << 512000.0 + u(rng) << "," << 4100000.0 + u(rng) << "," << u(rng) << "," << i % 4000 << "," << u(rng) << "\n";
  test::writeAll(dir / "points.csv", s.str());
  expectStreamIsReadText(dir / "points.csv");
}

TEST(TextStream, XyzRgbWithCommentsAndPtsCounts) {
  const auto dir = test::scratchDir("text_stream_xyz");
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::ostringstream s;
  for (int block = 0; block < 3; ++block) {
    s << 150000 << "\n";  // a PTS count line before each block
    for (int i = 0; i < 150000; ++i) {
      if (i % 40000 == 7) s << "# a comment among the points\n";
      s << u(rng) << " " << u(rng) << "  " << u(rng) << " " << (i % 256) << " " << (i / 3 % 256) << " 17\n";
    }
  }
  test::writeAll(dir / "points.xyz", s.str());
  expectStreamIsReadText(dir / "points.xyz");
}

TEST(TextStream, ErrorPastTheFirstBlockNamesReadTextsLine) {
  const auto dir = test::scratchDir("text_stream_error");
  std::ostringstream s;
  for (int i = 0; i < 400000; ++i) s << i * 0.001 << " 2.5 3.25\n";
  s << "1.0 2.0 oops\n";
  test::writeAll(dir / "bad.xyz", s.str());
  std::string whole_error, stream_error;
  try {
    readDataset(dir / "bad.xyz");
  } catch (const FileError& e) {
    whole_error = e.what();
  }
  Collect sink;
  StreamOptions o;
  o.chunk_points = 4096;
  try {
    streamDataset(dir / "bad.xyz", o, sink);
  } catch (const FileError& e) {
    stream_error = e.what();
  }
  EXPECT_NE(whole_error.find("line 400001"), std::string::npos) << whole_error;
  EXPECT_EQ(stream_error, whole_error);
}

}  // namespace
}  // namespace plumb
