#include <gtest/gtest.h>

#include <random>

#include "common/error.hpp"
#include "registration/common/pair_alignment.hpp"

using namespace plumb;

TEST(PairAlignment, RecoversAKnownTransformExactlyAndWithNoise) {
  const RigidTransform truth = RigidTransform::fromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(2.0, Eigen::Vector3d(0.3, -0.2, 1.0).normalized())),
      Eigen::Vector3d(120.0, -45.0, 3.5));
  std::vector<Eigen::Vector3d> s{{0, 0, 0}, {10, 0, 0}, {0, 8, 0}, {3, 4, 3}, {9, 7, 2.5}};
  std::vector<Eigen::Vector3d> t;
  for (const auto& p : s) t.push_back(truth.apply(p));
  const PairAlignmentResult exact = alignPointPairs(s, t);
  EXPECT_LT(RigidTransform::rotationErrorDeg(exact.transform, truth), 1e-9);
  EXPECT_LT(RigidTransform::translationError(exact.transform, truth), 1e-9);
  EXPECT_LT(exact.rms, 1e-9);

  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (auto& p : t) p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  // One bad pick: its residual stands out.
  t[3] += Eigen::Vector3d(0.5, 0, 0);
  const PairAlignmentResult r = alignPointPairs(s, t);
  ASSERT_EQ(r.residuals.size(), 5u);
  std::size_t worst = 0;
  for (std::size_t i = 1; i < 5; ++i)
    if (r.residuals[i] > r.residuals[worst]) worst = i;
  EXPECT_EQ(worst, 3u);
  EXPECT_GT(r.rms, 0.05);
}

TEST(PairAlignment, RejectsTooFewOrCollinearPairs) {
  const std::vector<Eigen::Vector3d> two{{0, 0, 0}, {1, 0, 0}};
  EXPECT_THROW(alignPointPairs(two, two), InputError);
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}};
  try {
    alignPointPairs(line, line);
    FAIL() << "collinear pairs accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos);
  }
  const std::vector<Eigen::Vector3d> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(alignPointPairs(three, two), InputError);
}

namespace {
/// Picks on a levelled station turned by 37 deg and shifted (national-grid scale), 5 mm noise.
struct LevelledPicks {
  RigidTransform truth = RigidTransform::fromYaw(37.0 * M_PI / 180.0, {651234.5, 6860123.25, 41.2});
  std::vector<Eigen::Vector3d> s{{0, 0, 0.2}, {12, 1, 2.8}, {2, 9, 0.1}, {8, 7, 2.9}, {5, -3, 1.5}};
  std::vector<Eigen::Vector3d> t;
  LevelledPicks() {
    std::mt19937 rng(11);
    std::normal_distribution<double> noise(0.0, 0.005);
    for (const auto& p : s) t.push_back(truth.apply(p) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
};
}  // namespace

TEST(PairAlignment, ALeftOutPairIsACheckPointWithItsResidual) {
  LevelledPicks p;
  p.t[1] += Eigen::Vector3d(0.0, 0.4, 0.0);  // a wrong pick
  PairAlignmentParams params;
  params.used = {true, false, true, true, true};
  const PairAlignmentResult r = alignPointPairs(p.s, p.t, params);
  EXPECT_EQ(r.used, 4u);
  EXPECT_LT(r.rms, 0.01) << "the fit without the wrong pick";
  EXPECT_NEAR(r.residuals[1], 0.4, 0.02) << "the left-out pick's residual is still reported";
  EXPECT_NEAR(r.check_rms, r.residuals[1], 1e-12);
  EXPECT_LT(RigidTransform::rotationErrorDeg(r.transform, p.truth), 0.1);
  const PairAlignmentResult all = alignPointPairs(p.s, p.t);
  EXPECT_GT(all.rms, 0.1) << "with it, the whole fit is off";
  EXPECT_EQ(all.check_rms, 0.0);
}

TEST(PairAlignment, LevelledFitTurnsAboutTheVerticalOnlyAndNeedsTwoPairs) {
  LevelledPicks p;
  PairAlignmentParams levelled;
  levelled.levelled = true;
  const PairAlignmentResult r = alignPointPairs(p.s, p.t, levelled);
  EXPECT_LT(RigidTransform::rotationErrorDeg(r.transform, p.truth), 0.05);
  EXPECT_LT(RigidTransform::translationError(r.transform, p.truth), 0.01);
  EXPECT_NEAR(r.transform.rotation()(2, 2), 1.0, 1e-12) << "no tilt at all";
  // Two pairs are enough when levelled (three are needed otherwise).
  const std::vector<Eigen::Vector3d> s2(p.s.begin(), p.s.begin() + 2), t2(p.t.begin(), p.t.begin() + 2);
  const PairAlignmentResult two = alignPointPairs(s2, t2, levelled);
  EXPECT_LT(RigidTransform::rotationErrorDeg(two.transform, p.truth), 0.1);
  EXPECT_THROW(alignPointPairs(s2, t2), InputError);
  // Points above one another tell nothing about the yaw.
  const std::vector<Eigen::Vector3d> stack{{1, 1, 0}, {1, 1, 3}};
  try {
    alignPointPairs(stack, stack, levelled);
    FAIL() << "coincident plan positions accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("coincide in plan"), std::string::npos);
  }
  // A tilted truth: the levelled fit cannot follow it, and its residuals show it.
  const RigidTransform tilted = RigidTransform::fromQuaternion(
      Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * M_PI / 180.0, Eigen::Vector3d::UnitX())), {0, 0, 0});
  std::vector<Eigen::Vector3d> tt;
  for (const auto& x : p.s) tt.push_back(tilted.apply(x));
  EXPECT_GT(alignPointPairs(p.s, tt, levelled).rms, 0.05);
  EXPECT_LT(alignPointPairs(p.s, tt).rms, 1e-9);
}
