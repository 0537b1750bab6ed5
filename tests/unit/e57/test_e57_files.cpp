// Every readable file of shared/data/e57 read with the right scans, counts, bounds and fields.
// Expected values were obtained with tools/e57_inspect.py (independent pure-Python parser:
// page CRCs, header, XML, bit-pack decoding; "valid" = invalid state 0; bounds of those points
// in the scan frame, spherical converted), run as:
//   python3 tests/unit/e57/tools/e57_inspect.py ../shared/data/e57/*.e57
// and cross-checked with shared/data/README.md (point counts, scan names).
#include <gtest/gtest.h>

#include <cmath>

#include "e57_test_helpers.hpp"
#include "io/e57/e57_reader.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using plumb::test::expectScan;
using plumb::test::sharedData;
using V = Eigen::Vector3d;

namespace {
Dataset read(const std::string& name, bool keep_direction_only = false) {
  E57ReadOptions o;
  o.keep_direction_only = keep_direction_only;
  return readE57(sharedData("e57/" + name), o);
}
std::string meta(const Dataset& d, const std::string& key) {
  for (const auto& [k, v] : d.metadata)
    if (k == key) return v;
  return "<missing " + key + ">";
}
const std::vector<std::string> kIrgb{"intensity", "red", "green", "blue"};
const V kA4Min(-44.952202, -1.349300, -0.607700), kA4Max(-44.300098, -0.886000, 0.369400);
const V kB2Min(-42.642300, 1.872600, 0.510100), kB2Max(-42.639500, 2.057800, 0.666700);
const V kBunnyMin(-0.094689, 0.040011, -0.061873), kBunnyMax(0.061009, 0.187321, 0.058799);
}  // namespace

