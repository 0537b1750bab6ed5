// Point formats 0-10, from the files tools/make_formats.py writes into tests/unit/las/data
// (its docstring lists the values checked here), plus the colour and extra-bytes rules on
// files patched byte by byte.
#include <gtest/gtest.h>

#include <string>

#include "io/las/las_reader.hpp"
#include "io/las/las_writer.hpp"
#include "las_test_util.hpp"
#include "support/test_support.hpp"

#ifndef PLUMB_LAS_TEST_DATA_DIR
#error "PLUMB_LAS_TEST_DATA_DIR must be defined"
#endif

namespace plumb {
namespace {

using test::las::peek;
using test::las::poke;

std::string meta(const Dataset& d, const std::string& key) {
  for (const auto& [k, v] : d.metadata)
    if (k == key) return v;
  return {};
}

class LasFormat : public ::testing::TestWithParam<int> {};

TEST_P(LasFormat, DecodesEveryField) {
  const int f = GetParam();
  const auto path = std::filesystem::path(PLUMB_LAS_TEST_DATA_DIR) / ("format_" + std::to_string(f) + ".las");
  const Dataset d = readLas(path);
  EXPECT_EQ(meta(d, "point format"), std::to_string(f));
  const char* version = f == 0 ? "1.0" : f == 1 ? "1.1" : f <= 3 ? "1.2" : f <= 5 ? "1.3" : "1.4";
  EXPECT_EQ(meta(d, "LAS version"), version);
  const PointCloud& c = d.scans[0].cloud;
  ASSERT_EQ(c.size(), 3u);
  const bool gps = f != 0 && f != 2, rgb = f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10;
  EXPECT_EQ(c.hasTimestamps(), gps);
  EXPECT_EQ(c.hasColors(), rgb);
  EXPECT_EQ(c.findScalarField("nir") != nullptr, f == 8 || f == 10);
  EXPECT_EQ(meta(d, "waveform packets").empty(), !(f == 4 || f == 5 || f == 9 || f == 10));
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d w = c.world(i);
    EXPECT_NEAR(w.x(), 500000.001 + i, 1e-6);
    EXPECT_NEAR(w.y(), 5999999.998 - 2 * i, 1e-6);
    EXPECT_NEAR(w.z(), 100.003 + 0.003 * i, 1e-6);
    EXPECT_EQ(c.intensity[i], 100 + i);
    EXPECT_EQ(c.return_index[i], i + 1);
    EXPECT_EQ(c.return_count[i], 3);
    EXPECT_EQ(c.classification[i], (f >= 6 ? 40 : 2) + i);
    ASSERT_EQ(c.user_data.size(), 3u);
    EXPECT_EQ(c.user_data[i], 7);
    ASSERT_EQ(c.point_source_id.size(), 3u);
    EXPECT_EQ(c.point_source_id[i], 300 + i);
    // Scan angle rank -5 deg (formats 0-5) or -500 x 0.006 = -3 deg (6-10).
    ASSERT_EQ(c.scan_angle.size(), 3u);
    EXPECT_NEAR(c.scan_angle[i], f >= 6 ? -3.0f : -5.0f, 1e-4);
    EXPECT_TRUE(c.classification_flags.empty());  // all 0: no column
    if (gps) {
      EXPECT_EQ(c.timestamps[i], 1000.5 + i);
    }
    if (rgb) {
      EXPECT_EQ(c.colors[i], (Rgb8{static_cast<std::uint8_t>(10 + i), 20, 30}));
    }
    if (f == 8 || f == 10) {
      EXPECT_EQ(c.findScalarField("nir")->values[i], 777);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFormats, LasFormat, ::testing::Range(0, 11));

TEST(LasColours, SixteenBitDetectedLateStillConvertsEveryPoint) {
  // 70000 points (> one 32768-record chunk) all with RGB <= 255 except the last one: the
  // file is 16-bit, so every earlier value (high byte 0) must become 0.
  PointCloud c;
  for (int i = 0; i < 70000; ++i) {
    c.positions.emplace_back(static_cast<float>(i % 100), 0.0f, 0.0f);
    c.colors.push_back({0, 0, 0});
  }
  const auto dir = test::scratchDir("las_colour_switch");
  LasWriteOptions o;
  o.version_minor = 2;  // format 2: RGB at 20
  writeLas(dir / "c.las", Dataset::fromCloud(c), o);
  std::string s = test::readAll(dir / "c.las");
  std::vector<std::uint8_t> b(s.begin(), s.end());
  const std::uint32_t start = peek<std::uint32_t>(b, 96);
  for (int i = 0; i < 70000; ++i) poke<std::uint16_t>(b, start + 26 * i + 20, 200);  // 8-bit look
  const Dataset eight = readLasBuffer(b, "eight.las");
  EXPECT_EQ(eight.scans[0].cloud.colors[69999][0], 200);
  EXPECT_EQ(eight.scans[0].cloud.colors[0][0], 200);
  poke<std::uint16_t>(b, start + 26 * 69999 + 20, 0x1234);  // one true 16-bit value, last
  const Dataset sixteen = readLasBuffer(b, "sixteen.las");
  EXPECT_EQ(sixteen.scans[0].cloud.colors[69999][0], 0x12);
  EXPECT_EQ(sixteen.scans[0].cloud.colors[0][0], 0);
  EXPECT_EQ(sixteen.scans[0].cloud.colors[40000][0], 0);  // in the same chunk as the switch
  EXPECT_EQ(meta(sixteen, "RGB"), "16-bit (high byte kept)");
}

TEST(LasExtraBytes, UndescribedExtraBytesAreIgnoredWithAWarning) {
  PointCloud c;
  c.positions = {{1, 2, 3}, {4, 5, 6}};
  c.scalar_fields.push_back({"deviation", {0.5f, -0.25f}});
  const auto dir = test::scratchDir("las_extra_undescribed");
  writeLas(dir / "e.las", Dataset::fromCloud(c));
  std::string s = test::readAll(dir / "e.las");
  std::vector<std::uint8_t> b(s.begin(), s.end());
  const Dataset described = readLasBuffer(b, "e.las");
  ASSERT_NE(described.scans[0].cloud.findScalarField("deviation"), nullptr);
  EXPECT_EQ(described.scans[0].cloud.findScalarField("deviation")->values[1], -0.25f);
  // Rename the Extra Bytes VLR (the only VLR, at 375: user id at 377): now undescribed.
  std::memcpy(b.data() + 377, "NotLASF_Spec", 12);
  const Dataset bare = readLasBuffer(b, "e.las");
  EXPECT_TRUE(bare.scans[0].cloud.scalar_fields.empty());
  bool warned = false;
  for (const auto& [k, v] : bare.metadata)
    warned |= k == "warning" && v == "4 extra bytes per point without an Extra Bytes VLR; ignored";
  EXPECT_TRUE(warned);
}

TEST(LasEmpty, ZeroPointFileReadsAndWrites) {
  const auto dir = test::scratchDir("las_empty");
  writeLas(dir / "z.las", Dataset::fromCloud(PointCloud{}));
  const Dataset d = readLas(dir / "z.las");
  EXPECT_EQ(d.pointCount(), 0u);
  EXPECT_EQ(meta(d, "point count"), "0");
}

}  // namespace
}  // namespace plumb
