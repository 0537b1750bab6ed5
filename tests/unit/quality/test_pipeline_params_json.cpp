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
  EXPECT_EQ(groups, 14);  // with "candidates", "visibility" (issue 13), "bim-features",
                          // "orientation" (issue 14) and "memory" (issue 16)
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
  EXPECT_TRUE(paramGroupUsedBy("memory", RegistrationMethod::Icp));  // how the inputs are read
}

// Issue 16: the memory budget is one group of the schema, reachable by --set and JSON, with
// 0 (half the available memory) by default; explicit budgets are taken as given.
TEST(PipelineParamsJson, MemoryBudgetIsAParameterGroup) {
  PipelineParams p;
  EXPECT_EQ(pipelineParamsToJson(p).at("memory").at("budget"), 0.0);
  EXPECT_EQ(pipelineParamsToJson(p).at("memory").at("subsample-voxel"), 0.02);
  setPipelineParam(p, "memory.budget", "512");
  EXPECT_EQ(memoryBudgetBytes(p.memory), 512ull << 20);
  EXPECT_THROW(setPipelineParam(p, "memory.budget", "-1"), InputError);
  p.memory.budget_mb = 0;
  EXPECT_GE(memoryBudgetBytes(p.memory), 256ull << 20);  // half of MemAvailable, at least 256 MB
}

// Issue 18: the nested parameters (direction clustering, segment-set distance, rotation
// enumeration) and the formerly hidden constants are reachable by JSON, by --set's
// setPipelineParam, and round trip through the schema with their defaults unchanged.
TEST(PipelineParamsJson, NestedAndFormerlyHiddenParametersAreReachable) {
  const nlohmann::json defaults = pipelineParamsToJson(PipelineParams{});
  // Defaults as before (results bit-identical with defaults).
  EXPECT_EQ(defaults.at("planes").at("cluster-angle"), 10.0);
  EXPECT_EQ(defaults.at("planes").at("max-tilt"), 10.0);
  EXPECT_EQ(defaults.at("planes").at("up-axis-known"), true);
  EXPECT_EQ(defaults.at("planes").at("allow-up-down-flip"), false);
  EXPECT_EQ(defaults.at("segments").at("robust-distance"), 0.10);
  EXPECT_EQ(defaults.at("openings").at("plane-distance"), 0.10);
  EXPECT_FALSE(defaults.at("openings").contains("offset-modes"));  // not used by openings
  EXPECT_EQ(defaults.at("segment-detection").at("snap-angle"), 20.0);
  EXPECT_EQ(defaults.at("segment-detection").at("line-angle"), 20.0);
  EXPECT_EQ(defaults.at("segment-detection").at("min-linearity"), 0.9);
  EXPECT_EQ(defaults.at("segment-detection").at("snap-near"), 0.03);
  EXPECT_EQ(defaults.at("plane-extraction").at("local-cell"), 0.6);
  EXPECT_EQ(defaults.at("agreement-rotation"), 2.0);
  EXPECT_EQ(defaults.at("agreement-translation"), 0.3);

  const nlohmann::json j = {
      {"agreement-rotation", 1.5}, {"agreement-translation", 0.2},
      {"planes", {{"cluster-angle", 12.0}, {"max-clusters", 4}, {"max-tilt", 5.0},
                  {"up-axis-known", false}, {"allow-up-down-flip", true}, {"min-frame-angle", 40.0}}},
      {"segments", {{"robust-distance", 0.2}, {"segment-angle", 7.0}, {"cluster-angle", 8.0}, {"max-tilt", 3.0}}},
      {"openings", {{"robust-distance", 0.15}, {"plane-distance", 0.2}, {"cluster-angle", 6.0}}},
      {"segment-detection", {{"line-angle", 15.0}, {"min-linearity", 0.8}, {"snap-angle", 25.0}, {"snap-near", 0.04}}},
      {"plane-extraction", {{"local-cell", 0.8}}}};
  PipelineParams p;
  pipelineParamsFromJson(j, p);
  EXPECT_DOUBLE_EQ(p.agreement_rotation_deg, 1.5);
  EXPECT_DOUBLE_EQ(p.agreement_translation, 0.2);
  EXPECT_DOUBLE_EQ(p.planes.clustering.angle_tolerance_deg, 12.0);
  EXPECT_EQ(p.planes.clustering.max_clusters, 4);
  EXPECT_DOUBLE_EQ(p.planes.rotations.max_tilt_deg, 5.0);
  EXPECT_FALSE(p.planes.rotations.up_axis_known);
  EXPECT_TRUE(p.planes.rotations.allow_up_down_flip);
  EXPECT_DOUBLE_EQ(p.planes.rotations.min_frame_angle_deg, 40.0);
  EXPECT_DOUBLE_EQ(p.segments.distance.robust_distance, 0.2);
  EXPECT_DOUBLE_EQ(p.segments.distance.max_angle_deg, 7.0);
  EXPECT_DOUBLE_EQ(p.segments.clustering.angle_tolerance_deg, 8.0);
  EXPECT_DOUBLE_EQ(p.segments.rotations.max_tilt_deg, 3.0);
  EXPECT_DOUBLE_EQ(p.openings.distance.robust_distance, 0.15);
  EXPECT_DOUBLE_EQ(p.openings.planes.distance_threshold, 0.2);
  EXPECT_DOUBLE_EQ(p.openings.planes.clustering.angle_tolerance_deg, 6.0);
  EXPECT_DOUBLE_EQ(p.segment_detection.line_angle_deg, 15.0);
  EXPECT_DOUBLE_EQ(p.segment_detection.min_linearity, 0.8);
  EXPECT_DOUBLE_EQ(p.segment_detection.snap_min_angle_deg, 25.0);
  EXPECT_DOUBLE_EQ(p.segment_detection.snap_near_distance, 0.04);
  EXPECT_DOUBLE_EQ(p.plane_extraction.msac_local_cell, 0.8);
  // Other groups' copies are untouched (planes' clustering is not segments').
  EXPECT_DOUBLE_EQ(PipelineParams{}.segments.clustering.max_clusters, p.segments.clustering.max_clusters);
  // Round trip.
  PipelineParams q;
  pipelineParamsFromJson(pipelineParamsToJson(p), q);
  EXPECT_EQ(pipelineParamsToJson(q), pipelineParamsToJson(p));
  // Validation like the feature parameters: range and type, naming the group and the key.
  const std::string range = readError({{"planes", {{"max-tilt", 100.0}}}});
  EXPECT_NE(range.find("\"planes\": parameter 'max-tilt'"), std::string::npos) << range;
  EXPECT_NE(readError({{"segment-detection", {{"min-linearity", 1.5}}}}).find("'min-linearity'"), std::string::npos);
  EXPECT_NE(readError({{"planes", {{"up-axis-known", "maybe"}}}}).find("'up-axis-known'"), std::string::npos);
  EXPECT_NE(readError({{"openings", {{"offset-modes", 3}}}}).find("'offset-modes'"), std::string::npos);
  PipelineParams bad;
  bad.segments.clustering.angle_tolerance_deg = 0.0;
  EXPECT_THROW(validatePipelineParams(bad), InputError);
}

