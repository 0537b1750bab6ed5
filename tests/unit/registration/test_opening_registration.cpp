#include <gtest/gtest.h>

#include <random>

#include "registration/openings/opening_registration.hpp"
#include "unit/registration/synthetic_building.hpp"

using namespace plumb;

namespace {
// Outdoor view of the building's x = 0 façade with walls `w` thick: the façade plane at
// x = -w holding the openings, plus the back walls of the rooms seen through the windows.
FeatureSet outdoorFeatures(const FeatureSet& indoor, const std::vector<test::Room>& rooms,
                           double w) {
  FeatureSet out;
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                        Z = Eigen::Vector3d::UnitZ();
  out.planes.push_back(test::makeRectPolygon({-w, 0, 0}, Y, Z, 9.0, 5.6));
  out.facades.push_back(0);
  for (auto o : indoor.openings) {
    for (auto& c : o.corners) c.x() = -w;
    o.facade = 0;
    out.openings.push_back(o);
    // The back wall of the room behind, seen through the window (a patch).
    for (const auto& r : rooms) {
      const Eigen::Vector3d c = o.corners[0];
      if (c.y() < r.min.y() || c.y() > r.max.y() || c.z() < r.min.z() || c.z() > r.max.z())
        continue;
      if (r.min.x() != 0.0) continue;
      out.planes.push_back(test::makeRectPolygon({r.max.x(), c.y() - 0.5, c.z() - 0.5}, Y, Z, 2.0, 2.0));
    }
  }
  (void)X;
  return out;
}
}  // namespace

TEST(OpeningRegistration, RecoversPoseAndWallThickness) {
  const auto rooms = test::asymmetricRooms();
  const FeatureSet indoor = test::roomFeatures(rooms);
  const double w = 0.35;
  const FeatureSet outdoor = outdoorFeatures(indoor, rooms, w);
  std::mt19937_64 rng(21);
  int ok = 0;
  for (int run = 0; run < 20; ++run) {
    const RigidTransform pose = test::randomPose(rng);
    test::Perturbation pert;
    pert.drop_fraction = 0.0;
    pert.outliers = 0;
    pert.position_noise = 0.003;
    FeatureSet source = test::perturb(indoor, pert, rng);
    source.transform(pose.inverse());
    const FeatureSet target = test::perturb(outdoor, pert, rng);
    const auto r = registerOpenings(source, target, {});
    const double rot = RigidTransform::rotationErrorDeg(r.transform, pose);
    const double tr = RigidTransform::translationError(r.transform, pose);
    if (r.ok()) {
      // Feature level: opening corners carry 3 mm noise over ~1 m windows, all in one plane;
      // the point refinement of the pipeline takes the rotation below 0.1°.
      EXPECT_LT(rot, 0.2) << run << ": " << r.message;
      EXPECT_LT(tr, 0.02) << run << ": " << r.message;
      double thickness = -1;
      for (const auto& [k, v] : r.figures)
        if (k == "wall thickness (m)") thickness = v;
      EXPECT_NEAR(thickness, w, 0.02) << r.message;
      ok += rot < 0.2 && tr < 0.02;
    }
  }
  EXPECT_GE(ok, 19);
}

TEST(OpeningRegistration, UnmeasurableThicknessIsAFailureNotAGuess) {
  const auto rooms = test::asymmetricRooms();
  const FeatureSet indoor = test::roomFeatures(rooms);
  FeatureSet outdoor = outdoorFeatures(indoor, rooms, 0.3);
  outdoor.planes.resize(1);  // façade only: nothing seen through the windows
  const auto r = registerOpenings(indoor, outdoor, {});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("ASSUMED"), std::string::npos) << r.message;
}

TEST(OpeningRegistration, NoOpeningsIsTooFewFeatures) {
  const FeatureSet indoor = test::roomFeatures(test::asymmetricRooms(), false);
  EXPECT_EQ(registerOpenings(indoor, indoor, {}).status, RegistrationStatus::TooFewFeatures);
}
