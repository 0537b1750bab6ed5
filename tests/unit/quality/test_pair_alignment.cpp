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
