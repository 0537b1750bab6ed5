// The "distance" scalar field (issue 17: signed distances exported with the registered data)
// through the PLY, E57 and LAS writers: read back by Plumb and checked by the independent
// Python tools (e57_inspect.py: the E57 prototype and decoded values; las_fields.py extra: the
// Extra Bytes VLR and the raw record bytes) and, for PLY, the header's vertex property.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "io/io.hpp"
#include "quality/cloud_distance.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const std::vector<std::vector<float>> kDistances = {{0.005f, -0.005f, 0.0123f, kNaN},
                                                    {-0.0421f, 0.001f, 0.09f}};

/// Two scans (4 and 3 points, the second with a pose) carrying the distances above.
Dataset measured() {
  Dataset d;
  d.scans.resize(2);
  for (std::size_t s = 0; s < 2; ++s)
    for (std::size_t i = 0; i < kDistances[s].size(); ++i)
      d.scans[s].cloud.positions.emplace_back(float(i), float(s), 1.5f);
  d.scans[1].pose = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2, 0, 0));
  d.scans[1].has_pose = true;
  attachDistanceField(d, kDistances);
  return d;
}

std::vector<float> allDistances() {
  std::vector<float> out(kDistances[0]);
  out.insert(out.end(), kDistances[1].begin(), kDistances[1].end());
  return out;
}

void expectSameValue(float got, float expected, std::size_t i) {
  if (std::isnan(expected)) EXPECT_TRUE(std::isnan(got)) << "point " << i;
  else EXPECT_EQ(got, expected) << "point " << i;
}

/// The "distance" values of every scan of `file`, read back by Plumb, scans concatenated.
std::vector<float> readBack(const std::filesystem::path& file, std::size_t scans) {
  const Dataset d = readDataset(file);
  EXPECT_EQ(d.scans.size(), scans);
  std::vector<float> out;
  for (const auto& scan : d.scans) {
    const ScalarField* f = scan.cloud.findScalarField("distance");
    EXPECT_NE(f, nullptr) << file;
    if (f) out.insert(out.end(), f->values.begin(), f->values.end());
  }
  return out;
}

std::string run(const std::string& command, const std::filesystem::path& out) {
  EXPECT_EQ(std::system((command + " > '" + out.string() + "'").c_str()), 0) << command;
  return test::readAll(out);
}

}  // namespace

TEST(DistanceField, PlyVertexProperty) {
  const auto file = test::scratchDir("distance_field") / "d.ply";
  writeDataset(file, measured());
  const std::string text = test::readAll(file);
  const std::string header = text.substr(0, text.find("end_header"));
  EXPECT_NE(header.find("property float distance\n"), std::string::npos) << header;
  const std::vector<float> got = readBack(file, 1), expected = allDistances();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) expectSameValue(got[i], expected[i], i);
}

TEST(DistanceField, E57PrototypeField) {
  const auto dir = test::scratchDir("distance_field");
  writeDataset(dir / "d.e57", measured());
  const std::vector<float> got = readBack(dir / "d.e57", 2), expected = allDistances();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) expectSameValue(got[i], expected[i], i);
  // The independent parser: float32 "plumb:distance" in each prototype, and the decoded values
  // of the second scan (no NaN) span exactly its smallest and largest distance.
  const std::string out = run("python3 " PLUMB_E57_INSPECT " '" + (dir / "d.e57").string() + "'", dir / "d.inspect");
  const std::size_t second = out.find("scan 1 ");
  ASSERT_NE(second, std::string::npos) << out;
  EXPECT_NE(out.find("plumb:distance:Float/single"), std::string::npos) << out;
  const std::size_t range = out.find("plumb:distance range [", second);
  ASSERT_NE(range, std::string::npos) << out;
  std::istringstream values(out.substr(range + 22));
  double lo = 0, hi = 0;
  char comma = 0;
  values >> lo >> comma >> hi;
  EXPECT_EQ(float(lo), -0.0421f);
  EXPECT_EQ(float(hi), 0.09f);
}

TEST(DistanceField, LasExtraBytes) {
  const auto dir = test::scratchDir("distance_field");
  writeDataset(dir / "d.las", measured());
  const std::vector<float> expected = allDistances();
  const std::vector<float> got = readBack(dir / "d.las", 1);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) expectSameValue(got[i], expected[i], i);
  // las_fields.py reads the Extra Bytes VLR (LASF_Spec 4) and the raw record bytes itself.
  const std::string out = run("python3 " PLUMB_LAS_FIELDS_PY " extra '" + (dir / "d.las").string() + "'", dir / "d.extra");
  EXPECT_NE(out.find("field distance type 9 at "), std::string::npos) << out;  // 9: float32
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::string key = "point " + std::to_string(i) + " distance=";
    const std::size_t at = out.find(key);
    ASSERT_NE(at, std::string::npos) << out;
    expectSameValue(float(std::stod(out.substr(at + key.size()))), expected[i], i);
  }
}
