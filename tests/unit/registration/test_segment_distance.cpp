#include <gtest/gtest.h>

#include <random>

#include "registration/segment_distance/segment_pair_distance.hpp"
#include "registration/segment_distance/segment_set_distance.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;

TEST(SegmentPairDistance, OverlapAndDistanceOfParallelSegments) {
  // [0,2] and [1,4] on parallel lines 0.05 apart: overlap 1 over the shorter 2 -> 0.5.
  const auto m = measureSegmentPair({0, 0, 0}, {2, 0, 0}, {4, 0.05, 0}, {1, 0.05, 0});
  EXPECT_NEAR(m.relative_overlap, 0.5, 1e-9);
  // Midpoint (1,0,0) to [1,4]: 0.05; midpoint (2.5,.05,0) to [0,2]: sqrt(0.25+0.0025).
  EXPECT_NEAR(m.distance, 0.5 * (0.05 + std::sqrt(0.25 + 0.0025)), 1e-9);
  // Disjoint: overlap clamped to 0. Contained: clamped to 1.
  EXPECT_EQ(measureSegmentPair({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}).relative_overlap, 0.0);
  EXPECT_NEAR(measureSegmentPair({0, 0, 0}, {5, 0, 0}, {1, 0, 0}, {2, 0, 0}).relative_overlap, 1.0,
              1e-12);
}

TEST(SegmentSetDistance, RobustCostMatchesBruteForceAndIsZeroAtTruth) {
  const FeatureSet f = test::roomFeatures(test::asymmetricRooms());
  SegmentDistanceParams p;
  p.robust_distance = 0.1;
  const SegmentSetIndex index(f.segments, p);
  const double d2 = 0.01;
  // Perfect alignment: every segment covered -> cost 0.
  EXPECT_NEAR(index.distance(f.segments, RigidTransform()), 0.0, 1e-9);
  // Shift by 5 cm across all: compare with a brute-force evaluation of eq. 7-8.
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 5; ++trial) {
    const RigidTransform t = RigidTransform::fromYaw(0.01 * trial, {0.03 * trial, 0.02, 0.0});
    double brute = 0.0;
    for (const auto& s : f.segments) {
      const Eigen::Vector3d a = t.apply(s.a), b = t.apply(s.b);
      double sum = 0.0;
      for (const auto& q : f.segments) {
        if (std::abs((b - a).normalized().dot(q.direction())) < std::cos(p.max_angle_deg * M_PI / 180))
          continue;
        const auto m = measureSegmentPair(a, b, q.a, q.b);
        if (m.distance < p.robust_distance) sum += m.relative_overlap * (d2 - m.distance * m.distance);
      }
      brute += std::max(0.0, d2 - sum);
    }
    EXPECT_NEAR(index.distance(f.segments, t), brute, 1e-9) << trial;
  }
  // Far away: every segment pays d^2.
  EXPECT_NEAR(index.distance(f.segments, RigidTransform::fromYaw(0, {100, 0, 0})),
              f.segments.size() * d2, 1e-12);
}