TEST(PipelineParamsJson, SetPipelineParamByGroupAndKey) {
  PipelineParams p;
  setPipelineParam(p, "planes.max-tilt", "4");
  setPipelineParam(p, "segments.robust-distance", "0.2");
  setPipelineParam(p, "agreement-rotation", "1");
  setPipelineParam(p, "seed", "12");
  EXPECT_DOUBLE_EQ(p.planes.rotations.max_tilt_deg, 4.0);
  EXPECT_DOUBLE_EQ(p.segments.distance.robust_distance, 0.2);
  EXPECT_DOUBLE_EQ(p.agreement_rotation_deg, 1.0);
  EXPECT_EQ(p.seed, 12u);
  auto error = [&p](const std::string& path, const std::string& value) {
    try {
      setPipelineParam(p, path, value);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("nope.max-tilt", "1").find("'nope'"), std::string::npos);
  EXPECT_NE(error("planes.nope", "1").find("'nope'"), std::string::npos);
  EXPECT_NE(error("planes.seed", "1").find("'seed'"), std::string::npos);  // no group seeds
  EXPECT_NE(error("nope", "1").find("'nope'"), std::string::npos);
  const std::string range = error("planes.max-tilt", "100");
  EXPECT_NE(range.find("\"planes\""), std::string::npos) << range;
  EXPECT_NE(range.find("'max-tilt'"), std::string::npos) << range;
  EXPECT_DOUBLE_EQ(p.planes.rotations.max_tilt_deg, 4.0);  // unchanged by the failed set
}

// Issue 17: tooltips speak the field's terms first; a paper citation may follow, on a later
// line only (the UI shows the help as the tooltip, line by line).
TEST(PipelineParamsJson, HelpTextsPutPaperCitationsAfterTheFirstLine) {
  PipelineParams p;
  int helps = 0, cited = 0;
  forEachParamGroup(p, [&](const char* group, const char*, const auto& schema, const auto&) {
    for (const auto& f : schema.fields()) {
      const std::string& help = f.spec.help;
      ++helps;
      EXPECT_FALSE(help.empty()) << group << "." << f.spec.key;
      const std::string first = help.substr(0, help.find('\n'));
      for (const char* citation : {"eq.", "eqs.", "Alg.", "2021 ", "2023 "})
        EXPECT_EQ(first.find(citation), std::string::npos) << group << "." << f.spec.key << ": " << help;
      cited += help.find('\n') != std::string::npos;
    }
  });
  EXPECT_GT(helps, 100);
  EXPECT_GE(cited, 4) << "the citations are kept, on their own line";
}
