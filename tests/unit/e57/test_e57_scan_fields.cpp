// The writer's field-description steps alone (e57_scan_fields.hpp): which fields a cloud
// gets, their types and limits, the values their callbacks give and the XML bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "io/e57/e57_scan_fields.hpp"

using namespace plumb;
using namespace plumb::e57;

namespace {

PointCloud cloudOf(std::vector<Eigen::Vector3f> positions, Eigen::Vector3d offset = Eigen::Vector3d::Zero()) {
  PointCloud c;
  c.positions.assign(positions.begin(), positions.end());
  c.offset = offset;
  return c;
}

std::vector<std::int64_t> integersOf(const OutField& f, std::size_t n) {
  std::vector<std::int64_t> v(n);
  f.integers(0, n, v.data());
  return v;
}

}  // namespace

TEST(E57ScanFields, IntensityIsIntegerOnlyWhenEveryValueIsWhole) {
  PointCloud c = cloudOf({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
  c.intensity = {7, 3, 5};
  WrittenScan w;
  OutField f = intensityField(c, w);
  EXPECT_EQ(f.spec.type, FieldType::Integer);
  EXPECT_EQ(f.spec.minimum, 3);
  EXPECT_EQ(f.spec.maximum, 7);
  EXPECT_TRUE(w.intensity_integer);
  EXPECT_EQ(w.intensity, (std::pair<double, double>{3, 7}));
  EXPECT_EQ(integersOf(f, 3), (std::vector<std::int64_t>{7, 3, 5}));

  c.intensity = {0.5f, std::numeric_limits<float>::quiet_NaN(), 2};
  w = WrittenScan{};
  f = intensityField(c, w);
  EXPECT_EQ(f.spec.type, FieldType::Float);
  EXPECT_TRUE(f.spec.single);
  EXPECT_FALSE(w.intensity_integer);
  EXPECT_EQ(w.intensity, (std::pair<double, double>{0.5, 2}));  // limits of the finite values
}

TEST(E57ScanFields, ExtentSkipsInvalidPositionsAndRefusesOverflowingQuanta) {
  PointCloud c = cloudOf({{1, 2, 3}, {NAN, 0, 0}, {-1, 5, 0}}, {1000, 0, 0});
  WrittenScan w;
  const PositionExtent e = positionExtent(c, E57WriteOptions{}, w);
  EXPECT_TRUE(e.any_invalid);
  EXPECT_EQ(e.bounds.min, Eigen::Vector3d(999, 2, 0));
  EXPECT_EQ(e.bounds.max, Eigen::Vector3d(1001, 5, 3));
  ASSERT_TRUE(w.bounds.has_value());
  E57WriteOptions fine;
  fine.scaled_precision = 1e-16;  // 1001 m / 1e-16 is beyond 4e18 raw units
  EXPECT_THROW(positionExtent(c, fine, w), InputError);
  fine.float_positions = true;
  EXPECT_NO_THROW(positionExtent(c, fine, w));
  EXPECT_EQ(invalidStateField(c).spec.name, "cartesianInvalidState");
  EXPECT_EQ(integersOf(invalidStateField(c), 3), (std::vector<std::int64_t>{0, 2, 0}));
}

TEST(E57ScanFields, ScaledPositionsUseQuantizedBoundsAndFillInvalidWithTheMinimum) {
  PointCloud c = cloudOf({{0.12344f, 0, 0}, {NAN, 0, 0}, {0.5f, 1, 2}});
  WrittenScan w;
  E57WriteOptions o;
  o.scaled_precision = 0.01;
  const PositionExtent e = positionExtent(c, o, w);
  std::vector<OutField> fields;
  appendPositionFields(c, o, e.bounds, w, fields);
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(fields[0].spec.name, "cartesianX");
  EXPECT_EQ(fields[0].spec.type, FieldType::ScaledInteger);
  EXPECT_EQ(fields[0].spec.minimum, 12);
  EXPECT_EQ(fields[0].spec.maximum, 50);
  EXPECT_DOUBLE_EQ(w.bounds->min.x(), 0.12);  // the bounds of the stored values
  EXPECT_EQ(integersOf(fields[0], 3), (std::vector<std::int64_t>{12, 12, 50}));
  o.float_positions = true;
  fields.clear();
  appendPositionFields(c, o, e.bounds, w, fields);
  EXPECT_EQ(fields[2].spec.type, FieldType::Float);
  EXPECT_FALSE(fields[2].spec.single);
}

TEST(E57ScanFields, ReturnIndexIsZeroBasedWithUnknownAsTheFirstReturn) {
  PointCloud c = cloudOf({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}});
  c.return_index = {0, 1, 3};
  c.return_count = {1, 2, 3};
  WrittenScan w;
  std::vector<OutField> fields;
  appendIndexFields(c, w, fields);
  ASSERT_EQ(fields.size(), 2u);
  EXPECT_EQ(fields[0].spec.name, "returnIndex");
  EXPECT_EQ(integersOf(fields[0], 3), (std::vector<std::int64_t>{0, 0, 2}));
  EXPECT_EQ(w.returns, (std::pair<std::int64_t, std::int64_t>{0, 2}));
  EXPECT_EQ(fields[1].spec.name, "returnCount");
  EXPECT_FALSE(w.rows.has_value());  // no grid
}

TEST(E57ScanFields, DescribeScanListsThePrototypeInOrder) {
  PointCloud c = cloudOf({{0, 0, 0}, {1, 1, 1}});
  c.colors = {{1, 2, 3}, {4, 5, 6}};
  c.color_invalid = {0, 1};
  c.normals = {{0, 0, 1}, {1, 0, 0}};
  c.timestamps = {1.5, 2.5};
  WrittenScan w;
  const auto fields = describeScan(c, E57WriteOptions{}, w);
  std::vector<std::string> names;
  for (const auto& f : w.prototype) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"cartesianX", "cartesianY", "cartesianZ", "colorRed", "colorGreen",
                                             "colorBlue", "isColorInvalid", "timeStamp", "nor:normalX",
                                             "nor:normalY", "nor:normalZ"}));
  EXPECT_EQ(fields.size(), names.size());
  EXPECT_EQ(w.records, 2u);
  EXPECT_TRUE(w.colors);
  EXPECT_FALSE(w.intensity.has_value());
  EXPECT_EQ(integersOf(fields[6], 2), (std::vector<std::int64_t>{0, 1}));
}
