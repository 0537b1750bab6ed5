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

namespace {
struct OuterParams {
  double scale = 2.0;
  DemoParams inner;
  DemoParams other;
};
}  // namespace

TEST(Params, NestedSchemasAreOneFlatList) {
  const auto s = ParamSchema<OuterParams>("outer")
                     .real(&OuterParams::scale, "scale", "Scale", "", 0.1, 10, "s")
                     .nested(&OuterParams::inner, DemoParams::schema())
                     .nested(&OuterParams::other, DemoParams::schema(), "other-", {"threshold"});
  ASSERT_EQ(s.fields().size(), 1u + 4u + 1u);
  OuterParams p;
  EXPECT_TRUE(setParam(s, p, "iterations", "9"));
  EXPECT_TRUE(setParam(s, p, "other-threshold", "0.3"));
  EXPECT_FALSE(setParam(s, p, "other-iterations", "9"));  // not taken from `other`
  EXPECT_EQ(p.inner.iterations, 9);
  EXPECT_EQ(p.other.iterations, 100);
  EXPECT_DOUBLE_EQ(p.other.threshold, 0.3);
  EXPECT_DOUBLE_EQ(p.inner.threshold, 0.02);
  // Nested fields keep their spec (range, unit) and check it.
  EXPECT_EQ(s.find("other-threshold")->spec.unit, "m");
  EXPECT_THROW(setParam(s, p, "threshold", "5"), InputError);
  const auto j = paramsToJson(s, p);
  EXPECT_EQ(j.at("iterations"), 9);
  OuterParams q;
  paramsFromJson(s, j, q);
  EXPECT_EQ(q.inner.iterations, 9);
  EXPECT_DOUBLE_EQ(q.other.threshold, 0.3);
}

TEST(Params, ASchemaListingAKeyTwiceIsAProgrammingError) {
  // The keys are the CLI flags and JSON keys: nesting two structs without a prefix collides.
  EXPECT_THROW(ParamSchema<OuterParams>("outer")
                   .nested(&OuterParams::inner, DemoParams::schema())
                   .nested(&OuterParams::other, DemoParams::schema()),
               std::logic_error);
}
