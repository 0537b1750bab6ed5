// PCD streaming (issue 16, io/pcd/pcd_records.hpp): binary and binary_compressed files are
// handed over a chunk of records at a time with the values the whole-file reader (PCL, in the
// import helper) gives: the same offset for double coordinates, the same grid, the same
// attributes; ASCII files take the whole-file route; a damaged compressed block is an error
// naming the file and the byte, on both routes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/pcd/pcd_io.hpp"
#include "io/stream/point_stream.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

struct Gather final : ChunkSink {
  PointCloud all;  // the chunks appended (exact world coordinates kept by append)
  std::size_t chunks = 0, largest = 0;
  StreamOutline outline;
  StreamScanEnd end;
  void begin(const StreamOutline& o) override { outline = o; }
  void chunk(const PointCloud& c) override {
    if (chunks++ == 0) all.offset = c.offset;
    largest = std::max(largest, c.size());
    all.append(c);
  }
  void endScan(const StreamScanEnd& e) override { end = e; }
};

Gather streamed(const std::filesystem::path& path) {
  StreamOptions o;
  o.chunk_points = 4096;
  Gather g;
  streamDataset(path, o, g);
  return g;
}

/// Chunks against the whole read: every world coordinate to the bit, every attribute.
void expectSameAsWhole(const std::filesystem::path& path) {
  const Dataset whole = readDataset(path);
  const PointCloud& w = whole.scans.at(0).cloud;
  const Gather g = streamed(path);
  ASSERT_EQ(g.all.size(), w.size());
  EXPECT_LE(g.largest, 4096u);
  EXPECT_EQ(g.end.points, w.size());
  EXPECT_EQ(g.end.fields, w.fieldNames());
  EXPECT_EQ(g.end.grid_rows, w.grid_rows);
  EXPECT_EQ(g.end.grid_columns, w.grid_columns);
  EXPECT_EQ(g.outline.dataset.metadata, whole.metadata);
  EXPECT_EQ(g.all.offset, w.offset);
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Eigen::Vector3d a = w.world(i), b = g.all.world(i);
    if (!a.allFinite()) {
      ASSERT_FALSE(b.allFinite()) << "point " << i;
      continue;
    }
    ASSERT_EQ(a, b) << "point " << i;
  }
  EXPECT_EQ(g.all.colors, w.colors);
  EXPECT_EQ(g.all.intensity, w.intensity);
  EXPECT_EQ(g.all.row, w.row);
  EXPECT_EQ(g.all.column, w.column);
  ASSERT_EQ(g.all.normals.size(), w.normals.size());
  for (std::size_t i = 0; i < w.normals.size(); ++i) ASSERT_EQ(g.all.normals[i], w.normals[i]);
  ASSERT_EQ(g.all.scalar_fields.size(), w.scalar_fields.size());
  for (std::size_t k = 0; k < w.scalar_fields.size(); ++k)
    EXPECT_EQ(g.all.scalar_fields[k].values, w.scalar_fields[k].values) << w.scalar_fields[k].name;
}

/// 20,000 points in Lambert-93 (double coordinates in the PCD), the first 6,000 NaN (the
/// offset sample then needs more than the first chunk), with colour, intensity, normals and
/// a scalar field.
PointCloud georeferencedCloud() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-400.f, 400.f);
  PointCloud c;
  c.offset = {651234.5, 6860123.25, 41.0};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 20000; ++i) {
    c.positions.emplace_back(i < 6000 ? nan : u(rng), u(rng), u(rng) / 40);
    c.colors.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), 7});
    c.intensity.push_back(static_cast<float>(i % 1000));
    c.normals.emplace_back(0.f, 0.6f, 0.8f);
  }
  ScalarField f{"deviation", {}};
  for (int i = 0; i < 20000; ++i) f.values.push_back(0.001f * static_cast<float>(i));
  c.scalar_fields.push_back(std::move(f));
  return c;
}

TEST(PcdChunks, SharedDataFilesStreamAsTheyAreReadWhole) {
  for (const char* name : {"capture0001.pcd", "capture0005.pcd", "room_scan1.pcd", "room_scan2.pcd"}) {
    SCOPED_TRACE(name);
    const auto path = test::sharedData(std::string("pcd/") + name);
    EXPECT_TRUE(streamsInChunks(path));
    expectSameAsWhole(path);
  }
}

TEST(PcdChunks, GeoreferencedBinaryAndCompressedStreamAsReadWhole) {
  const auto dir = test::scratchDir("pcd_chunks_georef");
  const PointCloud c = georeferencedCloud();
  for (bool compressed : {true, false}) {
    SCOPED_TRACE(compressed ? "binary_compressed" : "binary");
    PcdWriteOptions o;
    o.compressed = compressed;
    writePcd(dir / "g.pcd", c, o);
    ASSERT_TRUE(streamsInChunks(dir / "g.pcd"));
    expectSameAsWhole(dir / "g.pcd");
    const Gather g = streamed(dir / "g.pcd");
    ASSERT_EQ(g.all.size(), 14000u);  // unorganized: the NaN points are dropped
    EXPECT_LT((g.all.world(0) - c.world(6000)).norm(), 1e-9);
  }
}

