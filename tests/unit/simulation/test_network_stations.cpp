// Simulation support of the station network (issue 15): doorway stations, the walk order and
// the independent perturbation of every station.
#include <gtest/gtest.h>

#include "simulation/building_generator.hpp"
#include "simulation/doorway_stations.hpp"
#include "simulation/perturbation.hpp"
#include "simulation/presets.hpp"
#include "simulation/station_order.hpp"

namespace plumb {
namespace {

TEST(DoorwayStations, OneInTheMiddleOfEachInteriorDoorAtStationHeight) {
  const GeneratedBuilding b = generateBuilding(buildingPreset("two-rooms"));
  const auto doors = doorwayStations(b, 0, 1.5);
  ASSERT_EQ(doors.size(), 1u);  // the interior door; the entrance is left out
  EXPECT_NEAR(doors[0].x(), 4.0, 1e-6);  // the wall between the two 4 m rooms, mid-thickness
  EXPECT_GT(doors[0].y(), 0.0);
  EXPECT_LT(doors[0].y(), 5.0);
  EXPECT_NEAR(doors[0].z(), roomCentres(b.spec, 0, 1.5)[0].z(), 1e-9);
}

TEST(WalkOrder, EachNextStationIsTheNearestNotYetVisited) {
  const std::vector<Eigen::Vector3d> s{{0, 0, 0}, {10, 0, 0}, {1, 0, 0}, {5, 0, 0}};
  const auto w = walkOrder(s);
  ASSERT_EQ(w.size(), 4u);
  EXPECT_EQ(w[0].x(), 0);
  EXPECT_EQ(w[1].x(), 1);
  EXPECT_EQ(w[2].x(), 5);
  EXPECT_EQ(w[3].x(), 10);
}

TEST(PerturbScans, EveryScanMovesOnItsOwnAndTheTruthUndoesIt) {
  Dataset d;
  for (int i = 0; i < 3; ++i) {
    Scan s;
    s.pose = RigidTransform::fromYaw(0.0, {4.0 * i, 0, 1.5});
    d.scans.push_back(s);
  }
  const Dataset before = d;
  const auto undo = perturbScans(d, 180.0, 20.0, 7);
  ASSERT_EQ(undo.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(RigidTransform::translationError(undo[i] * d.scans[i].pose, before.scans[i].pose), 1e-9);
    EXPECT_LT(RigidTransform::rotationErrorDeg(undo[i] * d.scans[i].pose, before.scans[i].pose), 1e-9);
  }
  EXPECT_GT(RigidTransform::rotationErrorDeg(undo[0], undo[1]), 1e-3);  // independent
  Dataset again = before;
  const auto undo2 = perturbScans(again, 180.0, 20.0, 7);  // deterministic for a seed
  EXPECT_LT(RigidTransform::translationError(undo2[2], undo[2]), 1e-12);
}

}  // namespace
}  // namespace plumb
