#include <gtest/gtest.h>

#include <random>

#include "registration/segments/line_alignment.hpp"
#include "registration/segments/segment_registration.hpp"
#include "registration/segments/translation_voting.hpp"
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

namespace {
// The 12 edges of the box [0, 4] x [0, 3] x [0, 2.5] moved by `shift`.
std::vector<Segment3D> boxEdges(const Eigen::Vector3d& shift) {
  const Eigen::Vector3d size(4, 3, 2.5);
  std::vector<Segment3D> out;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        Eigen::Vector3d a = Eigen::Vector3d::Zero();
        a[(axis + 1) % 3] = i * size[(axis + 1) % 3];
        a[(axis + 2) % 3] = j * size[(axis + 2) % 3];
        Eigen::Vector3d b = a;
        b[axis] = size[axis];
        Segment3D s;
        s.a = a + shift;
        s.b = b + shift;
        out.push_back(s);
      }
  return out;
}
}  // namespace

TEST(TranslationVoting, StrongestPeakIsTheShiftAndPeaksAreApart) {
  // Source edges moved by -t: every pair of an edge with itself votes along a line through t,
  // the three directions' lines cross only there.
  const Eigen::Vector3d t(1.3, -0.7, 0.45);
  const auto target = boxEdges(Eigen::Vector3d::Zero());
  const auto source = boxEdges(-t);
  const auto cs = clusterSegmentDirections(source, {});
  const auto ct = clusterSegmentDirections(target, {});
  ASSERT_EQ(cs.clusters.size(), 3u);
  RotationCandidate rot;
  for (const auto& c : cs.clusters) {
    int match = -1;
    for (std::size_t m = 0; m < ct.clusters.size(); ++m)
      if (std::abs(c.direction.dot(ct.clusters[m].direction)) > 0.99) match = int(m);
    rot.target_of_source.push_back(match);
  }
  const double cell = 0.1;
  const auto peaks = voteTranslations(source, cs, target, ct, rot, cell, 5);
  ASSERT_FALSE(peaks.empty());
  EXPECT_LE(peaks.size(), 5u);
  EXPECT_LT((peaks[0] - t).norm(), 1.8 * cell) << peaks[0].transpose();
  for (std::size_t i = 0; i < peaks.size(); ++i)
    for (std::size_t j = i + 1; j < peaks.size(); ++j)
      EXPECT_GT((peaks[i] - peaks[j]).cwiseAbs().maxCoeff(), 2.5 * cell) << "peaks " << i << ", " << j;
  EXPECT_EQ(voteTranslations(source, cs, target, ct, rot, cell, 1).size(), 1u);
  // Without associations nothing votes.
  rot.target_of_source.assign(cs.clusters.size(), -1);
  EXPECT_TRUE(voteTranslations(source, cs, target, ct, rot, cell, 5).empty());
}
