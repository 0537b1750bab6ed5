// read -> write -> read keeps every point (to the stored precision), poses, names and
// attributes; each written scan is a new version (new GUID, the old one in originalGuids) in a
// new file (new file GUID); written files follow the interoperability rules of docs/E57_FORMAT.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>

#include "common/error.hpp"
#include "e57_test_helpers.hpp"
#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_writer.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using plumb::test::sharedData;

namespace {

// Compares two datasets scan by scan. `tol` bounds position differences (metres).
void expectSameData(const Dataset& a, const Dataset& b, double tol) {
  ASSERT_EQ(a.scans.size(), b.scans.size());
  for (std::size_t k = 0; k < a.scans.size(); ++k) {
    const Scan& s = a.scans[k];
    const Scan& t = b.scans[k];
    SCOPED_TRACE("scan " + std::to_string(k));
    EXPECT_EQ(s.name, t.name);
    EXPECT_NE(s.guid, t.guid) << "a written scan is a new version of the data";
    EXPECT_EQ(t.guid.size(), 38u);  // "{8-4-4-4-12}"
    EXPECT_EQ(t.original_guids, s.guid.empty() ? s.original_guids : std::vector<std::string>{s.guid});
    EXPECT_EQ(s.has_pose, t.has_pose);
    EXPECT_LT(RigidTransform::rotationErrorDeg(s.pose, t.pose), 1e-9);
    EXPECT_LT(RigidTransform::translationError(s.pose, t.pose), 1e-9);
    ASSERT_EQ(s.cloud.size(), t.cloud.size());
    EXPECT_EQ(s.cloud.fieldNames(), t.cloud.fieldNames());
    double worst = 0;
    for (std::size_t i = 0; i < s.cloud.size(); ++i) {
      if (!s.cloud.positions[i].allFinite()) {
        EXPECT_FALSE(t.cloud.positions[i].allFinite());
        continue;
      }
      worst = std::max(worst, (s.cloud.world(i) - t.cloud.world(i)).cwiseAbs().maxCoeff());
    }
    EXPECT_LE(worst, tol);
    EXPECT_EQ(s.cloud.colors, t.cloud.colors);
    EXPECT_EQ(s.cloud.intensity, t.cloud.intensity);
    EXPECT_EQ(s.cloud.row, t.cloud.row);
    EXPECT_EQ(s.cloud.column, t.cloud.column);
    EXPECT_EQ(s.cloud.grid_rows, t.cloud.grid_rows);
    EXPECT_EQ(s.cloud.grid_columns, t.cloud.grid_columns);
    EXPECT_EQ(s.cloud.return_index, t.cloud.return_index);
    EXPECT_EQ(s.cloud.return_count, t.cloud.return_count);
    EXPECT_EQ(s.cloud.timestamps, t.cloud.timestamps);
    EXPECT_EQ(s.cloud.normals, t.cloud.normals);
  }
}

Dataset roundTrip(const Dataset& d, const std::string& name, const E57WriteOptions& o = {}) {
  const auto dir = plumb::test::scratchDir("e57_roundtrip_" + name);
  writeE57(dir / (name + ".e57"), d, o);
  return readE57(dir / (name + ".e57"));
}

// Float positions read from a Float file and written as ScaledInteger move by at most half
// the quantum, plus float rounding of the local coordinates.
constexpr double kQuantumTol = 0.5e-4 + 1e-6;

std::uint64_t u64(const std::string& b, std::size_t at) {
  std::uint64_t v;
  std::memcpy(&v, b.data() + at, 8);
  return v;
}

}  // namespace

