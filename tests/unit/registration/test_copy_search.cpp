// The search for copies of a placed source in the target (copy_search.hpp): a room that the
// target holds twice (the second copy turned by a half turn, as in a mirrored duplex) is found
// from a placement in the first copy, exactly turned and within a cell; a target holding the
// room once, or only rooms of other sizes, gives no copy.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <random>

#include "registration/auto/copy_search.hpp"

using namespace plumb;

namespace {

/// Points on the floor, ceiling and walls of a w x d x h room (corner at the origin), on a
/// `step` grid, plus a cupboard in one corner so that the room is not its own half turn.
std::vector<Eigen::Vector3d> roomPoints(double w, double d, double h, double step) {
  std::vector<Eigen::Vector3d> out;
  for (double x = 0; x <= w; x += step)
    for (double y = 0; y <= d; y += step) {
      out.emplace_back(x, y, 0.0);
      out.emplace_back(x, y, h);
    }
  for (double z = 0; z <= h; z += step) {
    for (double x = 0; x <= w; x += step) {
      out.emplace_back(x, 0.0, z);
      out.emplace_back(x, d, z);
    }
    for (double y = 0; y <= d; y += step) {
      out.emplace_back(0.0, y, z);
      out.emplace_back(w, y, z);
    }
  }
  for (double y = 0; y <= 1.0; y += step)  // cupboard front, 0.6 m from the x = 0 wall
    for (double z = 0; z <= 2.0; z += step) out.emplace_back(0.6, y, z);
  return out;
}

void append(PointCloud& c, const std::vector<Eigen::Vector3d>& pts, const RigidTransform& t) {
  for (const auto& p : pts) c.positions.push_back(t.apply(p).cast<float>());
}

const RigidTransform kFirst = RigidTransform::fromYaw(0.0, {10.0, 0.0, 0.0});
const RigidTransform kSecond = RigidTransform::fromYaw(M_PI, {24.0, 5.0, 0.0});  // half turn
/// The scanner's own frame: the room as a station delivers it.
const RigidTransform kStation = RigidTransform::fromYaw(0.7, {-1.3, 2.1, -1.5});

PointCloud sourceScan() {
  PointCloud s;
  append(s, roomPoints(4.0, 5.0, 2.6, 0.05), kStation);
  return s;
}

double shiftAt(const RigidTransform& a, const RigidTransform& b, const Eigen::Vector3d& x) {
  return (a.apply(x) - b.apply(x)).norm();
}

}  // namespace

TEST(CopySearch, FindsTheHalfTurnedCopyOfAPlacedRoom) {
  PointCloud target;
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kFirst);
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kSecond);
  append(target, roomPoints(3.0, 3.0, 2.6, 0.05), RigidTransform::fromYaw(0.0, {0.0, 12.0, 0.0}));
  const PointCloud source = sourceScan();
  const RigidTransform chosen = kFirst * kStation.inverse();
  const CopySearchResult r = findCopies(source, target, chosen, CopySearchParams{});
  EXPECT_GT(r.chosen_fraction, 0.95) << r.message;
  ASSERT_FALSE(r.copies.empty()) << r.message;
  const RigidTransform truth = kSecond * kStation.inverse();
  const Eigen::Vector3d centre = source.bounds().center();
  // The best copy is the second room: exactly turned, shifted to within one fine cell.
  EXPECT_LT(RigidTransform::rotationErrorDeg(r.copies[0].transform, truth), 1e-6) << r.message;
  EXPECT_LT(shiftAt(r.copies[0].transform, truth, centre), 0.1) << r.copies[0].label;
  // No copy is the chosen placement itself, and none lies in the smaller room.
  for (const Hypothesis& c : r.copies) {
    EXPECT_GT(shiftAt(c.transform, chosen, centre), 1.0) << c.label;
    const Eigen::Vector3d at = c.transform.apply(centre);
    EXPECT_FALSE(at.y() > 11.0 && at.x() < 4.0) << c.label;
  }
}

TEST(CopySearch, NoCopyInATargetHoldingTheRoomOnce) {
  PointCloud target;
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kFirst);
  append(target, roomPoints(3.0, 3.0, 2.6, 0.05), RigidTransform::fromYaw(0.0, {0.0, 12.0, 0.0}));
  const PointCloud source = sourceScan();
  const CopySearchResult r =
      findCopies(source, target, kFirst * kStation.inverse(), CopySearchParams{});
  EXPECT_TRUE(r.copies.empty()) << r.message;
  EXPECT_FALSE(r.skipped);
}

TEST(CopySearch, SkippedWhenTheChosenPlacementExplainsLittle) {
  PointCloud target;
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kFirst);
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kSecond);
  const PointCloud source = sourceScan();
  // Placed 30 m away from everything: nothing explained, no search.
  const RigidTransform nowhere = RigidTransform::fromYaw(0.0, {0.0, 0.0, 30.0}) * kFirst *
                                 kStation.inverse();
  const CopySearchResult r = findCopies(source, target, nowhere, CopySearchParams{});
  EXPECT_TRUE(r.skipped) << r.message;
  EXPECT_TRUE(r.copies.empty());
}

// A room placed upside down (its floor on the ceiling: a scan whose up direction was only
// estimated) explains all but its cupboard; its upright self is not among the quarter turns
// about the vertical, only among the upside-down turns (CopySearchParams::upside_down).
TEST(CopySearch, FindsTheUprightRoomFromAnUpsideDownPlacementOnlyWhenAsked) {
  PointCloud target;
  append(target, roomPoints(4.0, 5.0, 2.6, 0.05), kFirst);
  const PointCloud source = sourceScan();
  const RigidTransform truth = kFirst * kStation.inverse();
  const Eigen::Vector3d centre = kFirst.apply({2.0, 2.5, 1.3});
  const Eigen::Matrix3d flip = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const RigidTransform chosen = RigidTransform(flip, centre - flip * centre) * truth;
  const Eigen::Vector3d at = source.bounds().center();
  const auto findsTruth = [&](const CopySearchResult& r) {
    return std::any_of(r.copies.begin(), r.copies.end(), [&](const Hypothesis& c) {
      return RigidTransform::rotationErrorDeg(c.transform, truth) < 1e-6 &&
             shiftAt(c.transform, truth, at) < 0.1;
    });
  };
  const CopySearchResult upright = findCopies(source, target, chosen, CopySearchParams{});
  EXPECT_FALSE(findsTruth(upright)) << upright.message;
  CopySearchParams p;
  p.upside_down = true;
  const CopySearchResult both = findCopies(source, target, chosen, p);
  EXPECT_TRUE(findsTruth(both)) << both.message;
  for (const Hypothesis& c : both.copies)
    if (RigidTransform::rotationErrorDeg(c.transform, truth) < 1e-6)
      EXPECT_NE(c.label.find("upside down"), std::string::npos) << c.label;
}