TEST(E57Files, A4) {
  const Dataset d = read("A4.e57");
  EXPECT_EQ(d.format, "e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].name, "A4 - Cloud");
  EXPECT_FALSE(d.scans[0].has_pose);
  expectScan(d.scans[0], 4, kA4Min, kA4Max, kIrgb);
}

TEST(E57Files, A4Moved) {
  const Dataset d = read("A4_moved.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 4, V(-44.119438, 0.705303, -0.607700), V(-43.467335, 1.168603, 0.369400), kIrgb);
}

TEST(E57Files, ABTwoScans) {
  const Dataset d = read("A_B.e57");
  ASSERT_EQ(d.scans.size(), 2u);
  EXPECT_EQ(d.scans[0].name, "B2 - Cloud");
  EXPECT_EQ(d.scans[1].name, "A4 - Cloud");
  EXPECT_EQ(d.scans[0].guid, "{d3d0f9b8-6722-4ee4-9ee9-46a7a81f732c}");
  expectScan(d.scans[0], 2, kB2Min, kB2Max, kIrgb);
  expectScan(d.scans[1], 4, kA4Min, kA4Max, kIrgb);
  // Python: scan 1 intensity range [0, 257.8960266113281], scan 0 colorRed 255.
  const auto& in = d.scans[1].cloud.intensity;
  EXPECT_NEAR(*std::max_element(in.begin(), in.end()), 257.8960266, 1e-4);
  EXPECT_EQ(d.scans[0].cloud.colors[0][0], 255);
  EXPECT_EQ(d.pointCount(), 6u);
}

TEST(E57Files, ABDifferentDims) {
  const Dataset d = read("A_B_different_dims.e57");
  ASSERT_EQ(d.scans.size(), 2u);
  EXPECT_EQ(d.scans[0].name, "no-color");
  expectScan(d.scans[0], 1, V(84.174026, 537.270325, 4.628726), V(84.174026, 537.270325, 4.628726), {"intensity"}, 1e-5);
  EXPECT_NEAR(d.scans[0].cloud.intensity[0], 0.7596482634544373, 1e-6);
  expectScan(d.scans[1], 1, V(83.197845, 538.468445, 4.590276), V(83.197845, 538.468445, 4.590276),
             {"red", "green", "blue"}, 1e-5);
  EXPECT_EQ(d.scans[1].cloud.colors[0][0], 74);
}

TEST(E57Files, AMergedB) {
  const Dataset d = read("A_merged_B.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 6, V(-44.952202, -1.349300, -0.607700), V(-42.639500, 2.057800, 0.666700), kIrgb);
}

TEST(E57Files, AMovedB) {
  const Dataset d = read("A_moved_B.e57");
  ASSERT_EQ(d.scans.size(), 2u);
  expectScan(d.scans[0], 2, kB2Min, kB2Max, kIrgb);
  expectScan(d.scans[1], 4, V(-44.119438, 0.705303, -0.607700), V(-43.467335, 1.168603, 0.369400), kIrgb);
}

TEST(E57Files, B2) {
  const Dataset d = read("B2.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 2, kB2Min, kB2Max, kIrgb);
}

// One cloud (the Stanford bunny, 30,571 points) in five encodings; ScaledInteger ones are
// quantised, hence the 1e-6 m bound tolerance.
struct BunnyEncoding {
  const char* file;
  double tolerance;
};
class E57Bunny : public ::testing::TestWithParam<BunnyEncoding> {};

TEST_P(E57Bunny, ReadsTheWholeCloud) {
  const Dataset d = read(GetParam().file);
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].name, "bunny");
  expectScan(d.scans[0], 30571, kBunnyMin, kBunnyMax, {}, GetParam().tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Encodings, E57Bunny,
    ::testing::Values(BunnyEncoding{"bunnyFloat.e57", 2e-6}, BunnyEncoding{"bunnyInt19.e57", 1e-6},
                      BunnyEncoding{"bunnyInt21.e57", 1e-6}, BunnyEncoding{"bunnyInt24.e57", 1e-6},
                      BunnyEncoding{"libe57format_reference_bunnyDouble.e57", 2e-6},
                      BunnyEncoding{"libe57format_reference_bunnyInt32.e57", 1e-6}));

TEST(E57Files, BunnyEncodingsDecodeToTheSamePoints) {
  // Independent of the Python values: five encodings of one cloud agree point by point
  // within their quantisation (21-bit ScaledInteger is the coarsest here, < 1e-6 m).
  const Dataset ref = read("libe57format_reference_bunnyDouble.e57");
  for (const char* name : {"bunnyFloat.e57", "bunnyInt19.e57", "bunnyInt21.e57", "bunnyInt24.e57",
                           "libe57format_reference_bunnyInt32.e57"}) {
    const Dataset d = read(name);
    ASSERT_EQ(d.pointCount(), ref.pointCount()) << name;
    double worst = 0;
    for (std::size_t i = 0; i < ref.pointCount(); ++i)
      worst = std::max(worst, (d.scans[0].cloud.world(i) - ref.scans[0].cloud.world(i)).norm());
    EXPECT_LT(worst, 2e-6) << name;
  }
}

TEST(E57Files, CartesianInvalidStateSingle) {
  // States 0, 1, 2 stored as Float (Python: valid=1 of 3, the kept point is (-1,-2,-3)).
  const Dataset d = read("cartesian_invalid_state_single.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 1, V(-1, -2, -3), V(-1, -2, -3), {});
  const Dataset k = read("cartesian_invalid_state_single.e57", true);
  expectScan(k.scans[0], 2, V(-4, -5, -6), V(-1, -2, -3), {"direction_only"});
  EXPECT_EQ(k.scans[0].cloud.findScalarField("direction_only")->values, (Column<float>{0, 1}));
}

TEST(E57Files, EmptyNoData3D) {
  const Dataset d = read("empty.e57");
  EXPECT_TRUE(d.scans.empty());
  EXPECT_EQ(meta(d, "scans"), "0");
}

TEST(E57Files, EmptyPointCloud) {
  const Dataset d = read("empty_pc.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].cloud.size(), 0u);
}

TEST(E57Files, FloatIntensityWithoutLimits) {
  const Dataset d = read("float_intensity_without_min_max.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 1, V(1, 1, 1), V(1, 1, 1), {"intensity"});
  EXPECT_EQ(d.scans[0].cloud.intensity[0], 1.0f);
}

TEST(E57Files, IntegerIntensity) {
  const Dataset d = read("integer_intensity.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 2, V(1.1, 2.2, 3.3), V(4.4, 5.5, 6.6), {"intensity"}, 1e-6);
  const auto& in = d.scans[0].cloud.intensity;
  EXPECT_EQ(*std::min_element(in.begin(), in.end()), -66.0f);
  EXPECT_EQ(*std::max_element(in.begin(), in.end()), 66.0f);
}

TEST(E57Files, ScaledIntegerIntensity) {
  const Dataset d = read("scaled_integer_intensity.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 2, V(1.1, 2.2, 3.3), V(4.4, 5.5, 6.6), {"intensity"}, 1e-6);
  const auto& in = d.scans[0].cloud.intensity;
  EXPECT_NEAR(*std::min_element(in.begin(), in.end()), -66.6, 1e-5);
  EXPECT_NEAR(*std::max_element(in.begin(), in.end()), 66.6, 1e-5);
}

TEST(E57Files, Las2e57NoImagesTag) {
  const Dataset d = read("las2e57_no_images_tag.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  const Scan& s = d.scans[0];
  expectScan(s, 153, V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5),
             {"red", "green", "blue", "return_index", "return_count", "point_source_id"}, 1e-9);
  // 16-bit colours (max 65280 = 255 << 8) scale to 8 bits by their top byte.
  std::uint8_t max_red = 0;
  for (const auto& c : s.cloud.colors) max_red = std::max(max_red, c[0]);
  EXPECT_EQ(max_red, 255);
  EXPECT_EQ(s.cloud.return_index[0], 2);  // stored 1 (0-based in E57) -> 2
  // las2e57's "las:pointSourceId" is the LAS point source ID (1 for every point: e57_inspect.py).
  ASSERT_EQ(s.cloud.point_source_id.size(), 153u);
  for (auto id : s.cloud.point_source_id) EXPECT_EQ(id, 1);
}

TEST(E57Files, ColourRepresentation) {
  const Dataset d = read("libe57format_3rdParty_las2e57_ColourRepresentation.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 153, V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5),
             {"red", "green", "blue", "return_index", "return_count", "point_source_id"}, 1e-9);
}

TEST(E57Files, ColouredCubeDouble) {
  const Dataset d = read("libe57format_self_ColouredCubeDouble.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 7680, V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5), {"red", "green", "blue"});
}

TEST(E57Files, ColouredCubeFloat) {
  // libE57Format layout: 3 data packets then an index packet (docs/E57_FORMAT.md §8).
  const Dataset d = read("libe57format_self_ColouredCubeFloat.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 7680, V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5), {"red", "green", "blue"});
}

TEST(E57Files, PinholeImagesOnly) {
  const Dataset d = read("libe57format_self_PinholeImageWithDistortionParameters.e57");
  EXPECT_TRUE(d.scans.empty());
  EXPECT_EQ(meta(d, "images2D (skipped)"), "3");
}

TEST(E57Files, ZeroPoints) {
  const Dataset d = read("libe57format_self_ZeroPoints.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].cloud.size(), 0u);
}

TEST(E57Files, LibE57FormatEmpty) {
  const Dataset d = read("libe57format_self_empty.e57");
  EXPECT_TRUE(d.scans.empty());
}

TEST(E57Files, ClassificationWithoutNamespace) {
  const Dataset d = read("no_ext_namespace.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 1, V(1, 2, 3), V(1, 2, 3), {"classification"});
}

TEST(E57Files, OriginalGuids) {
  const Dataset d = read("original_guids.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].guid, "{9DD0BCF6-69A8-476D-2A3C-3E05A05DC421}");
  EXPECT_EQ(d.scans[0].original_guids, (std::vector<std::string>{"guid1", "guid2", "guid3"}));
  expectScan(d.scans[0], 1, V(1, 2, 3), V(1, 2, 3), {});
}

TEST(E57Files, SphericalGridReadError) {
  // Spherical + row/column + sphericalInvalidState; every value in the file is 0 (Python).
  const Dataset d = read("read_error.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  const Scan& s = d.scans[0];
  expectScan(s, 2651, V(0, 0, 0), V(0, 0, 0), {"intensity", "red", "green", "blue", "row", "column"});
  EXPECT_EQ(s.cloud.grid_rows, 1);  // all row/column indices are 0
  EXPECT_EQ(s.cloud.grid_columns, 1);
}

TEST(E57Files, NormalsExtension) {
  const Dataset d = read("testWithNormals.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].name, "dummyWithNormals - Cloud");
  expectScan(d.scans[0], 2, V(1, 0, 0), V(2, 0, 0), {"nx", "ny", "nz"});
  for (const auto& n : d.scans[0].cloud.normals) EXPECT_TRUE(n.allFinite());
}

TEST(E57Files, TinyCartesianFloatRgb) {
  const Dataset d = read("tinyCartesianFloatRgb.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].name, "exp2.fls.subsampled");
  expectScan(d.scans[0], 2090, V(-9.779530, 4.513879, 295.524689), V(-6.774238, 7.515460, 298.532166),
             {"red", "green", "blue"}, 2e-6);
  // Offset = rounded bounding-box centre of the first block: positions stay small.
  EXPECT_NEAR(d.scans[0].cloud.offset.z(), 297.0, 0.6);
}

TEST(E57Files, TinyPcAndImages) {
  const Dataset d = read("tiny_pc_and_images.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(meta(d, "images2D (skipped)"), "4");
  expectScan(d.scans[0], 2, V(0, 0, 0), V(1, 1, 1), {});
}

TEST(E57Files, TinyPcWithExtension) {
  const Dataset d = read("tiny_pc_with_extension.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 1, V(1, 2, 3), V(1, 2, 3), {"nx", "ny", "nz"});
}

TEST(E57Files, TinySpherical) {
  // 360 points, every second one direction-only (Python: valid=180 of 360).
  const Dataset d = read("tiny_spherical.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  expectScan(d.scans[0], 180, V(0.000001, -0.499999, 0.0), V(1.0, 0.5, 1.0), {}, 2e-6);
  for (std::size_t i = 0; i < d.scans[0].cloud.size(); ++i)
    EXPECT_NEAR(d.scans[0].cloud.world(i).norm(), 1.0, 1e-5);  // range 1 everywhere
  const Dataset k = read("tiny_spherical.e57", true);
  EXPECT_EQ(k.scans[0].cloud.size(), 360u);
}

TEST(E57Files, TranslationWithoutRotation) {
  const Dataset d = read("translationWithoutRotation.e57");
  ASSERT_EQ(d.scans.size(), 1u);
  const Scan& s = d.scans[0];
  EXPECT_EQ(s.name, "Scan 0");
  EXPECT_TRUE(s.has_pose);
  EXPECT_TRUE(s.pose.rotation().isIdentity(1e-12));
  EXPECT_TRUE(s.pose.translation().isApprox(V(4, 5, 6)));
  expectScan(s, 4, V(0, 0, 0), V(1, 1, 0), {});
  const Bounds b = d.bounds();  // dataset frame = pose applied (matches its cartesianBounds)
  EXPECT_TRUE(b.min.isApprox(V(4, 5, 6)));
  EXPECT_TRUE(b.max.isApprox(V(5, 6, 6)));
}