TEST(E57RoundTrip, MultiScanAB) {
  const Dataset d = readE57(sharedData("e57/A_B.e57"));
  const Dataset r = roundTrip(d, "A_B");
  expectSameData(d, r, kQuantumTol);
  ASSERT_EQ(r.scans.size(), 2u);
  EXPECT_EQ(r.scans[1].original_guids, std::vector<std::string>{"{3e80c997-fbd5-4b07-ba33-9b79f63247fa}"});
  // A new file: its GUID is not the source's (issue 17: exports kept the source file's GUID).
  const auto file_guid = [](const Dataset& x) {
    for (const auto& [k, v] : x.metadata)
      if (k == "file GUID") return v;
    return std::string();
  };
  ASSERT_FALSE(file_guid(d).empty());
  ASSERT_EQ(file_guid(r).size(), 38u);
  EXPECT_NE(file_guid(r), file_guid(d));
  EXPECT_NE(file_guid(roundTrip(d, "A_B_again")), file_guid(r)) << "every written file is a new file";
}

TEST(E57RoundTrip, ScaledIntegerBunnyIsExactAtItsOwnPrecision) {
  // bunnyInt24 stores 24-bit ScaledIntegers; writing Float positions then ScaledInteger at
  // the same 0.1 mm default quantum keeps every point within half a quantum.
  const Dataset d = readE57(sharedData("e57/bunnyInt24.e57"));
  expectSameData(d, roundTrip(d, "bunny"), kQuantumTol);
  E57WriteOptions f;
  f.float_positions = true;
  expectSameData(d, roundTrip(d, "bunny_float", f), 1e-9);
}

TEST(E57RoundTrip, SphericalGrid) {
  const Dataset d = readE57(sharedData("e57/read_error.e57"));
  expectSameData(d, roundTrip(d, "read_error"), kQuantumTol);
}

TEST(E57RoundTrip, ReturnsAndSixteenBitColours) {
  const Dataset d = readE57(sharedData("e57/las2e57_no_images_tag.e57"));
  const Dataset r = roundTrip(d, "las2e57");
  // las:pointSourceId (a custom scalar field) has no standard E57 field: not written.
  Dataset expected = d;
  expected.scans[0].cloud.scalar_fields.clear();
  expectSameData(expected, r, kQuantumTol);
}

TEST(E57RoundTrip, Normals) {
  const Dataset d = readE57(sharedData("e57/testWithNormals.e57"));
  expectSameData(d, roundTrip(d, "normals"), kQuantumTol);
}

