// Control points: the files (control_points.hpp), the grid scale factor from PROJ and the
// georeferencing of an adjusted network (georeference.hpp), on small exact networks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/error.hpp"
#include "registration/network/georeference.hpp"

namespace plumb {
namespace {

std::filesystem::path writeText(const std::string& name, const std::string& text) {
  const auto p = std::filesystem::temp_directory_path() / ("plumb_test_georef_" + name);
  std::ofstream(p) << text;
  return p;
}

/// The message of the FileError `f` throws ("" when it throws none).
template <class F>
std::string fileErrorOf(F&& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e.what();
  }
  return {};
}

TEST(ControlPoints, FilesReadWithHeaderCommentsAndRoles) {
  const auto c = readControlPoints(writeText(
      "c.csv", "name;E;N;H;role\n# surveyed 2026-11-02\nCP1; 651000.123; 6860000.5; 40.25\n\nCK1 651010 6860003 41 check\n"));
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].name, "CP1");
  EXPECT_DOUBLE_EQ(c[0].grid.x(), 651000.123);
  EXPECT_FALSE(c[0].check);
  EXPECT_TRUE(c[1].check);
  const auto t = readTargetObservations(writeText("t.csv", "tls-0,CP1,1.5,-2,0.25\n"));
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].station, "tls-0");
  EXPECT_EQ(t[0].line, 1u);
  EXPECT_DOUBLE_EQ(t[0].position.y(), -2.0);
}

TEST(ControlPoints, BadLinesAreErrorsNamingFileAndLine) {
  EXPECT_NE(fileErrorOf([] { readControlPoints(writeText("b1.csv", "CP1,1,2,3\nCP2,1,2\n")); }).find("line 2"),
            std::string::npos);
  EXPECT_NE(fileErrorOf([] { readControlPoints(writeText("b2.csv", "CP1,1,2,3,benchmark\n")); }).find("'control' or 'check'"),
            std::string::npos);
  EXPECT_NE(fileErrorOf([] { readControlPoints(writeText("b3.csv", "CP1,1,2,3\nCP1,4,5,6\n")); }).find("given twice"),
            std::string::npos);
  EXPECT_NE(fileErrorOf([] { readControlPoints(writeText("b4.csv", "CK1,1,2,3,check\n")); }).find("no control point"),
            std::string::npos);
  EXPECT_NE(fileErrorOf([] { readTargetObservations(writeText("b5.csv", "tls-0,CP1,1,x,3\n")); }).find("'x' is not a coordinate"),
            std::string::npos);
}

TEST(ControlPoints, UtmScaleFactorFromProj) {
  // On the central meridian of zone 32N (9 deg E, E = 500 000 m): k0 = 0.9996 exactly.
  EXPECT_NEAR(gridScaleFactor("EPSG:32632", {500000, 6860000, 0}), 0.9996, 1e-9);
  // 151 km east of it: k0 (1 + x^2 / (2 R^2)) with R ~ 6380 km gives 0.99988.
  EXPECT_NEAR(gridScaleFactor("EPSG:32632", {651000, 6860000, 0}), 0.99988, 1e-5);
  EXPECT_THROW(gridScaleFactor("EPSG:4326", {651000, 6860000, 0}), InputError);  // geographic
  EXPECT_THROW(gridScaleFactor("not a crs", {0, 0, 0}), InputError);
}

TEST(ControlPoints, GroundFrameUndoesTheScaleHorizontallyOnly) {
  const GridFrame g = makeGridFrame({{"A", {651000.4, 6860000, 40}}, {"B", {651010.4, 6860010, 42}},
                                     {"C", {0, 0, 0}, true}},
                                    0.9996);
  EXPECT_EQ(g.origin, Eigen::Vector3d(651005, 6860005, 41));  // centroid of the control, to the metre
  const Eigen::Vector3d ground = g.toGround({651105, 6860005, 51});
  EXPECT_NEAR(ground.x(), 100 / 0.9996, 1e-9);
  EXPECT_NEAR(ground.z(), 10, 1e-12);
  EXPECT_LT((g.toGrid(ground) - Eigen::Vector3d(651105, 6860005, 51)).norm(), 1e-9);
}

/// Three stations in a row (true poses: yaws and shifts in the ground frame), exact links a-b
/// and b-c, each station seeing the targets `seen[station]`, and the network adjusted with
/// station 0 held at identity (as adjustNetwork leaves it).
struct SmallNetwork {
  std::vector<RigidTransform> truth{RigidTransform::fromYaw(0.3, {0, 0, 0}), RigidTransform::fromYaw(1.2, {6, 1, 0.1}),
                                    RigidTransform::fromYaw(-2.0, {12, -1, 0.2})};
  std::vector<AdjustmentLink> links;
  NetworkAdjustment adjustment;
  ControlSurvey survey;

