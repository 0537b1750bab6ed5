#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "registration/auto/pipeline_param_groups.hpp"

using namespace plumb;

TEST(PipelineParamsJson, RoundTripsEveryGroup) {
  PipelineParams p;
  p.method = RegistrationMethod::Segments;
  p.refine = false;
  p.seed = 42;
  p.refinement.final_distance = 0.03;
  p.quality.max_point_rms = 0.05;
  p.candidates.min_overlap_gap = 0.012;
  const nlohmann::json j = pipelineParamsToJson(p);
  int groups = 0;
  forEachParamGroup(p, [&](const char* key, const char*, const auto&, const auto&) {
    EXPECT_TRUE(j.contains(key)) << key;
    // Every step runs with the top-level seed, so the JSON shows that one in each group.
    if (j[key].contains("seed")) {
      EXPECT_EQ(j[key]["seed"], 42) << key;
    }
    ++groups;
  });
  EXPECT_EQ(groups, 11);  // with "candidates" (runner-up comparison) and "visibility" (issue 13)
  PipelineParams q;
  pipelineParamsFromJson(j, q);
  EXPECT_DOUBLE_EQ(q.candidates.min_overlap_gap, 0.012);
  EXPECT_EQ(q.method, RegistrationMethod::Segments);
  EXPECT_FALSE(q.refine);
  EXPECT_EQ(q.seed, 42u);
  EXPECT_DOUBLE_EQ(q.refinement.final_distance, 0.03);
  EXPECT_DOUBLE_EQ(q.quality.max_point_rms, 0.05);
  EXPECT_EQ(pipelineParamsToJson(q), j);
}

TEST(PipelineParamsJson, RejectsUnknownGroupsAndOutOfRangeValues) {
  PipelineParams p;
  EXPECT_THROW(pipelineParamsFromJson(nlohmann::json{{"no-such-group", {}}}, p), InputError);
  EXPECT_THROW(pipelineParamsFromJson(nlohmann::json{{"refinement", {{"final-distance", 50.0}}}}, p),
               InputError);
  EXPECT_THROW(pipelineParamsFromJson(nlohmann::json{{"method", "magic"}}, p), InputError);
}

TEST(PipelineParamsJson, GroupsUsedByEachMethod) {
  EXPECT_TRUE(paramGroupUsedBy("planes", RegistrationMethod::Auto));
  EXPECT_TRUE(paramGroupUsedBy("plane-extraction", RegistrationMethod::Planes));
  EXPECT_FALSE(paramGroupUsedBy("segments", RegistrationMethod::Planes));
  EXPECT_TRUE(paramGroupUsedBy("mesh-edges", RegistrationMethod::Segments));
  EXPECT_FALSE(paramGroupUsedBy("plane-extraction", RegistrationMethod::Icp));
  EXPECT_TRUE(paramGroupUsedBy("refinement", RegistrationMethod::Icp));
}
