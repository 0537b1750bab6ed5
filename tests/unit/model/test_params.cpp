#include <gtest/gtest.h>

#include "common/error.hpp"
#include "common/params_json.hpp"

using namespace plumb;

namespace {
enum class Method { Fast, Exact };
struct DemoParams {
  double threshold = 0.02;  ///< m
  int iterations = 100;
  bool refine = true;
  Method method = Method::Exact;
  static const ParamSchema<DemoParams>& schema() {
    static const auto s = ParamSchema<DemoParams>("demo")
                              .real(&DemoParams::threshold, "threshold", "Threshold", "m", 0.001, 1.0, "help")
                              .integer(&DemoParams::iterations, "iterations", "Iterations", "", 1, 1e6, "n")
                              .boolean(&DemoParams::refine, "refine", "Refine", "r")
                              .choice(&DemoParams::method, "method", "Method", {"fast", "exact"}, "m");
    return s;
  }
};
}  // namespace

TEST(Params, SchemaReadsDefaultsAndSetsFromText) {
  const auto& s = DemoParams::schema();
  DemoParams p;
  ASSERT_EQ(s.fields().size(), 4u);
  EXPECT_DOUBLE_EQ(s.find("threshold")->get(p), 0.02);
  EXPECT_TRUE(setParam(s, p, "threshold", "0.5"));
  EXPECT_TRUE(setParam(s, p, "method", "fast"));
  EXPECT_TRUE(setParam(s, p, "refine", "false"));
  EXPECT_FALSE(setParam(s, p, "nope", "1"));
  EXPECT_DOUBLE_EQ(p.threshold, 0.5);
  EXPECT_EQ(p.method, Method::Fast);
  EXPECT_FALSE(p.refine);
}

TEST(Params, RejectsOutOfRangeAndWrongTypes) {
  const auto& s = DemoParams::schema();
  DemoParams p;
  EXPECT_THROW(setParam(s, p, "threshold", "5"), InputError);
  EXPECT_THROW(setParam(s, p, "threshold", "abc"), InputError);
  EXPECT_THROW(setParam(s, p, "iterations", "2.5"), InputError);
  EXPECT_THROW(setParam(s, p, "method", "slow"), InputError);
  EXPECT_DOUBLE_EQ(p.threshold, 0.02);
}

TEST(Params, JsonRoundTrip) {
  const auto& s = DemoParams::schema();
  DemoParams p;
  p.iterations = 7;
  p.method = Method::Fast;
  const auto j = paramsToJson(s, p);
  EXPECT_EQ(j["method"], "fast");
  DemoParams q;
  paramsFromJson(s, j, q);
  EXPECT_EQ(q.iterations, 7);
  EXPECT_EQ(q.method, Method::Fast);
  EXPECT_THROW(paramsFromJson(s, nlohmann::json{{"bogus", 1}}, q), InputError);
}
