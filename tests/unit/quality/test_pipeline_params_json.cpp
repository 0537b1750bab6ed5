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
    // One seed: the top-level one; no group has its own (issue 18).
    EXPECT_FALSE(j[key].contains("seed")) << key;
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

namespace {
/// The message of the InputError that reading `j` throws ("" when it reads).
std::string readError(const nlohmann::json& j) {
  PipelineParams p;
  try {
    pipelineParamsFromJson(j, p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(PipelineParamsJson, TopLevelIsValidatedByItsSchemaNamingTheKey) {
  EXPECT_NE(readError({{"sede", 3}}).find("'sede'"), std::string::npos) << readError({{"sede", 3}});
  EXPECT_NE(readError({{"seed", -1}}).find("'seed'"), std::string::npos);
  EXPECT_NE(readError({{"seed", 1.5}}).find("whole number"), std::string::npos);
  EXPECT_NE(readError({{"seed", 1e16}}).find("outside its valid range"), std::string::npos);
  EXPECT_NE(readError({{"refine", nlohmann::json::array()}}).find("'refine'"), std::string::npos);
  EXPECT_NE(readError({{"model-sample-spacing", 2.0}}).find("'model-sample-spacing'"), std::string::npos);
  EXPECT_NE(readError({{"method", "magic"}}).find("'method'"), std::string::npos);
  // A group's error names the group and the key.
  const std::string e = readError({{"refinement", {{"final-distance", 50.0}}}});
  EXPECT_NE(e.find("\"refinement\""), std::string::npos) << e;
  EXPECT_NE(e.find("'final-distance'"), std::string::npos) << e;
  EXPECT_EQ(readError({{"seed", 9000000000000000ull}, {"method", "planes"}}), "");
  PipelineParams p;
  pipelineParamsFromJson({{"seed", 9000000000000000ull}}, p);
  EXPECT_EQ(p.seed, 9000000000000000ull);  // exact through the schema's double
}

TEST(PipelineParamsJson, AGroupSeedFromOlderFilesMustEqualTheTopLevelSeed) {
  // Files written before issue 18 carry the top-level seed in some groups: read, dropped.
  PipelineParams p;
  pipelineParamsFromJson({{"seed", 7}, {"planes", {{"seed", 7}}}, {"refinement", {{"seed", 7}}}}, p);
  EXPECT_EQ(p.seed, 7u);
  PipelineParams d;
  pipelineParamsFromJson({{"segments", {{"seed", 1}}}}, d);  // the default top-level seed
  EXPECT_EQ(d.seed, kDefaultSeed);
  // A different one would be silently ignored: an error naming the group's key.
  const std::string e = readError({{"seed", 7}, {"openings", {{"seed", 8}}}});
  EXPECT_NE(e.find("\"openings\".\"seed\" = 8"), std::string::npos) << e;
  EXPECT_NE(e.find("top-level"), std::string::npos) << e;
  EXPECT_NE(readError({{"plane-extraction", {{"seed", "1"}}}}), "");
}

TEST(PipelineParamsJson, ValidationNamesTheGroupAndTheParameter) {
  PipelineParams p;
  EXPECT_NO_THROW(validatePipelineParams(p));
  p.planes.distance_threshold = -1.0;
  try {
    validatePipelineParams(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"planes\": parameter 'plane-distance'"), std::string::npos) << e.what();
  }
  PipelineParams q;
  q.model_sample_spacing = 0.0;
  EXPECT_THROW(validatePipelineParams(q), InputError);
}

TEST(PipelineParamsJson, GroupsUsedByEachMethod) {
  EXPECT_TRUE(paramGroupUsedBy("planes", RegistrationMethod::Auto));
  EXPECT_TRUE(paramGroupUsedBy("plane-extraction", RegistrationMethod::Planes));
  EXPECT_FALSE(paramGroupUsedBy("segments", RegistrationMethod::Planes));
  EXPECT_TRUE(paramGroupUsedBy("mesh-edges", RegistrationMethod::Segments));
  EXPECT_FALSE(paramGroupUsedBy("plane-extraction", RegistrationMethod::Icp));
  EXPECT_TRUE(paramGroupUsedBy("refinement", RegistrationMethod::Icp));
  EXPECT_TRUE(paramGroupUsedBy("registration", RegistrationMethod::Icp));  // the seed, refine
}
