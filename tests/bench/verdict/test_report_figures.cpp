// bench_verdict reads the quality report generically: evidence other engineers add (a
// "visibility" object, "verdict_level", "candidates") must reach the table unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "evidence_table.hpp"
#include "report_figures.hpp"

using namespace plumb::verdict;

TEST(ReportFigures, EveryNumericLeafButTransformsAxesAndTimings) {
  const auto f = reportFigures(R"({
    "success": true, "transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
    "points": {"rms_m": 0.004, "overlap_ratio": 0.7},
    "runner_up": {"transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "relative_gap": 0.3},
    "direction_resistance": [0.5, 0.1, 0.9],
    "weak_directions": [{"axis": [1,0,0], "slide_resistance": 0.01}],
    "visibility": {"contradiction_ratio": 0.25},
    "candidates": [{"transform": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]], "score": 2}, {"score": 1}],
    "figures": {"seconds global": 3.0, "wall thickness m": 0.4},
    "warnings": ["a", "b"]})");
  EXPECT_DOUBLE_EQ(f.at("points.rms_m"), 0.004);
  EXPECT_DOUBLE_EQ(f.at("runner_up.relative_gap"), 0.3);
  EXPECT_DOUBLE_EQ(f.at("direction_resistance.min"), 0.1);
  EXPECT_DOUBLE_EQ(f.at("direction_resistance.max"), 0.9);
  EXPECT_DOUBLE_EQ(f.at("weak_directions[0].slide_resistance"), 0.01);
  EXPECT_DOUBLE_EQ(f.at("visibility.contradiction_ratio"), 0.25);
  EXPECT_DOUBLE_EQ(f.at("candidates.count"), 2.0);
  EXPECT_DOUBLE_EQ(f.at("candidates[0].score"), 2.0);
  EXPECT_DOUBLE_EQ(f.at("figures.wall thickness m"), 0.4);
  EXPECT_DOUBLE_EQ(f.at("warnings.count"), 2.0);
  for (const auto& [k, v] : f) {
    EXPECT_EQ(k.find("transform"), std::string::npos) << k;
    EXPECT_EQ(k.find("axis"), std::string::npos) << k;
    EXPECT_EQ(k.find("seconds"), std::string::npos) << k;
  }
  EXPECT_EQ(f.count("success"), 0u);
}

TEST(ReportFigures, LevelFromVerdictLevelElseSuccessAndWarnings) {
  EXPECT_EQ(reportLevel(R"({"success": true, "warnings": []})"), Level::Usable);
  EXPECT_EQ(reportLevel(R"({"success": true, "warnings": ["weak"]})"), Level::CheckVisually);
  EXPECT_EQ(reportLevel(R"({"success": false, "warnings": []})"), Level::FailedOrAmbiguous);
  EXPECT_EQ(reportLevel(R"({"success": true, "warnings": [], "verdict_level": "check visually"})"),
            Level::CheckVisually);
  EXPECT_EQ(reportLevel(R"({"success": false, "verdict_level": "usable"})"), Level::Usable);
  EXPECT_EQ(reportLevel(R"({"success": true, "verdict_level": "ambiguous"})"),
            Level::FailedOrAmbiguous);
}

TEST(EvidenceTable, QuantilesInterpolateBetweenSortedValues) {
  EXPECT_DOUBLE_EQ(quantile({3, 1, 2, 5, 4}, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(quantile({3, 1, 2, 5, 4}, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile({3, 1, 2, 5, 4}, 1.0), 5.0);
  EXPECT_DOUBLE_EQ(quantile({0, 10}, 0.1), 1.0);
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}
