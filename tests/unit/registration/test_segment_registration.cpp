#include <gtest/gtest.h>

#include <random>

#include "registration/segments/line_alignment.hpp"
#include "registration/segments/segment_registration.hpp"
#include "unit/registration/random_pose_trials.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;

TEST(LineAlignment, ClosedFormTranslationEq14) {
  // Three non-parallel lines through known points; points shifted by t0 must come back.
  const Eigen::Vector3d t0(1.5, -2.0, 0.25);
  std::vector<PointLineConstraint> c;
  const std::vector<Eigen::Vector3d> dirs = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const Eigen::Vector3d a(i, 2.0 * i, -1.0 * i), d = dirs[i].normalized();
    c.push_back({a + 0.7 * d - t0, a, d, 1.0});
  }
  const auto t = translationFromLines(c);
  ASSERT_TRUE(t);
  EXPECT_LT((*t - t0).norm(), 1e-9);
  // Parallel lines only: singular, reported as such.
  std::vector<PointLineConstraint> par = {c[0], c[0]};
  EXPECT_FALSE(translationFromLines(par));
}

TEST(SegmentRegistration, RecoversRandomPosesWithNoiseDropsAndOutliers) {
  // The method draws nothing (voting): the 20 runs differ by pose, noise and outliers only.
  const int ok = test::randomPoseSuccesses(
      42, 20, {}, [](const FeatureSet& source, const FeatureSet& target, int) {
        return registerSegments(source.segments, target.segments, {});
      });
  EXPECT_GE(ok, 19) << "successes out of 20";
}

TEST(SegmentRegistration, DeterministicAndReportsTooFewFeatures) {
  const FeatureSet truth = test::roomFeatures(test::asymmetricRooms());
  SegmentRegistrationParams p;
  const auto a = registerSegments(truth.segments, truth.segments, p);
  const auto b = registerSegments(truth.segments, truth.segments, p);
  ASSERT_TRUE(a.ok()) << a.message;
  EXPECT_TRUE(a.transform.matrix().isApprox(b.transform.matrix(), 0.0));
  EXPECT_LT(a.transform.rotationAngleDeg(), 1e-6);
  std::vector<Segment3D> few(truth.segments.begin(), truth.segments.begin() + 3);
  const auto f = registerSegments(few, truth.segments, p);
  EXPECT_EQ(f.status, RegistrationStatus::TooFewFeatures);
}

TEST(SegmentRegistration, UnrelatedSegmentsAreNotAConfidentAnswer) {
  // Source: random segments with no counterpart in the target -> failure, not success.
  const FeatureSet truth = test::roomFeatures(test::asymmetricRooms());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  std::vector<Segment3D> junk;
  for (int i = 0; i < 60; ++i) {
    Segment3D s;
    s.a = {u(rng), u(rng), u(rng)};
    s.b = s.a + Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized() * 2.0;
    junk.push_back(s);
  }
  const auto r = registerSegments(junk, truth.segments, {});
  EXPECT_FALSE(r.ok()) << r.message;
}
