// The report's SVG pictures: points outside the extent are left out, text is escaped.
#include <gtest/gtest.h>

#include "report/svg_plots.hpp"

using namespace plumb::report;

namespace {
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST(SvgPlots, AScatterDrawsThePointsInsideItsExtentOnly) {
  ScatterPicture p;
  p.title = "plan";
  p.min = {0, 0};
  p.max = {10, 10};
  p.layers.push_back({"a", "#f00", {{1, 1}, {5, 5}, {11, 5}, {-1, 2}}});
  const std::string svg = scatterSvg(p);
  EXPECT_EQ(count(svg, "width=\"1.6\""), 2u);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(SvgPlots, BarsScaleToTheLargestValue) {
  BarPicture b;
  b.title = "h";
  b.bars = {{"x", 1.0, "#00f"}, {"y", 4.0, "#00f"}};
  const std::string svg = barsSvg(b, 200, 188);  // plot height 188 - 2 * 44 = 100
  EXPECT_NE(svg.find("height=\"25.0\""), std::string::npos);
  EXPECT_NE(svg.find("height=\"100.0\""), std::string::npos);
}

TEST(SvgPlots, TextIsEscaped) {
  EXPECT_EQ(escapeXml("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  EXPECT_EQ(escapeXml(std::string("x\x01y")), "x y");
}
