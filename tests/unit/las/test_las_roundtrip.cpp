// LAS write -> read round trips (1.2 format 3/2, 1.4 format 7): every point preserved to the
// scale, every attribute exactly.
#include <gtest/gtest.h>

#include <random>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"
#include "io/las/las_writer.hpp"
#include "las_test_util.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

using test::las::peek;

std::string meta(const Dataset& d, const std::string& key) {
  for (const auto& [k, v] : d.metadata)
    if (k == key) return v;
  return {};
}

// Each listed column of `b` equals that of `a`.
template <class... Column>
void expectSameColumns(const PointCloud& a, const PointCloud& b, Column... column) {
  auto same = [&](auto member) { EXPECT_EQ(a.*member, b.*member); };
  (same(column), ...);
}

// Every point and attribute (LAS fields included) of `b` equals `a`: positions within half
// the scale plus float rounding of local coordinates (a few 1e-5 m for clouds spanning 1 km).
void expectSamePoints(const PointCloud& a, const PointCloud& b, double scale) {
  ASSERT_EQ(a.size(), b.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    worst = std::max(worst, (a.world(i) - b.world(i)).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, scale / 2 + 1e-4);
  using P = PointCloud;
  expectSameColumns(a, b, &P::intensity, &P::return_index, &P::return_count, &P::classification,
                    &P::timestamps, &P::colors, &P::scan_angle, &P::user_data, &P::point_source_id,
                    &P::classification_flags, &P::scanner_channel, &P::scan_flags);
}

TEST(LasRoundTrip, Las12Format3PreservesEveryPoint) {
  const Dataset in = readLas(test::sharedData("las/autzen_trim.las"));
  const auto dir = test::scratchDir("las_roundtrip_12");
  LasWriteOptions o;
  o.version_minor = 2;
  writeLas(dir / "out.las", in, o);
  const Dataset back = readLas(dir / "out.las");
  EXPECT_EQ(meta(back, "LAS version"), "1.2");
  EXPECT_EQ(meta(back, "point format"), "3");
  EXPECT_EQ(back.coordinate_system, in.coordinate_system);  // WKT VLR written
  expectSamePoints(in.scans[0].cloud, back.scans[0].cloud, 1e-4);
}

TEST(LasRoundTrip, Las14Format7PreservesEveryPointAndLasField) {
  const Dataset in = readLas(test::sharedData("las/autzen_trim_7.las"));
  const auto dir = test::scratchDir("las_roundtrip_14");
  writeLas(dir / "out.las", in);
  const Dataset back = readLas(dir / "out.las");
  EXPECT_EQ(meta(back, "LAS version"), "1.4");
  EXPECT_EQ(meta(back, "point format"), "7");
  EXPECT_EQ(meta(back, "point record length"), "36 bytes (0 extra)");
  expectSamePoints(in.scans[0].cloud, back.scans[0].cloud, 1e-4);  // LAS fields included
  EXPECT_FALSE(back.scans[0].cloud.point_source_id.empty());
  EXPECT_EQ(back.coordinate_system, in.coordinate_system);
}

TEST(LasRoundTrip, HeaderCountsAndBoundsAreFilled) {
  const Dataset in = readLas(test::sharedData("las/1.2-with-color.las"));
  const auto dir = test::scratchDir("las_roundtrip_header");
  writeLas(dir / "a14.las", in);
  LasWriteOptions o12;
  o12.version_minor = 2;
  writeLas(dir / "a12.las", in, o12);
  const std::string s14 = test::readAll(dir / "a14.las"), s12 = test::readAll(dir / "a12.las");
  const std::vector<std::uint8_t> h14(s14.begin(), s14.end()), h12(s12.begin(), s12.end());
  // 1.4 format 7: legacy count 0, 64-bit count 1065 at 247, by-return 925/114/21/5 (script).
  EXPECT_EQ(peek<std::uint32_t>(h14, 107), 0u);
  EXPECT_EQ(peek<std::uint64_t>(h14, 247), 1065u);
  EXPECT_EQ(peek<std::uint64_t>(h14, 255), 925u);
  EXPECT_EQ(peek<std::uint64_t>(h14, 263), 114u);
  EXPECT_EQ(peek<std::uint16_t>(h14, 94), 375u);
  EXPECT_TRUE(peek<std::uint16_t>(h14, 6) & 0x10);  // WKT bit, required for format 7
  EXPECT_EQ(h12[25], 2);
  EXPECT_EQ(h12[104], 3);
  EXPECT_EQ(peek<std::uint32_t>(h12, 107), 1065u);
  EXPECT_EQ(peek<std::uint32_t>(h12, 111), 925u);
  // Bounds: max X at 179, min X at 187 (script: 638982.55 / 635619.85).
  EXPECT_NEAR(peek<double>(h12, 179), 638982.55, 1e-4);
  EXPECT_NEAR(peek<double>(h12, 187), 635619.85, 1e-4);
  EXPECT_DOUBLE_EQ(peek<double>(h12, 131), 1e-4);
  // File size = offset to points + count * record length.
  EXPECT_EQ(h12.size(), peek<std::uint32_t>(h12, 96) + 1065u * 34u);
}

TEST(LasRoundTrip, ExtraBytesAndScalarFieldsSurvive) {
  const Dataset in = readLas(test::sharedData("las/extrabytes.las"));
  const auto dir = test::scratchDir("las_roundtrip_extra");
  writeLas(dir / "out.las", in);
  const Dataset back = readLas(dir / "out.las");
  const PointCloud& a = in.scans[0].cloud;
  const PointCloud& b = back.scans[0].cloud;
  ASSERT_EQ(b.scalar_fields.size(), a.scalar_fields.size());
  for (const auto& f : a.scalar_fields) {
    const ScalarField* g = b.findScalarField(f.name);
    ASSERT_NE(g, nullptr) << f.name;
    EXPECT_EQ(f.values, g->values) << f.name;
  }
  EXPECT_EQ(meta(back, "point record length"), "64 bytes (28 extra)");  // 36 + 7 floats
}

TEST(LasRoundTrip, GeoreferencedSyntheticCloudKeepsTenthOfMillimetre) {
  // Lambert-93-like coordinates (x 6.5e5, y 6.86e6): values must survive to 0.1 mm.
  PointCloud c;
  c.offset = Eigen::Vector3d(652000.0, 6862000.0, 35.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-500.0f, 500.0f);
  for (int i = 0; i < 5000; ++i) {
    c.positions.emplace_back(u(rng), u(rng), u(rng) / 50);
    c.intensity.push_back(static_cast<float>(i % 65536));
    c.colors.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i * 7), 255});
    c.timestamps.push_back(1e9 + i * 1e-6);
  }
  Dataset d = Dataset::fromCloud(c);
  d.coordinate_system = "EPSG:2154";
  const auto dir = test::scratchDir("las_roundtrip_geo");
  for (int minor : {2, 4}) {
    LasWriteOptions o;
    o.version_minor = minor;
    const auto path = dir / ("geo1" + std::to_string(minor) + ".las");
    writeLas(path, d, o);
    const Dataset back = readLas(path);
    const PointCloud& b = back.scans[0].cloud;
    ASSERT_EQ(b.size(), c.size());
    for (std::size_t i = 0; i < c.size(); ++i)
      ASSERT_LE((b.world(i) - c.world(i)).cwiseAbs().maxCoeff(), 1e-4) << i;
    EXPECT_EQ(b.colors, c.colors);
    EXPECT_EQ(b.intensity, c.intensity);
    EXPECT_EQ(b.timestamps, c.timestamps);
    // EPSG codes go to GeoTIFF keys in 1.2; format 7 allows WKT only: the code's WKT.
    if (minor == 2) {
      EXPECT_EQ(back.coordinate_system, "EPSG:2154");
    } else {
      EXPECT_NE(back.coordinate_system.find("Lambert-93"), std::string::npos)
          << back.coordinate_system;
      EXPECT_NE(back.coordinate_system.find("AUTHORITY[\"EPSG\",\"2154\"]"), std::string::npos);
    }
  }
}