  SmallNetwork(const std::vector<Eigen::Vector3d>& points, const std::vector<std::vector<int>>& seen, double k) {
    for (std::size_t a = 0; a + 1 < truth.size(); ++a)
      links.push_back({a, a + 1, truth[a].inverse() * truth[a + 1], 0.001, 0.01});
    adjustment.links.resize(links.size());
    adjustment.sigma_position.assign(3, Eigen::Vector3d::Zero());
    adjustment.sigma_rotation_deg.assign(3, Eigen::Vector3d::Zero());
    for (const auto& t : truth) adjustment.poses.push_back(truth[0].inverse() * t);
    const Eigen::Vector3d g0(651000, 6860000, 40);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Eigen::Vector3d p = points[i];
      survey.points.push_back({"P" + std::to_string(i), g0 + Eigen::Vector3d(k * p.x(), k * p.y(), p.z()), i >= 3});
    }
    for (std::size_t s = 0; s < seen.size(); ++s)
      for (int i : seen[s])
        survey.observations.push_back({"s" + std::to_string(s), "P" + std::to_string(i), truth[s].inverse().apply(points[i]), 1});
    survey.grid = makeGridFrame(survey.points, k);
  }
};

TEST(Georeference, ControlPointsPlaceTheNetworkAndCheckPointsAgree) {
  const double k = 0.99988;
  SmallNetwork n({{1, 2, 1}, {7, -2, 0.5}, {13, 3, 1.5}, {4, 0, 1}, {10, 1, 2}}, {{0, 1, 3}, {1, 2, 3, 4}, {2, 4}}, k);
  const Georeference g = georeferenceNetwork(n.survey, {"s0", "s1", "s2"}, n.links, PoseGraphParams{}, n.adjustment);
  ASSERT_TRUE(g.done) << g.message;
  EXPECT_EQ(g.control_used, 3u);
  EXPECT_LT(g.control_rms, 1e-6);
  EXPECT_LT(g.check_max, 1e-6);
  // Each station: the ground frame moved to the grid origin (a translation of the true poses).
  const Eigen::Vector3d g0(651000, 6860000, 40), o = g.grid.origin;
  const RigidTransform to_registered(Eigen::Matrix3d::Identity(),
                                     Eigen::Vector3d(o.x() + (g0.x() - o.x()) / k, o.y() + (g0.y() - o.y()) / k, g0.z()));
  for (std::size_t s = 0; s < 3; ++s) {
    ASSERT_TRUE(n.adjustment.poses[s]);
    EXPECT_LT(RigidTransform::translationError(*n.adjustment.poses[s], to_registered * n.truth[s]), 1e-6) << s;
    EXPECT_LT(RigidTransform::rotationErrorDeg(*n.adjustment.poses[s], to_registered * n.truth[s]), 1e-6) << s;
  }
  // Without the scale factor the check points disagree by (1 - k) times their distance from the
  // origin: the factor is applied before the residuals are computed.
  SmallNetwork unscaled({{1, 2, 1}, {7, -2, 0.5}, {13, 3, 1.5}, {4, 0, 1}, {10, 1, 2}}, {{0, 1, 3}, {1, 2, 3, 4}, {2, 4}}, k);
  unscaled.survey.grid.scale_factor = 1.0;
  const Georeference u = georeferenceNetwork(unscaled.survey, {"s0", "s1", "s2"}, unscaled.links, PoseGraphParams{},
                                             unscaled.adjustment);
  EXPECT_GT(u.control_rms, 1e-4);
}

TEST(Georeference, ControlInALineOrUnseenDoesNotGeoreference) {
  SmallNetwork line({{1, 0, 1}, {7, 0, 1}, {13, 0, 1}}, {{0, 1}, {1, 2}, {2}}, 1.0);
  const auto before = *line.adjustment.poses[2];
  const Georeference g = georeferenceNetwork(line.survey, {"s0", "s1", "s2"}, line.links, PoseGraphParams{}, line.adjustment);
  EXPECT_FALSE(g.done);
  EXPECT_NE(g.message.find("in a line"), std::string::npos) << g.message;
  EXPECT_EQ(line.adjustment.poses[2]->matrix(), before.matrix()) << "left as it was";
  SmallNetwork unseen({{1, 2, 1}, {7, -2, 0.5}, {13, 3, 1.5}}, {{0}, {1}, {}}, 1.0);
  const Georeference u = georeferenceNetwork(unseen.survey, {"s0", "s1", "s2"}, unseen.links, PoseGraphParams{},
                                             unseen.adjustment);
  EXPECT_FALSE(u.done);
  EXPECT_NE(u.message.find("2 control point(s)"), std::string::npos) << u.message;
}

TEST(Georeference, AnObservationOfAnUnknownStationNamesTheLine) {
  SmallNetwork n({{1, 2, 1}, {7, -2, 0.5}, {13, 3, 1.5}}, {{0, 1, 2}, {}, {}}, 1.0);
  n.survey.observations[1].station = "s7";
  n.survey.observations[1].line = 12;
  n.survey.targets_file = "targets.csv";
  const std::string e = fileErrorOf([&] { checkObservations(n.survey, {"s0", "s1", "s2"}); });
  EXPECT_NE(e.find("targets.csv"), std::string::npos) << e;
  EXPECT_NE(e.find("line 12"), std::string::npos) << e;
  EXPECT_NE(e.find("'s7'"), std::string::npos) << e;
}

