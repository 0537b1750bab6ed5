#pragma once
// Registration trials on the synthetic rooms under random poses: perturbed copies of the same
// features as source and target, the source moved by the inverse of a random pose.
#include <gtest/gtest.h>

#include <random>

#include "registration/common/registration_result.hpp"
#include "unit/registration/synthetic_building.hpp"

namespace plumb::test {

/// Runs `runs` trials with `solve(source, target, run) -> GlobalRegistrationResult` and returns how
/// many recover the pose within 0.1 deg / 2 cm. Fails the calling test on a confident wrong
/// answer (success outside the tolerance) and on a failure reported without a reason.
template <class Solve>
int randomPoseSuccesses(std::uint64_t seed, int runs, const Perturbation& pert, Solve solve) {
  const FeatureSet truth = roomFeatures(asymmetricRooms());
  std::mt19937_64 rng(seed);
  int ok = 0;
  for (int run = 0; run < runs; ++run) {
    const RigidTransform pose = randomPose(rng);  // maps source -> target
    const FeatureSet target = perturb(truth, pert, rng);
    FeatureSet source = perturb(truth, pert, rng);
    source.transform(pose.inverse());
    const GlobalRegistrationResult r = solve(source, target, run);
    const double rot = RigidTransform::rotationErrorDeg(r.transform, pose);
    const double tr = RigidTransform::translationError(r.transform, pose);
    if (r.ok()) {
      // Feature-level accuracy before any point refinement (noise 5 mm, 0.05 deg per feature).
      EXPECT_LT(rot, 0.1) << "run " << run << " " << r.message;
      EXPECT_LT(tr, 0.02) << "run " << run << " " << r.message;
      ok += rot < 0.1 && tr < 0.02;
    } else {
      EXPECT_FALSE(r.message.empty()) << "run " << run << ": failure without a reason";
    }
  }
  return ok;
}

}  // namespace plumb::test