TEST(LasRoundTrip, CoordinateSystemsAreWrittenOrTheReportSaysWhyNot) {
  PointCloud c;
  c.positions = {{1, 2, 3}, {4, 5, 6}};
  const auto dir = test::scratchDir("las_roundtrip_crs");
  struct Case {
    std::string crs;
    int minor;
    std::string read_back_contains;  ///< "" when nothing may be written
  };
  const Case cases[] = {
      {"EPSG:4326", 2, "EPSG:4326"},          // geographic: GeographicTypeGeoKey
      {"EPSG:4326", 4, "GEOGCS[\"WGS 84\""},   // 1.4: WKT from PROJ
      {"EPSG:32631", 4, "UTM zone 31N"},
      {"EPSG:999999", 4, ""},                 // no such code
      {"EPSG:2154abc", 2, ""},                // not a code
      {"Lambert 93, NGF heights", 4, ""},     // free text is not WKT
  };
  for (const Case& k : cases) {
    Dataset d = Dataset::fromCloud(c);
    d.coordinate_system = k.crs;
    LasWriteOptions o;
    o.version_minor = k.minor;
    WriteReport report;
    o.report = &report;
    const auto path = dir / "crs.las";
    writeLas(path, d, o);
    const Dataset back = readLas(path);
    ASSERT_EQ(back.scans[0].cloud.size(), 2u) << k.crs;
    bool noted = false;
    for (const auto& n : report.notes) noted |= n.find("was not written") != std::string::npos;
    if (k.read_back_contains.empty()) {
      EXPECT_EQ(back.coordinate_system, "") << k.crs;
      EXPECT_TRUE(noted) << k.crs << ": a dropped coordinate system must be reported";
    } else {
      EXPECT_NE(back.coordinate_system.find(k.read_back_contains), std::string::npos)
          << k.crs << " 1." << k.minor << " read back as " << back.coordinate_system;
      EXPECT_FALSE(noted) << k.crs;
    }
  }
}

