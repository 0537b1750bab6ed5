// The HTML report carries every figure of the JSON report, exactly, each with a meaning.
#include <gtest/gtest.h>


#include "report/figure_meanings.hpp"
#include "report/html_report.hpp"
#include "support/html_figures.hpp"
#include "report_fixture.hpp"

using namespace plumb;
using plumb::test::htmlFigures;
using namespace plumb::report;

namespace {


RegistrationReport fullReport() {
  RegistrationReport r;
  r.source = {"source", "indoor <scan>.e57", false, 112624, 0};
  r.target = {"target", "model.ifc", true, 0, 5000};
  r.quality = test::fullQualityReport();
  r.created_utc = "2026-11-24T07:00:00Z";
  r.plumb_version = "test";
  return r;
}

}  // namespace

TEST(HtmlReport, EveryJsonFigureAppearsWithTheSameValue) {
  const RegistrationReport r = fullReport();
  const auto json = flattenReportJson(qualityReportToJson(r.quality));
  const auto html = htmlFigures(reportHtml(r));
  ASSERT_GT(json.size(), 60u);
  EXPECT_EQ(html.size(), json.size());
  for (const auto& [path, value] : json) {
    ASSERT_TRUE(html.count(path)) << path << " is missing from the HTML";
    EXPECT_EQ(html.at(path), value) << path;
  }
}

TEST(HtmlReport, EveryFigureHasAMeaning) {
  for (const auto& [path, value] : flattenReportJson(qualityReportToJson(test::fullQualityReport())))
    EXPECT_FALSE(figureMeaning(path).empty()) << path << " (" << value << ") has no meaning";
}

TEST(HtmlReport, TextIsEscapedAndTheVerdictLevelShows) {
  const std::string html = reportHtml(fullReport());
  EXPECT_NE(html.find("indoor &lt;scan&gt;.e57"), std::string::npos);
  EXPECT_EQ(html.find("<scan>"), std::string::npos);
  EXPECT_NE(html.find("class=\"verdict check-visually\""), std::string::npos);
  EXPECT_NE(html.find("<li>a direction is weakly constrained</li>"), std::string::npos);
  EXPECT_NE(html.find("5000 triangles"), std::string::npos);
  EXPECT_NE(html.find("Sign-off"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // self-contained, nothing to run
}

TEST(HtmlReport, GridCoordinatesOfTheTransformKeepTheirDigits) {
  const std::string html = reportHtml(fullReport());
  EXPECT_NE(html.find("651000.2500"), std::string::npos);
  EXPECT_NE(html.find("6860000.5000"), std::string::npos);
}