TEST(PcdChunks, OrganizedGridKeepsRowsColumnsAndHolesAcrossChunks) {
  const auto dir = test::scratchDir("pcd_chunks_grid");
  PointCloud c;
  c.grid_rows = 50;
  c.grid_columns = 300;  // 15,000 cells: four chunks, rows cut between chunks
  for (int i = 0; i < 15000; ++i) {
    const bool hole = i % 7 == 3;
    c.positions.emplace_back(hole ? std::numeric_limits<float>::quiet_NaN() : 0.01f * i, 1.f, 2.f);
    c.row.push_back(i / 300);
    c.column.push_back(i % 300);
  }
  writePcd(dir / "grid.pcd", c);
  expectSameAsWhole(dir / "grid.pcd");
  const Gather g = streamed(dir / "grid.pcd");
  ASSERT_EQ(g.all.size(), 15000u);
  EXPECT_EQ(g.all.row[14999], 49);
  EXPECT_EQ(g.all.column[14999], 299);
  EXPECT_EQ(g.end.grid_rows, 50);
}

// fuzz_pcd: FIELDS, SIZE, TYPE and COUNT given twice; PCL keeps the last of each, and so must
// the header check whose layout the stream reads with (it appended them: 44-byte records
// instead of PCL's 32).
TEST(PcdChunks, RepeatedHeaderLinesReadWithPclsLayout) {
  const auto path = std::filesystem::path(PLUMB_IO_REGRESSIONS_DIR) / "pcd/regressions/fuzz_repeated_header_lines.ok.pcd";
  ASSERT_TRUE(streamsInChunks(path));
  const Dataset whole = readDataset(path);
  ASSERT_EQ(whole.pointCount(), 2u);
  expectSameAsWhole(path);
}

TEST(PcdChunks, AsciiAndEmptyFilesTakeTheWholeFileRoute) {
  const auto dir = test::scratchDir("pcd_chunks_ascii");
  test::writeAll(dir / "a.pcd",
                 "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
                 "POINTS 2\nDATA ascii\n1 2 3\n4 5 6\n");
  EXPECT_FALSE(streamsInChunks(dir / "a.pcd"));
  expectSameAsWhole(dir / "a.pcd");
  PointCloud none;
  writePcd(dir / "empty.pcd", none, PcdWriteOptions{false});
  const Gather g = streamed(dir / "empty.pcd");
  EXPECT_EQ(g.all.size(), 0u);
  EXPECT_EQ(g.end.points, 0u);
}

TEST(PcdChunks, AGridOfZeroWidthIsEmptyNeverACrash) {
  // WIDTH 0 x HEIGHT 3: no point. fuzz_pcd found the organized-grid code dividing by the width
  // (SIGFPE in plumb-cli info) before any data was read. Bytes after the declared points are
  // ignored, as for any PCD (PCL does the same): both routes give an empty cloud.
  const auto dir = test::scratchDir("pcd_chunks_zero_width");
  const std::string header = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 0\nHEIGHT 3\nDATA binary\n";
  for (const std::string& data : {std::string(), std::string(12, '\x01')}) {
    test::writeAll(dir / "zero.pcd", header + data);
    EXPECT_EQ(readPcd(dir / "zero.pcd").pointCount(), 0u) << data.size() << " data bytes";
    const Gather g = streamed(dir / "zero.pcd");
    EXPECT_EQ(g.all.size(), 0u) << data.size() << " data bytes";
    EXPECT_EQ(g.end.points, 0u);
  }
}

/// The message of the FileError streaming `path` throws ("" if none).
std::string streamError(const std::filesystem::path& path) {
  try {
    streamed(path);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

/// A one-point x y z (float) binary_compressed PCD whose LZF block is `block`.
std::string onePointPcd(const std::string& block) {
  std::string s =
      "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\n"
      "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1\nDATA binary_compressed\n";
  const std::uint32_t sizes[2] = {static_cast<std::uint32_t>(block.size()), 12};
  s.append(reinterpret_cast<const char*>(sizes), sizeof sizes);
  return s + block;
}

TEST(PcdChunks, DamagedCompressedBlockIsAnErrorOnBothRoutes) {
  const auto dir = test::scratchDir("pcd_chunks_damaged");
  const std::string twelve("\x00\x00\x80\x3f\x00\x00\x00\x40\x00\x00\x40\x40", 12);  // 1 2 3
  const std::string header_end = onePointPcd("");
  const std::size_t block = header_end.size();
  struct Case {
    const char* name;
    std::string block, problem;
    std::size_t where;  // byte offset named in the message
  };
  const std::vector<Case> cases = {
      {"far.pcd", std::string("\x20\x00", 2) + twelve, "back reference points before the start", block},
      {"past.pcd", std::string(1, '\x1f') + twelve, "literal run goes past the end", block},
      {"fewer.pcd", std::string(1, '\x07') + twelve.substr(0, 8), "fewer than its points need", block + 9},
      {"more.pcd", std::string(1, '\x0b') + twelve + std::string("\x00\x01", 2), "more bytes than its points need",
       block + 15}};
  test::writeAll(dir / "good.pcd", onePointPcd(std::string(1, '\x0b') + twelve));
  const Gather good = streamed(dir / "good.pcd");
  ASSERT_EQ(good.all.size(), 1u);
  EXPECT_EQ(good.all.positions[0], Eigen::Vector3f(1, 2, 3));
  expectSameAsWhole(dir / "good.pcd");
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    test::writeAll(dir / c.name, onePointPcd(c.block));
    const std::string e = streamError(dir / c.name);
    EXPECT_NE(e.find(c.name), std::string::npos) << e;
    EXPECT_NE(e.find(c.problem), std::string::npos) << e;
    EXPECT_NE(e.find("byte " + std::to_string(c.where)), std::string::npos) << e;
    EXPECT_THROW(readDataset(dir / c.name), FileError);  // PCL refuses it too
  }
}

}  // namespace
}  // namespace plumb
