// How figures read: counts as whole numbers, lengths in mm, ratios in percent.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "report/figure_meanings.hpp"

using plumb::report::displayValue;
using plumb::report::figureMeaning;
using plumb::report::genericPath;
using nlohmann::json;

TEST(FigureMeanings, CountsReadAsWholeNumbers) {
  EXPECT_EQ(displayValue("features.inliers", json(6)), "6");
  EXPECT_EQ(displayValue("points.inliers", json(std::size_t{10929})), "10929");
}

TEST(FigureMeanings, LengthsAnglesRatiosAndTimesHaveUnits) {
  EXPECT_EQ(displayValue("points.rms_m", json(0.0194297)), "19.4 mm");
  EXPECT_EQ(displayValue("points.refinement_shift_m", json(1.5)), "1.500 m");
  EXPECT_EQ(displayValue("points.refinement_rotation_deg", json(0.2194)), "0.219 deg");
  EXPECT_EQ(displayValue("points.overlap_ratio", json(0.7158)), "71.6 %");
  EXPECT_EQ(displayValue("runner_up.relative_gap", json(0.5478)), "54.8 %");
  EXPECT_EQ(displayValue("figures.seconds features", json(4.2228)), "4.22 s");
}

TEST(FigureMeanings, BooleansNullsAndListsReadAsWords) {
  EXPECT_EQ(displayValue("refined", json(true)), "yes");
  EXPECT_EQ(displayValue("runner_up", json(nullptr)), "none");
  EXPECT_EQ(displayValue("warnings", json::array()), "none");
  EXPECT_EQ(displayValue("warnings", json({"a", "b"})), "a; b");
  EXPECT_EQ(displayValue("normal_matrix_eigenvalues", json({1.5, 2.0})), "[1.5, 2]");
}

TEST(FigureMeanings, ArrayIndicesShareTheirMeaning) {
  EXPECT_EQ(genericPath("candidates[12].rms_m"), "candidates[].rms_m");
  EXPECT_EQ(figureMeaning("candidates[3].rms_m"), figureMeaning("candidates[0].rms_m"));
  EXPECT_FALSE(figureMeaning("visibility.target_in_source.contradicting").empty());
  EXPECT_NE(figureMeaning("figures.wall thickness (m)").find("wall thickness"), std::string::npos);
  EXPECT_TRUE(figureMeaning("no.such.figure").empty());
}
