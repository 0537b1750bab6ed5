// E57 reads and writes that used to lose or invent data (issue 12), checked with the
// independent parser tools/e57_inspect.py (xml.etree for the XML, its own bit-pack decoder):
// isColorInvalid, cartesianBounds of the stored values, a data3D without coordinates, and
// scan names that XML cannot carry as they are.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "common/error.hpp"
#include "io/e57/crc32c.hpp"
#include "io/e57/e57_reader.hpp"
#include "io/e57/e57_writer.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

/// Output of e57_inspect.py on `file`.
std::string inspect(const std::filesystem::path& file) {
  const std::string out = file.string() + ".inspect";
  EXPECT_EQ(std::system(("python3 " PLUMB_E57_INSPECT " '" + file.string() + "' > '" + out + "'").c_str()), 0);
  return test::readAll(out);
}

PointCloud colouredLine(std::size_t n) {
  PointCloud c;
  for (std::size_t i = 0; i < n; ++i) {
    c.positions.emplace_back(static_cast<float>(i), 0.0f, 1.0f);
    c.colors.push_back({static_cast<std::uint8_t>(10 * i), 20, 30});
  }
  return c;
}

TEST(E57Lossless, InvalidColoursStayInvalid) {
  const auto dir = test::scratchDir("e57_color_invalid");
  PointCloud c = colouredLine(3);
  c.color_invalid = {0, 1, 0};
  writeE57(dir / "a.e57", Dataset::fromCloud(c));
  const std::string text = inspect(dir / "a.e57");
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
  EXPECT_NE(text.find("isColorInvalid set=1"), std::string::npos) << text;
  const PointCloud back = readE57(dir / "a.e57").scans[0].cloud;
  ASSERT_TRUE(back.hasColors());
  EXPECT_EQ(back.color_invalid, (std::vector<std::uint8_t>{0, 1, 0}));
  EXPECT_EQ(back.colors[1], (Rgb8{0, 0, 0}));
  EXPECT_EQ(back.colors[2], (Rgb8{20, 20, 30}));
  // No valid colour at all: no colour column (nothing invented).
  c.color_invalid = {1, 1, 1};
  writeE57(dir / "b.e57", Dataset::fromCloud(c));
  const Dataset all = readE57(dir / "b.e57");
  EXPECT_FALSE(all.scans[0].cloud.hasColors());
  EXPECT_TRUE(all.scans[0].cloud.color_invalid.empty());
}

TEST(E57Lossless, CartesianBoundsHoldTheStoredPoints) {
  // 1.00006 is stored as 1.0001 at the 0.1 mm quantum: bounds from the unquantized value put
  // that point 0.04 mm outside them.
  const auto dir = test::scratchDir("e57_bounds");
  PointCloud c;
  c.positions = {{0.00006f, -2.00006f, 5.00004f}, {1.00006f, -0.99994f, 5.00016f}};
  writeE57(dir / "a.e57", Dataset::fromCloud(c));
  const std::string text = inspect(dir / "a.e57");
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
  EXPECT_NE(text.find("points inside cartesianBounds: yes"), std::string::npos) << text;
}

/// Renames the first cartesianX element of the XML to cartesianQ (same length) and fixes the
/// CRC of its page, so that scan has no complete set of coordinates.
void breakFirstScanCoordinates(const std::filesystem::path& file) {
  std::string b = test::readAll(file);
  const auto at = b.find("<cartesianX ");
  ASSERT_NE(at, std::string::npos);
  b[at + 10] = 'Q';
  const auto close = b.find("</cartesianX>", at);
  ASSERT_LT(close, b.find("</prototype>", at));
  b[close + 11] = 'Q';
  for (std::size_t changed : {at, close}) {  // CRC-32C of the page, big-endian (E57_FACTS §3)
    const std::size_t page = changed / 1024 * 1024;
    const std::uint32_t crc = e57::crc32c(b.data() + page, 1020);
    for (int k = 0; k < 4; ++k) b[page + 1020 + k] = static_cast<char>(crc >> (24 - 8 * k));
  }
  test::writeAll(file, b);
}

