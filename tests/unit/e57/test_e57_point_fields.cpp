// The prototype-field steps of the E57 reader alone: roles, value ranges, colour scaling.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/e57/e57_point_fields.hpp"

using namespace plumb::e57;
using namespace plumb::e57::detail;

namespace {

FieldSpec integerField(const std::string& name, std::int64_t lo, std::int64_t hi) {
  FieldSpec f;
  f.name = name;
  f.type = FieldType::Integer;
  f.minimum = lo;
  f.maximum = hi;
  return f;
}

FieldSpec floatField(const std::string& name) {
  FieldSpec f;
  f.name = name;
  f.type = FieldType::Float;
  return f;
}

}  // namespace

TEST(E57PointFields, RolesOfStandardAndExtensionNames) {
  EXPECT_EQ(roleOf("cartesianX"), X);
  EXPECT_EQ(roleOf("sphericalElevation"), Elevation);
  EXPECT_EQ(roleOf("isColorInvalid"), ColorInvalid);
  // Extensions match under any namespace prefix, standard names only as written.
  EXPECT_EQ(roleOf("nor:normalY"), NormalY);
  EXPECT_EQ(roleOf("anything:classification"), Classification);
  EXPECT_EQ(roleOf("plumb:sensorOriginZ"), SensorZ);
  EXPECT_EQ(roleOf("ext:cartesianX"), -1);
  EXPECT_EQ(roleOf("reflectance"), -1);
}

TEST(E57PointFields, FirstFieldOfARoleWinsTheRestAreOthers) {
  const std::vector<FieldSpec> fields = {floatField("cartesianX"), floatField("reflectance"),
                                         floatField("cartesianX"), floatField("cartesianY")};
  const FieldRoles r = assignRoles(fields);
  EXPECT_EQ(r.column[X], 0);
  EXPECT_EQ(r.column[Y], 3);
  EXPECT_FALSE(r.has(Z));
  EXPECT_FALSE(r.hasAll(X, Y, Z));
  EXPECT_EQ(r.others, (std::vector<std::size_t>{1, 2}));
}

TEST(E57PointFields, FieldRangeByType) {
  FieldSpec scaled = integerField("intensity", -10, 20);
  scaled.type = FieldType::ScaledInteger;
  scaled.scale = 0.5;
  scaled.offset = 100;
  EXPECT_DOUBLE_EQ(fieldRange(scaled).minimum, 95.0);
  EXPECT_DOUBLE_EQ(fieldRange(scaled).maximum, 110.0);
  EXPECT_DOUBLE_EQ(fieldRange(integerField("colorRed", 0, 65535)).maximum, 65535.0);
  FieldSpec f = floatField("intensity");  // no limits given: 0..255
  EXPECT_DOUBLE_EQ(fieldRange(f).maximum, 255.0);
  f.has_float_limits = true;
  f.float_min = -1;
  f.float_max = 1;
  EXPECT_DOUBLE_EQ(fieldRange(f).minimum, -1.0);
}

TEST(E57PointFields, ColorScaleKeepsTopBitsOfIntegersAndScalesFloats) {
  const ColorScale sixteen({0, 65535}, true);
  EXPECT_EQ(sixteen(0), 0);
  EXPECT_EQ(sixteen(255), 0);
  EXPECT_EQ(sixteen(256), 1);
  EXPECT_EQ(sixteen(65280), 255);
  EXPECT_EQ(sixteen(65535), 255);
  const ColorScale unit({0, 1}, false);
  EXPECT_EQ(unit(0.0), 0);
  EXPECT_EQ(unit(0.5), 128);  // 127.5 rounds to even: 128
  EXPECT_EQ(unit(1.0), 255);
  EXPECT_EQ(unit(2.0), 255);   // clamped
  EXPECT_EQ(unit(-1.0), 0);
  EXPECT_EQ(unit(std::nan("")), 0);
  const ColorScale empty({5, 5}, true);  // no span: values pass through
  EXPECT_EQ(empty(200), 200);
}

TEST(E57PointFields, ColorsAreDirectOnlyForIntegerZeroTo255) {
  ScanInfo info;
  info.fields = {integerField("colorRed", 0, 255), integerField("colorGreen", 0, 255),
                 integerField("colorBlue", 0, 255)};
  EXPECT_TRUE(colorDecoding(info, assignRoles(info.fields)).direct);
  info.fields[2] = integerField("colorBlue", 0, 65535);
  const ColorDecoding wide = colorDecoding(info, assignRoles(info.fields));
  EXPECT_FALSE(wide.direct);
  EXPECT_EQ(wide.scale[2](65535), 255);
  EXPECT_EQ(wide.scale[0](255), 255);
  // Declared colour limits override the field ranges.
  info.color_limits = std::array<Limits, 3>{Limits{0, 1023}, Limits{0, 1023}, Limits{0, 1023}};
  const ColorDecoding limited = colorDecoding(info, assignRoles(info.fields));
  EXPECT_FALSE(limited.direct);
  EXPECT_EQ(limited.scale[0](1023), 255);
  EXPECT_EQ(limited.scale[0](4), 1);
}

TEST(E57PointFields, ClampToTargetRange) {
  EXPECT_EQ(clampTo<std::uint8_t>(300.0), 255);
  EXPECT_EQ(clampTo<std::uint8_t>(-3.0), 0);
  EXPECT_EQ(clampTo<std::int32_t>(std::nan("")), 0);
  EXPECT_EQ(clampTo<std::int32_t>(1e12), 2147483647);
}
