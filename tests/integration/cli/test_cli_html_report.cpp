// plumb-cli register --report R.html: the report to hand over holds the same figures as the
// JSON report of the same registration, and a real browser (headless Chromium) opens it.
#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>


#include "report/html_report.hpp"
#include "support/html_figures.hpp"
#include "support/cli_runner.hpp"

using namespace plumb;
using plumb::test::htmlFigures;
using plumb::test::plumbCli;
using plumb::test::shellQuote;

namespace {

std::string roomScan(int i) { return test::sharedData("pcd/room_scan" + std::to_string(i) + ".pcd").string(); }


int runChromium(const std::filesystem::path& dir, const std::string& args) {
  const std::string cmd = "cd " + shellQuote(dir.string()) + " && timeout 120 " + shellQuote(PLUMB_CHROMIUM) +
                          " --headless --no-sandbox --disable-gpu --user-data-dir=" +
                          shellQuote((dir / "chromium-profile").string()) + " " + args + " 2>chromium.log";
  return std::system(cmd.c_str());
}

void expectSameFigures(const std::string& html_text, const std::string& json_text) {
  const auto html = htmlFigures(html_text);
  const auto json = report::flattenReportJson(json_text);
  ASSERT_GT(json.size(), 50u);
  EXPECT_EQ(html.size(), json.size());
  for (const auto& [path, value] : json) {
    ASSERT_TRUE(html.count(path)) << path;
    EXPECT_EQ(html.at(path), value) << path;
  }
}

}  // namespace

// One registration (the real room pair) writes both reports; one test, so it runs once.
TEST(HtmlReport, SameFiguresAsTheJsonReportVerdictPicturesAndAHeadlessBrowserOpensIt) {
  const auto dir = test::scratchDir("cli_html_report");
  const auto r = plumbCli(dir, "register " + shellQuote(roomScan(2)) + " " + shellQuote(roomScan(1)) +
                                   " --report report.html --report report.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string html = test::readAll(dir / "report.html"), json = test::readAll(dir / "report.json");
  {
    SCOPED_TRACE("every figure of the JSON report, equal");
    expectSameFigures(html, json);
  }
  EXPECT_NE(html.find("Verdict: usable"), std::string::npos);
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 4u);  // plan, section, distance histogram, per-feature residuals
  EXPECT_NE(html.find("Sign-off"), std::string::npos);

  ASSERT_FALSE(std::string(PLUMB_CHROMIUM).empty())
      << "chromium is not installed (packaging/dev.sh deps installs it)";
  const std::string url = "file://" + (dir / "report.html").string();
  ASSERT_EQ(runChromium(dir, "--dump-dom " + url + " > dom.html"), 0) << test::readAll(dir / "chromium.log");
  const std::string dom = test::readAll(dir / "dom.html");
  EXPECT_NE(dom.find("Verdict: usable"), std::string::npos);
  {
    SCOPED_TRACE("the figures as the browser parsed them");
    expectSameFigures(dom, json);
  }
  ASSERT_EQ(runChromium(dir, "--window-size=1100,3000 --screenshot=" + (dir / "report.png").string() + " " + url), 0);
  EXPECT_GT(std::filesystem::file_size(dir / "report.png"), 50'000u);  // a blank page is ~10 KB
}

TEST(HtmlReportOption, AnotherExtensionIsRefusedBeforeAnythingRuns) {
  const auto dir = test::scratchDir("cli_html_report_ext");
  const auto r = plumbCli(dir, "register " + shellQuote(roomScan(2)) + " " + shellQuote(roomScan(1)) +
                                   " --report report.txt");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("must end in .json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "report.txt"));
}

// A registration that fails (one flat patch onto the room: nothing holds it) still gets its
// report, with the verdict and no pictures of a result it does not have.
TEST(HtmlReportOption, AFailedRegistrationGetsAReportWithoutPictures) {
  const auto dir = test::scratchDir("cli_html_report_failed");
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex 3600\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n";
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 60; ++j) ply << i * 0.05 << " " << j * 0.05 << " 0\n";
  test::writeAll(dir / "patch.ply", ply.str());
  const auto r = plumbCli(dir, "register patch.ply " + shellQuote(roomScan(1)) + " --report report.html");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::string html = test::readAll(dir / "report.html");
  EXPECT_NE(html.find("Verdict: failed"), std::string::npos);
  EXPECT_NE(html.find("None: the registration failed"), std::string::npos);
  EXPECT_EQ(html.find("<svg"), std::string::npos);
  EXPECT_FALSE(htmlFigures(html).empty());
}