TEST(E57Lossless, AScanWithoutCoordinatesIsSkippedNotFatal) {
  const auto dir = test::scratchDir("e57_skip_scan");
  Dataset d = Dataset::fromCloud(colouredLine(4), "broken");
  Scan good;
  good.name = "good";
  good.cloud = colouredLine(5);
  d.scans.push_back(good);
  writeE57(dir / "a.e57", d);
  breakFirstScanCoordinates(dir / "a.e57");
  const Dataset r = readE57(dir / "a.e57");
  ASSERT_EQ(r.scans.size(), 1u);
  EXPECT_EQ(r.scans[0].name, "good");
  EXPECT_EQ(r.scans[0].cloud.size(), 5u);
  bool warned = false;
  for (const auto& [k, v] : r.metadata)
    warned |= k == "warning" && v.find("scan 0 ('broken'") != std::string::npos &&
              v.find("skipped") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(E57Lossless, ControlCharactersAndInvalidUtf8InNamesKeepTheXmlWellFormed) {
  const auto dir = test::scratchDir("e57_names");
  Dataset d = Dataset::fromCloud(colouredLine(2), std::string("bad\x01name\xff\x1b[0m ok \xc3\xa9"));
  d.scans[0].description = std::string("tab\tand\x7f" "del \xed\xa0\x80");  // surrogate: invalid
  writeE57(dir / "a.e57", d);
  const std::string text = inspect(dir / "a.e57");  // xml.etree parses the XML section
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
  const Dataset r = readE57(dir / "a.e57");
  EXPECT_EQ(r.scans[0].name, "bad\xEF\xBF\xBDname\xEF\xBF\xBD\xEF\xBF\xBD[0m ok \xc3\xa9");
  EXPECT_EQ(r.scans[0].cloud.size(), 2u);
}

}  // namespace

namespace {

/// Every LAS attribute and three scalar fields whose names XML or the reader would not take.
PointCloud lasAttributedCloud() {
  PointCloud c = colouredLine(4);
  c.classification = {2, 6, 9, 2};
  c.classification_flags = {0, 1, 4, 8};
  c.scanner_channel = {0, 1, 2, 3};
  c.scan_flags = {0, 1, 2, 3};
  c.user_data = {0, 7, 255, 1};
  c.point_source_id = {1, 65535, 300, 2};
  c.scan_angle = {-12.5f, 0.006f, 30.0f, -0.018f};
  auto field = [](const char* name, std::initializer_list<float> v) { return ScalarField{name, Column<float>(v)}; };
  c.scalar_fields.push_back(field("my field", {1.5f, -2.0f, 3.25f, 0.0f}));
  c.scalar_fields.push_back(field("normalX", {9, 8, 7, 6}));
  c.scalar_fields.push_back(field("2x", {0.1f, 0.2f, 0.3f, 0.4f}));
  return c;
}

}  // namespace

TEST(E57Lossless, LasAttributesAndScalarFieldsRoundTripAsExtensionFields) {
  const auto dir = test::scratchDir("e57_las_fields");
  const PointCloud c = lasAttributedCloud();
  writeE57(dir / "a.e57", Dataset::fromCloud(c));
  const std::string text = inspect(dir / "a.e57");
  EXPECT_EQ(text.find("ERROR"), std::string::npos) << text;
  EXPECT_NE(text.find("plumb:pointSourceId range [1, 65535]"), std::string::npos) << text;
  EXPECT_NE(text.find("plumb:my_field"), std::string::npos) << text;
  const PointCloud back = readE57(dir / "a.e57").scans[0].cloud;
  EXPECT_EQ(back.classification, c.classification);
  EXPECT_EQ(back.classification_flags, c.classification_flags);
  EXPECT_EQ(back.scanner_channel, c.scanner_channel);
  EXPECT_EQ(back.scan_flags, c.scan_flags);
  EXPECT_EQ(back.user_data, c.user_data);
  EXPECT_EQ(back.point_source_id, c.point_source_id);
  ASSERT_EQ(back.scan_angle.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(back.scan_angle[i], c.scan_angle[i]);  // bit-exact
  EXPECT_FALSE(back.hasNormals());  // "normalX" stays a scalar field, not a normal
  ASSERT_EQ(back.scalar_fields.size(), 3u);
  EXPECT_EQ(back.scalar_fields[0].name, "my_field");
  EXPECT_EQ(back.scalar_fields[1].name, "normalX_2");
  EXPECT_EQ(back.scalar_fields[2].name, "_2x");
  for (std::size_t f = 0; f < 3; ++f)
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(back.scalar_fields[f].values[i], c.scalar_fields[f].values[i]);
}
