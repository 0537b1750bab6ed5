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