/// The network of SmallNetwork with its link 1-2 replaced by a wrong one (station 2 turned by a
/// half turn about station 1), the adjustment placing station 2 by it.
void plantHalfTurn(SmallNetwork& n, std::size_t control_points) {
  for (std::size_t i = 0; i < n.survey.points.size(); ++i) n.survey.points[i].check = i >= control_points;
  n.survey.grid = makeGridFrame(n.survey.points, 1.0);
  const RigidTransform wrong = RigidTransform::fromYaw(M_PI, {0, 0, 0}) * n.links[1].transform;
  n.links[1].transform = wrong;
  n.adjustment.poses[2] = *n.adjustment.poses[1] * wrong;
}

TEST(Georeference, TheControlDropsALinkItContradictsAndPlacesTheStationByItsOwnTargets) {
  // Station 2 sees three control points itself: its resection puts it where the truth is, the
  // half-turned link is dropped, and the station is settled by its own control.
  SmallNetwork n({{1, 2, 1}, {7, -2, 0.5}, {13, 3, 1.5}, {11, -3, 1}, {14, 0, 2}, {4, 0, 1}},
                 {{0, 1}, {1, 2}, {2, 3, 4}}, 1.0);
  plantHalfTurn(n, 5);
  const Georeference g = georeferenceNetwork(n.survey, {"s0", "s1", "s2"}, n.links, PoseGraphParams{}, n.adjustment);
  ASSERT_TRUE(g.done) << g.message;
  EXPECT_EQ(g.links_dropped, 1u);
  EXPECT_TRUE(n.adjustment.links[1].dropped);
  EXPECT_FALSE(n.adjustment.links[0].dropped);
  EXPECT_EQ(g.settled, (std::vector<std::size_t>{2}));
  EXPECT_TRUE(g.unplaced.empty());
  const RigidTransform to_registered(Eigen::Matrix3d::Identity(), Eigen::Vector3d(651000, 6860000, 40));
  for (std::size_t s = 0; s < 3; ++s) {
    ASSERT_TRUE(n.adjustment.poses[s]) << s;
    EXPECT_LT(RigidTransform::translationError(*n.adjustment.poses[s], to_registered * n.truth[s]), 1e-4) << s;
  }
}

TEST(Georeference, AStationTheControlCannotHoldAfterItsLinkIsDroppedIsUnplaced) {
  // Station 2 sees only one control point: once the control contradicts its only link, nothing
  // places it. Stations 0 and 1 see three points together and stay placed.
  SmallNetwork n({{1, 2, 1}, {7, -2, 0.5}, {5, 3, 1.5}, {13, 3, 1}}, {{0, 1}, {1, 2}, {3}}, 1.0);
  plantHalfTurn(n, 4);
  const Georeference g = georeferenceNetwork(n.survey, {"s0", "s1", "s2"}, n.links, PoseGraphParams{}, n.adjustment);
  ASSERT_TRUE(g.done) << g.message;
  EXPECT_EQ(g.links_dropped, 1u);
  EXPECT_EQ(g.unplaced, (std::vector<std::size_t>{2}));
  EXPECT_FALSE(n.adjustment.poses[2]) << "its pose is reset: not placed";
  EXPECT_TRUE(n.adjustment.poses[0] && n.adjustment.poses[1]);
}

TEST(Georeference, ACheckPointContradictingAStationLeavesItUnplaced) {
  // Station 2 sees no control point, only check point P3: the control cannot judge its
  // half-turned link, but the check can. The check stays out of the solve; the station it
  // contradicts is not placed, and the failure is reported with its misfit.
  SmallNetwork n({{1, 2, 1}, {7, -2, 0.5}, {5, 3, 1.5}, {13, 3, 1}}, {{0, 1}, {1, 2}, {3}}, 1.0);
  plantHalfTurn(n, 3);
  const Georeference g = georeferenceNetwork(n.survey, {"s0", "s1", "s2"}, n.links, PoseGraphParams{}, n.adjustment);
  ASSERT_TRUE(g.done) << g.message;
  EXPECT_EQ(g.links_dropped, 0u) << "check points never drop links";
  ASSERT_EQ(g.check_failures.size(), 1u);
  EXPECT_EQ(g.check_failures[0].station, 2u);
  EXPECT_EQ(g.check_failures[0].point, "P3");
  EXPECT_GT(g.check_failures[0].misfit, 1.0);
  EXPECT_EQ(g.unplaced, (std::vector<std::size_t>{2}));
  EXPECT_FALSE(n.adjustment.poses[2]);
  EXPECT_TRUE(n.adjustment.poses[0] && n.adjustment.poses[1]);
  EXPECT_EQ(g.points[3].observations, 0u) << "residuals are those of the placed stations";
}

}  // namespace
}  // namespace plumb