TEST(E57RoundTrip, SyntheticGeoreferencedScansWithPoses) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-60.0, 60.0);
  Dataset d;
  d.coordinate_system = "EPSG:2154";
  for (int k = 0; k < 3; ++k) {
    Scan s;
    s.name = "station " + std::to_string(k);
    s.description = "synthetic <&> ]]> test";
    s.has_pose = true;
    s.pose = RigidTransform::fromQuaternion(
        Eigen::Quaterniond(Eigen::AngleAxisd(0.3 + k, Eigen::Vector3d(1, 2, 3).normalized())),
        Eigen::Vector3d(651234.5 + k, 6861234.25, 35.0));
    const std::size_t n = k == 2 ? 0 : 20000 + 777 * k;  // several packets; one empty scan
    s.cloud.offset = Eigen::Vector3d(651200.0, 6861200.0, 30.0);
    for (std::size_t i = 0; i < n; ++i) {
      // Points on the 0.1 mm grid so ScaledInteger storage is exact.
      Eigen::Vector3d w(651200.0 + std::round(u(rng) * 1e4) / 1e4, 6861200.0 + std::round(u(rng) * 1e4) / 1e4,
                        30.0 + std::round(u(rng) * 1e3) / 1e4);
      s.cloud.positions.push_back((w - s.cloud.offset).cast<float>());
      s.cloud.intensity.push_back(static_cast<float>(rng() % 4096));
      s.cloud.colors.push_back({static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                                static_cast<std::uint8_t>(rng())});
      s.cloud.row.push_back(static_cast<std::int32_t>(i / 200));
      s.cloud.column.push_back(static_cast<std::int32_t>(i % 200));
      s.cloud.timestamps.push_back(1.5e9 + i * 1e-5);
      s.cloud.return_index.push_back(static_cast<std::uint8_t>(1 + i % 3));
      s.cloud.return_count.push_back(3);
    }
    if (n > 0) s.cloud.positions[5] = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
    s.cloud.grid_rows = n ? static_cast<std::int32_t>((n + 199) / 200) : 0;
    s.cloud.grid_columns = n ? 200 : 0;
    d.scans.push_back(std::move(s));
  }
  const auto dir = plumb::test::scratchDir("e57_roundtrip_synthetic");
  writeE57(dir / "s.e57", d);
  const Dataset r = readE57(dir / "s.e57");
  EXPECT_EQ(r.coordinate_system, "EPSG:2154");
  EXPECT_EQ(r.scans[0].description, "synthetic <&> ]]> test");
  // The NaN point is written as cartesianInvalidState=2 and dropped on reading.
  Dataset expected = d;
  for (auto& s : expected.scans) {
    if (s.cloud.empty()) continue;
    std::vector<bool> keep(s.cloud.size(), true);
    keep[5] = false;
    const auto rows = s.cloud.grid_rows, cols = s.cloud.grid_columns;
    s.cloud.filter(keep);
    s.cloud.grid_rows = rows, s.cloud.grid_columns = cols;
    s.guid = "";
  }
  for (std::size_t k = 0; k < r.scans.size(); ++k) EXPECT_TRUE(r.scans[k].original_guids.empty());
  // Float local coordinates: the 0.1 mm grid points come back within float rounding.
  expectSameData(expected, r, 1e-5);

  // The independent Python parser (tools/e57_inspect.py: CRCs, header, XML, bit-pack
  // decoding) reads the written file with the same counts.
  const std::string report = (dir / "inspect.txt").string();
  ASSERT_EQ(std::system(("python3 " PLUMB_E57_INSPECT " " + (dir / "s.e57").string() + " > " + report).c_str()), 0);
  const std::string text = plumb::test::readAll(report);
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
  EXPECT_NE(text.find("valid=19999 (of 20000)"), std::string::npos) << text;
  EXPECT_NE(text.find("valid=20776 (of 20777)"), std::string::npos) << text;
  EXPECT_NE(text.find("recordCount=0"), std::string::npos) << text;

  // File structure (docs/E57_FORMAT.md §2, §7, §10 pitfalls 5 and 8).
  const std::string bytes = plumb::test::readAll(dir / "s.e57");
  EXPECT_EQ(bytes.size() % 1024, 0u);
  EXPECT_EQ(u64(bytes, 16), bytes.size());
  EXPECT_EQ(bytes.compare(0, 8, "ASTM-E57"), 0);
  EXPECT_EQ(u64(bytes, 48 + 24), 0u);  // first section: indexPhysicalOffset = 0
}

TEST(E57RoundTrip, CancelKeepsExistingFile) {
  const auto dir = plumb::test::scratchDir("e57_cancel");
  const Dataset d = readE57(sharedData("e57/bunnyInt21.e57"));
  writeE57(dir / "b.e57", d);
  const std::string before = plumb::test::readAll(dir / "b.e57");
  Progress p;
  p.cancel();
  EXPECT_THROW(writeE57(dir / "b.e57", d, {}, &p), Canceled);
  EXPECT_EQ(plumb::test::readAll(dir / "b.e57"), before);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // no temp left
}

TEST(E57RoundTrip, RejectsPrecisionThatOverflowsScaledIntegers) {
  const auto dir = plumb::test::scratchDir("e57_overflow");
  PointCloud c;
  c.offset = Eigen::Vector3d(6.0e9, 0, 0);
  c.positions.push_back(Eigen::Vector3f::Zero());
  E57WriteOptions o;
  o.scaled_precision = 1e-9;  // 6e9 m / 1e-9 m does not fit in int64
  EXPECT_THROW(writeE57(dir / "o.e57", Dataset::fromCloud(c), o), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "o.e57"));
  o.float_positions = true;  // Float positions have no such limit
  writeE57(dir / "o.e57", Dataset::fromCloud(c), o);
  EXPECT_EQ(readE57(dir / "o.e57").scans.at(0).cloud.world(0).x(), 6.0e9);
}
