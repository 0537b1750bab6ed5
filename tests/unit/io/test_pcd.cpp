// PCD through PCL: every shared PCD file (values verified by verify_shared_data.py, which
// decodes the LZF data itself), organized-cloud rules, round trips, and errors.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "io/pcd/pcd_io.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
struct PcdFact {
  const char* file;
  std::size_t points, finite;
  bool organized;
  Eigen::Vector3d min, max;
};
// From: python3 tests/unit/io/verify_shared_data.py ../shared/data
const PcdFact kFacts[] = {
    {"capture0001.pcd", 307200, 249647, true, {-1.7228, -1.1953, 1.5120}, {1.2234, 0.7810, 3.1570}},
    {"capture0002.pcd", 307200, 249931, true, {-1.6923, -1.1896, 1.5390}, {1.2643, 0.7693, 3.1010}},
    {"capture0003.pcd", 307200, 248494, true, {-1.7714, -1.1840, 1.4490}, {1.2668, 0.7616, 3.6210}},
    {"capture0004.pcd", 307200, 244573, true, {-2.0256, -1.3721, 1.3900}, {1.2708, 0.7581, 3.7380}},
    {"capture0005.pcd", 307200, 244977, true, {-1.9553, -1.3999, 1.3680}, {1.2839, 0.7653, 3.6980}},
    {"room_scan1.pcd", 112586, 112586, false, {-13.7998, -6.4928, -1.3517}, {15.4471, 7.9796, 1.7091}},
    {"room_scan2.pcd", 112624, 112624, false, {-12.5520, -10.9194, -1.7184}, {12.2995, 10.0504, 1.8821}},
};

std::size_t finite(const PointCloud& c) {
  std::size_t n = 0;
  for (const auto& p : c.positions) n += p.allFinite();
  return n;
}
}  // namespace

TEST(Pcd, EverySharedFile) {
  for (const auto& f : kFacts) {
    SCOPED_TRACE(f.file);
    const Dataset d = readPcd(test::sharedData(std::string("pcd/") + f.file));
    ASSERT_EQ(d.scans.size(), 1u);
    const PointCloud& c = d.scans[0].cloud;
    EXPECT_EQ(c.size(), f.points);
    EXPECT_EQ(finite(c), f.finite);
    const Bounds b = c.bounds();
    EXPECT_LT((b.min - f.min).cwiseAbs().maxCoeff(), 1e-4);
    EXPECT_LT((b.max - f.max).cwiseAbs().maxCoeff(), 1e-4);
    if (f.organized) {
      EXPECT_EQ(c.grid_rows, 480);
      EXPECT_EQ(c.grid_columns, 640);
      ASSERT_TRUE(c.hasGrid());
      EXPECT_EQ(c.row[641], 1);  // index = row * columns + column
      EXPECT_EQ(c.column[641], 1);
    } else {
      EXPECT_EQ(c.grid_rows, 0);
      EXPECT_FALSE(c.hasGrid());
    }
  }
}

TEST(Pcd, RoundTripCompressedAndBinaryKeepsGridAndAttributes) {
  const auto dir = test::scratchDir("pcd_roundtrip");
  PointCloud c;
  c.grid_rows = 2;
  c.grid_columns = 3;
  for (int i = 0; i < 6; ++i) {
    c.positions.emplace_back(i, 2.f * i, i == 4 ? std::numeric_limits<float>::quiet_NaN() : 0.5f);
    c.colors.push_back({static_cast<std::uint8_t>(10 * i), 20, 250});
    c.intensity.push_back(0.25f * i);
    c.normals.emplace_back(0.f, 0.f, 1.f);
  }
  c.scalar_fields.push_back({"curvature", {1, 2, 3, 4, 5, 6}});
  for (bool compressed : {true, false}) {
    PcdWriteOptions o;
    o.compressed = compressed;
    writePcd(dir / "o.pcd", c, o);
    const PointCloud r = readPcd(dir / "o.pcd").scans[0].cloud;
    ASSERT_EQ(r.size(), 6u);
    EXPECT_EQ(r.grid_rows, 2);
    EXPECT_EQ(r.grid_columns, 3);
    EXPECT_TRUE(std::isnan(r.positions[4].z()));
    EXPECT_EQ(r.positions[5], c.positions[5]);
    EXPECT_EQ(r.colors, c.colors);
    EXPECT_EQ(r.intensity, c.intensity);
    EXPECT_EQ(r.normals[3], c.normals[3]);
    ASSERT_NE(r.findScalarField("curvature"), nullptr);
    EXPECT_EQ(r.findScalarField("curvature")->values, c.scalar_fields[0].values);
  }
}

TEST(Pcd, UnorganizedDropsNaNAndGeoreferencedUsesDouble) {
  const auto dir = test::scratchDir("pcd_georef");
  PointCloud c;
  c.offset = {652000, 6862000, 30};
  c.positions = {{0.001f, 0.002f, 0.003f}, {1.f, 2.f, 3.f}, {std::numeric_limits<float>::quiet_NaN(), 0.f, 0.f}};
  writePcd(dir / "g.pcd", c);
  const PointCloud r = readPcd(dir / "g.pcd").scans[0].cloud;
  ASSERT_EQ(r.size(), 2u);  // NaN point removed (unorganized)
  EXPECT_LT((r.world(0) - c.world(0)).norm(), 1e-6);
  EXPECT_LT((r.world(1) - c.world(1)).norm(), 1e-6);
  EXPECT_EQ(r.offset, Eigen::Vector3d(652001, 6862002, 33));  // median of the finite points, 1 m
}

TEST(Pcd, ErrorsNameFileAndPlace) {
  const auto dir = test::scratchDir("pcd_errors");
  auto err = [&](const std::string& name, const std::string& bytes) {
    test::writeAll(dir / name, bytes);
    try {
      readPcd(dir / name);
    } catch (const FileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string m = err("a.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n");
  EXPECT_NE(m.find("a.pcd: FIELDS, SIZE, TYPE and COUNT have different numbers"), std::string::npos) << m;
  EXPECT_NE(m.find("line 9"), std::string::npos) << m;
  m = err("b.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 10\nHEIGHT 1\nPOINTS 10\nDATA binary\n" +
                       std::string(12 * 4 + 5, '\0'));
  EXPECT_NE(m.find("expected 10 points, file ends at byte"), std::string::npos) << m;
  EXPECT_NE(m.find("in point 4"), std::string::npos) << m;
  m = err("c.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 2\nPOINTS 5\nDATA ascii\n");
  EXPECT_NE(m.find("WIDTH x HEIGHT (3 x 2) differs from POINTS 5"), std::string::npos) << m;
  EXPECT_NE(m.find("line 8"), std::string::npos) << m;
  m = err("f.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 1\n");
  EXPECT_NE(m.find("no DATA line"), std::string::npos) << m;
  m = err("d.pcd", "");
  EXPECT_NE(m.find("d.pcd: file is empty"), std::string::npos) << m;
  // Truncated binary_compressed: cut a real file in its compressed block.
  std::string real = test::readAll(test::sharedData("pcd/room_scan1.pcd"));
  m = err("e.pcd", real.substr(0, real.size() / 2));
  EXPECT_NE(m.find("e.pcd: truncated data: the compressed block has"), std::string::npos) << m;
}