TEST(LasRoundTrip, MultiScanDatasetIsMergedInTheDatasetFrame) {
  Dataset d;
  for (int k = 0; k < 2; ++k) {
    Scan s;
    s.cloud.positions = {{1, 2, 3}, {4, 5, 6}};
    s.pose = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(100.0 * k, 0, 0));
    s.has_pose = true;
    d.scans.push_back(s);
  }
  const auto dir = test::scratchDir("las_roundtrip_merge");
  writeLas(dir / "m.las", d);
  const PointCloud b = readLas(dir / "m.las").scans[0].cloud;
  ASSERT_EQ(b.size(), 4u);
  EXPECT_NEAR(b.world(3).x(), 104.0, 1e-4);
  EXPECT_NEAR(b.world(0).x(), 1.0, 1e-4);
}

TEST(LasRoundTrip, CoarserScaleQuantisesAndIsRecorded) {
  PointCloud c;
  c.positions = {{0.12345f, 1.0f, 2.0f}, {3.0f, 4.0f, 5.0f}};
  const auto dir = test::scratchDir("las_roundtrip_scale");
  LasWriteOptions o;
  o.scale = 0.01;
  writeLas(dir / "s.las", Dataset::fromCloud(c), o);
  const Dataset back = readLas(dir / "s.las");
  EXPECT_EQ(meta(back, "scale"), "0.01 0.01 0.01");
  EXPECT_NEAR(back.scans[0].cloud.world(0).x(), 0.12, 1e-6);
}

TEST(LasRoundTrip, FailedWriteLeavesTheExistingFileIntact) {
  const auto dir = test::scratchDir("las_roundtrip_atomic");
  PointCloud small;
  small.positions = {{0, 0, 0}};
  writeLas(dir / "keep.las", Dataset::fromCloud(small));
  const std::string before = test::readAll(dir / "keep.las");
  PointCloud huge;  // 1000 km apart: does not fit int32 at 0.1 mm
  huge.positions = {{0, 0, 0}, {1e6f, 0, 0}};
  EXPECT_THROW(writeLas(dir / "keep.las", Dataset::fromCloud(huge)), FileError);
  EXPECT_EQ(test::readAll(dir / "keep.las"), before);
  // Cancelled half-way through the records (the temporary file is open by then).
  Progress cancelled;
  cancelled.cancel();
  const Dataset big = readLas(test::sharedData("las/autzen_trim.las"));
  EXPECT_THROW(writeLas(dir / "keep.las", big, {}, &cancelled), Canceled);
  EXPECT_EQ(test::readAll(dir / "keep.las"), before);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u) << "no temporary file may be left behind";
  EXPECT_THROW(writeLas(dir / "no" / "such" / "dir.las", Dataset::fromCloud(small)), FileError);
}

}  // namespace
}  // namespace plumb
