// LAS writes that used to lose data silently (issue 12), each checked with the independent
// reader tools/las_fields.py: float intensity, invented RGB, dropped NaN points, a pose
// that overflows the scaled integers, return number 0, and every standard field of LAS -> LAS.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"
#include "io/las/las_writer.hpp"
#include "support/test_support.hpp"

#ifndef PLUMB_LAS_FIELDS_PY
#error "PLUMB_LAS_FIELDS_PY must be defined"
#endif

namespace plumb {
namespace {

/// Output of `las_fields.py dump FILE` as lines.
std::vector<std::string> dump(const std::filesystem::path& file) {
  const auto out = file.string() + ".dump";
  const std::string cmd = "python3 " PLUMB_LAS_FIELDS_PY " dump '" + file.string() + "' > '" + out + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::vector<std::string> lines;
  std::istringstream in(test::readAll(out));
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

/// The value after `key ` in a dump line.
std::string field(const std::string& line, const std::string& key) {
  const auto at = line.find(" " + key + " ");
  if (at == std::string::npos) return {};
  const auto begin = at + key.size() + 2;
  return line.substr(begin, line.find(' ', begin) - begin);
}

PointCloud line(std::size_t n) {
  PointCloud c;
  for (std::size_t i = 0; i < n; ++i) c.positions.emplace_back(static_cast<float>(i), 1.0f, 2.0f);
  return c;
}

std::vector<std::string> intensities(const std::vector<std::string>& lines) {
  std::vector<std::string> v;
  for (const auto& l : lines)
    if (l.rfind("point", 0) == 0) v.push_back(field(l, "intensity"));
  return v;
}

TEST(LasLossless, EveryStandardFieldSurvivesLasToLas) {
  const auto dir = test::scratchDir("las_lossless_fields");
  ASSERT_EQ(std::system(("python3 " PLUMB_LAS_FIELDS_PY " make '" + (dir / "in.las").string() + "'").c_str()), 0);
  writeLas(dir / "out.las", readLas(dir / "in.las"));
  const auto in = dump(dir / "in.las"), out = dump(dir / "out.las");
  ASSERT_EQ(in.size(), 8u);
  ASSERT_EQ(out.size(), in.size());
  EXPECT_EQ(out[0], "version 1.4 format 6 record 30 count 5");  // no RGB invented
  for (std::size_t k = 1; k < in.size(); ++k) EXPECT_EQ(out[k], in[k]);
}

TEST(LasLossless, FloatIntensityIsScaledFromItsRangeTo16Bits) {
  const auto dir = test::scratchDir("las_lossless_intensity");
  PointCloud c = line(4);
  c.intensity = {0.0f, 0.25f, 0.5f, 1.0f};
  WriteReport report;
  LasWriteOptions o;
  o.report = &report;
  writeLas(dir / "a.las", Dataset::fromCloud(c), o);
  EXPECT_EQ(intensities(dump(dir / "a.las")), (std::vector<std::string>{"0", "16384", "32768", "65535"}));
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("intensity scaled linearly from [0, 1]"), std::string::npos) << report.notes[0];
  // E57 intensity limits, when the reader left them, replace the data's min/max.
  Dataset d = Dataset::fromCloud(c);
  d.metadata.emplace_back("scan 0 intensity limits", "0 .. 2");
  writeLas(dir / "b.las", d, o);
  EXPECT_EQ(intensities(dump(dir / "b.las")), (std::vector<std::string>{"0", "8192", "16384", "32768"}));
  // Integers within 0..65535 are kept as they are.
  c.intensity = {0.0f, 7.0f, 300.0f, 65535.0f};
  writeLas(dir / "c.las", Dataset::fromCloud(c), o);
  EXPECT_EQ(intensities(dump(dir / "c.las")), (std::vector<std::string>{"0", "7", "300", "65535"}));
  EXPECT_TRUE(report.notes.empty());
}

TEST(LasLossless, NoColourMeansAPointFormatWithoutRgb) {
  const auto dir = test::scratchDir("las_lossless_rgb");
  PointCloud c = line(2);
  LasWriteOptions o12;
  o12.version_minor = 2;
  writeLas(dir / "a14.las", Dataset::fromCloud(c));
  writeLas(dir / "a12.las", Dataset::fromCloud(c), o12);
  EXPECT_EQ(dump(dir / "a14.las")[0], "version 1.4 format 6 record 30 count 2");
  EXPECT_EQ(dump(dir / "a12.las")[0], "version 1.2 format 0 record 20 count 2");
  c.colors = {{1, 2, 3}, {4, 5, 6}};
  writeLas(dir / "b14.las", Dataset::fromCloud(c));
  writeLas(dir / "b12.las", Dataset::fromCloud(c), o12);
  EXPECT_EQ(dump(dir / "b14.las")[0], "version 1.4 format 7 record 36 count 2");
  EXPECT_EQ(dump(dir / "b12.las")[0], "version 1.2 format 2 record 26 count 2");
}

TEST(LasLossless, NanPointsAreCountedAsDropped) {
  const auto dir = test::scratchDir("las_lossless_nan");
  PointCloud c = line(3);
  c.positions[1].x() = std::numeric_limits<float>::quiet_NaN();
  WriteReport report;
  LasWriteOptions o;
  o.report = &report;
  writeLas(dir / "a.las", Dataset::fromCloud(c), o);
  EXPECT_EQ(dump(dir / "a.las")[0], "version 1.4 format 6 record 30 count 2");
  ASSERT_TRUE(report.points.has_value());
  EXPECT_EQ(*report.points, 2u);
  EXPECT_EQ(report.dropped, 1u);
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("1 points with a non-finite (NaN) position"), std::string::npos);
}

TEST(LasLossless, PoseBeyondTheScaledIntegerRangeIsAnError) {
  const auto dir = test::scratchDir("las_lossless_overflow");
  Dataset d = Dataset::fromCloud(line(3), "far");
  d.scans[0].pose = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1e308, 0, 0));
  try {
    writeLas(dir / "a.las", d);
    FAIL() << "a 1e308 translation was written";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scan 'far'"), std::string::npos) << m;
    EXPECT_NE(m.find("puts X at"), std::string::npos) << m;
    EXPECT_NE(m.find("2^53"), std::string::npos) << m;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "a.las"));
}

TEST(LasLossless, ReturnNumberZeroIsWrittenAsOneWithConsistentCounts) {
  const auto dir = test::scratchDir("las_lossless_returns");
  PointCloud c = line(3);
  c.return_index = {0, 1, 2};
  c.return_count = {0, 2, 2};
  WriteReport report;
  LasWriteOptions o;
  o.report = &report;
  for (int minor : {2, 4}) {
    o.version_minor = minor;
    const auto file = dir / ("a1" + std::to_string(minor) + ".las");
    writeLas(file, Dataset::fromCloud(c), o);
    const auto lines = dump(file);
    EXPECT_EQ(field(lines[3], "return"), "1/1");
    EXPECT_EQ(field(lines[4], "return"), "1/2");
    EXPECT_EQ(field(lines[5], "return"), "2/2");
    EXPECT_EQ(lines[1], "by_return 2 1 0 0 0");
    ASSERT_EQ(report.notes.size(), 1u);
    EXPECT_NE(report.notes[0].find("1 points had return number 0"), std::string::npos);
  }
}

}  // namespace
}  // namespace plumb
