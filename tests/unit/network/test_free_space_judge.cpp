// The free-space judge (free_space_judge.hpp, docs/NETWORK.md "The free space judges ambiguous
// stations"): two rooms of the same size side by side, one piece of furniture each, scanned by
// the simulator; station 1 (a corner of room 0) is the ambiguous one, and its twin placement is
// the same corner of room 1. The judge must settle it when it is placed right and its twin is
// the alternative, choose the right placement when the twin is the adopted one, and keep it
// ambiguous when two placements are clean or when no placed station sees where it is placed.
#include <gtest/gtest.h>

#include "registration/network/free_space_judge.hpp"
#include <nlohmann/json.hpp>

#include "registration/network/network_registration.hpp"
#include "registration/network/network_report.hpp"
#include "registration/network/unchecked_stations.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/survey.hpp"

namespace plumb {
namespace {

struct TwinRooms {
  BimModel model;
  std::vector<Station> stations;
  std::vector<std::optional<RigidTransform>> truth;  ///< station -> model frame
  RigidTransform twin;  ///< room 0 -> room 1 (the shift between the room centres)
};

/// Stations: 0 room 0 centre, 1 a corner of room 0, 2 room 1 centre.
TwinRooms scanTwinRooms() {
  BuildingSpec spec;
  spec.name = "twin-rooms";
  spec.column_widths = {4.0, 4.0};
  spec.row_depths = {5.0};
  spec.furniture_per_room = 1;
  spec.seed = 3;
  const GeneratedBuilding b = generateBuilding(spec);
  const auto centres = roomCentres(spec, 0);
  SurveyRequest r;
  r.tls_stations = {centres[0], centres[0] + Eigen::Vector3d(-1.1, -1.4, 0), centres[1]};
  r.tls.azimuth_step_deg = r.tls.elevation_step_deg = 0.5;
  const SimulatedSurvey survey = simulateSurvey(b.model, b.glass_triangles, {}, r);
  TwinRooms t;
  t.model = b.model;
  t.stations = stationsOf(survey.datasets[0].data, "twin.e57");
  for (const auto& p : survey.datasets[0].true_poses) t.truth.push_back(p);
  t.twin = RigidTransform(Eigen::Matrix3d::Identity(), centres[1] - centres[0]);
  return t;
}

const TwinRooms& twinRooms() {
  static const TwinRooms t = scanTwinRooms();
  return t;
}

/// The three stations, then the model node (index 3).
const std::vector<Station>& stationsAndModel() {
  static const std::vector<Station> st = [] {
    std::vector<Station> s = twinRooms().stations;
    s.push_back(modelStation(twinRooms().model, "twin.ifc"));
    return s;
  }();
  return st;
}

/// Station 1 moved into room 1 (its twin placement) in a copy of `poses`.
PlacementHypothesis twinOf(const std::vector<std::optional<RigidTransform>>& poses, const RigidTransform& move,
                           const std::string& source) {
  PlacementHypothesis h{source, poses, {1}};
  h.poses[1] = move * *poses[1];
  return h;
}

TEST(FreeSpaceJudge, SettlesARightPlacementWhoseTwinTheFurnitureRefutes) {
  const TwinRooms& t = twinRooms();
  const auto j = judgeByFreeSpace(t.stations, t.truth, {1}, {0, 2}, {twinOf(t.truth, t.twin, "the twin")},
                                  FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_TRUE(j.ran);
  ASSERT_EQ(j.stations.size(), 1u);
  const StationJudgement& s = j.stations[0];
  ASSERT_EQ(s.placements.size(), 2u);  // adopted, the twin
  const JudgedPlacement &adopted = s.placements[0], &twin = s.placements[1];
  EXPECT_TRUE(adopted.clean) << s.why;
  EXPECT_GE(adopted.tally.visible, 2000u);
  EXPECT_LE(adopted.tally.ratio(), FreeSpaceJudgeParams{}.clean_ratio) << s.why;
  EXPECT_TRUE(twin.judged);
  EXPECT_GE(twin.tally.ratio(), FreeSpaceJudgeParams{}.refute_ratio) << s.why;
  EXPECT_GE(twin.tally.ratio(), 3 * adopted.tally.ratio());
  ASSERT_TRUE(s.decided);
  EXPECT_EQ(*s.decided, 0u);
  EXPECT_TRUE(s.settled) << s.why;
  EXPECT_EQ(j.settled, std::vector<std::size_t>{1});
  EXPECT_TRUE(j.chosen.empty());
  EXPECT_NE(s.why.find("settled by the free space"), std::string::npos) << s.why;
}

TEST(FreeSpaceJudge, ChoosesTheRightPlacementOverAnAdoptedTwin) {
  const TwinRooms& t = twinRooms();
  auto adopted = t.truth;  // the links placed station 1 in room 1, where its twin corner is
  adopted[1] = t.twin * *t.truth[1];
  auto truth = twinOf(adopted, t.twin.inverse(), "the BIM's placement 2");
  truth.bim_candidate = 1;
  const auto j = judgeByFreeSpace(t.stations, adopted, {1}, {0, 2}, {truth}, FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  const StationJudgement& s = j.stations[0];
  EXPECT_FALSE(s.placements[0].clean);
  EXPECT_GT(s.placements[0].tally.ratio(), FreeSpaceJudgeParams{}.refute_ratio);
  EXPECT_FALSE(s.settled);
  EXPECT_TRUE(j.settled.empty());
  ASSERT_TRUE(s.decided) << s.why;
  EXPECT_EQ(*s.decided, 1u);
  ASSERT_EQ(j.chosen.size(), 1u);
  EXPECT_EQ(j.chosen[0].first, 1u);
  EXPECT_EQ(j.chosen[0].second.bim_candidate, std::optional<std::size_t>(1));
  EXPECT_NE(s.why.find("placed by the free space at the BIM's placement 2"), std::string::npos) << s.why;
}

TEST(FreeSpaceJudge, OfHypothesesPlacingTheStationAlikeTheOneMovingFewestIsTaken) {
  // Adopted: station 1 in its twin. Two hypotheses put it back at the truth, first a dropped
  // link taken as true that also moves station 2 (by a few centimetres, so that both tallies
  // are the same), then a BIM copy moving station 1 alone. Only station 1 was judged: the BIM
  // copy is taken, not the link with its side effects.
  const TwinRooms& t = twinRooms();
  auto adopted = t.truth;
  adopted[1] = t.twin * *t.truth[1];
  auto link = twinOf(adopted, t.twin.inverse(), "the link 0 - 1 taken as true");
  link.moved = {1, 2};
  link.poses[2] = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.03, 0, 0)) * *t.truth[2];
  link.link = 7;
  auto copy = twinOf(adopted, t.twin.inverse(), "the BIM's placement 2");
  copy.bim_candidate = 1;
  const auto j = judgeByFreeSpace(t.stations, adopted, {1}, {0, 2}, {link, copy}, FreeSpaceJudgeParams{},
                                  PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  EXPECT_TRUE(j.stations[0].placements[1].clean && j.stations[0].placements[2].clean) << j.stations[0].why;
  ASSERT_EQ(j.chosen.size(), 1u) << j.stations[0].why;
  EXPECT_EQ(j.chosen[0].second.source, "the BIM's placement 2");
  EXPECT_FALSE(j.chosen[0].second.link);
  EXPECT_NE(j.stations[0].why.find("at the BIM's placement 2"), std::string::npos) << j.stations[0].why;
}

TEST(FreeSpaceJudge, TwoCleanPlacementsDecideNothing) {
  const TwinRooms& t = twinRooms();
  // 8 cm off: another placement (beyond the 5 cm drop threshold), yet within the free-space
  // margin (10 cm + 1 % of the range): the free space cannot refute it.
  auto off = twinOf(t.truth, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.08, 0, 0)), "a copy");
  const auto j = judgeByFreeSpace(t.stations, t.truth, {1}, {0, 2}, {off}, FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  EXPECT_TRUE(j.stations[0].placements[1].clean) << j.stations[0].why;
  EXPECT_FALSE(j.stations[0].decided);
  EXPECT_FALSE(j.stations[0].settled);
  EXPECT_TRUE(j.settled.empty() && j.chosen.empty());
  EXPECT_NE(j.stations[0].why.find("does not tell"), std::string::npos) << j.stations[0].why;
}

TEST(FreeSpaceJudge, TheSamePlacementOfferedAgainIsNoCompetitor) {
  const TwinRooms& t = twinRooms();
  // A BIM copy 1 mm from the adopted placement, beside the twin: the station is settled.
  auto same = twinOf(t.truth, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.001, 0, 0)), "copy 1");
  same.bim_candidate = 0;
  const auto j = judgeByFreeSpace(t.stations, t.truth, {1}, {0, 2}, {same, twinOf(t.truth, t.twin, "the twin")},
                                  FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  EXPECT_TRUE(j.stations[0].settled) << j.stations[0].why;
  EXPECT_EQ(j.settled, std::vector<std::size_t>{1});
  EXPECT_TRUE(j.chosen.empty()) << "the adopted placement is kept, nothing is taken as true";
  EXPECT_NE(j.stations[0].why.find("refutes 1 placement(s) elsewhere"), std::string::npos) << j.stations[0].why;
}

TEST(FreeSpaceJudge, NoPlacedStationSeesIt) {
  const TwinRooms& t = twinRooms();
  auto adopted = t.truth;  // station 1 placed 500 m east, where no station saw
  adopted[1] = RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(500, 0, 0)) * *t.truth[1];
  const auto j = judgeByFreeSpace(t.stations, adopted, {1}, {0, 2}, {}, FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  EXPECT_FALSE(j.stations[0].settled);
  EXPECT_FALSE(j.stations[0].placements[0].judged);
  EXPECT_EQ(j.stations[0].placements[0].tally.visible, 0u);
  EXPECT_NE(j.stations[0].why.find("see too little"), std::string::npos) << j.stations[0].why;
}

TEST(FreeSpaceJudge, OnlyConfirmedStationsObserve) {
  const TwinRooms& t = twinRooms();  // stations 0 and 2 placed, but nothing outside the links confirms them
  const auto j = judgeByFreeSpace(t.stations, t.truth, {1}, {}, {twinOf(t.truth, t.twin, "the twin")},
                                  FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{});
  ASSERT_EQ(j.stations.size(), 1u);
  EXPECT_FALSE(j.stations[0].placements[0].judged);
  EXPECT_FALSE(j.stations[0].settled);
  EXPECT_TRUE(j.settled.empty() && j.chosen.empty());
}

/// A link b -> a at `b_in_a`, accepted unless `accepted` is false, weighted 1 mm / 0.01 deg.
Link handLink(std::size_t a, std::size_t b, const RigidTransform& b_in_a, const std::string& reason,
              bool accepted = true) {
  Link l;
  l.a = a, l.b = b, l.transform = b_in_a, l.reason = reason;
  l.registered = l.accepted = accepted;
  l.level = accepted ? VerdictLevel::Usable : VerdictLevel::Failed;
  l.status = accepted ? "success" : "ambiguous";
  l.sigma_translation = 0.001, l.sigma_rotation_deg = 0.01;
  return l;
}

TEST(FreeSpaceJudge, TheNetworkTakesTheBimCopyTheFreeSpaceChoseAndDropsTheTwinLink) {
  // Stations 0 and 2 registered onto the model; station 1 ambiguous on it (its copies: the
  // truth and the twin corner of room 1), placed by one wrong link onto station 0 (the twin).
  const TwinRooms& t = twinRooms();
  const std::vector<Station>& st = stationsAndModel();
  const std::size_t model = 3;
  const RigidTransform twin1 = t.twin * *t.truth[1];
  std::vector<Link> links{handLink(0, model, t.truth[0]->inverse(), "model"),
                          handLink(2, model, t.truth[2]->inverse(), "model"),
                          handLink(1, model, RigidTransform(), "model", false),
                          handLink(0, 1, t.truth[0]->inverse() * twin1, "sequence")};
  links[2].model_candidates = {twin1, *t.truth[1]};  // the pipeline's chosen one first: the twin
  const NetworkResult r = adjustRegisteredLinks(st, links, model, NetworkParams{});
  ASSERT_TRUE(r.adjustment.poses[1]);
  EXPECT_TRUE(r.placed(1)) << (r.free_space.stations.empty() ? "" : r.free_space.stations[0].why);
  EXPECT_LT(RigidTransform::translationError(*r.adjustment.poses[1], *t.truth[1]), 0.001);
  EXPECT_EQ(r.links[2].decision, kFreeSpaceDecision);
  EXPECT_TRUE(r.links[2].accepted);
  bool twin_dropped = false;
  for (std::size_t k = 0; k < r.adjusted.size(); ++k)
    if (r.adjusted[k] == 3) twin_dropped = r.adjustment.links[k].dropped;
  EXPECT_TRUE(twin_dropped) << "the wrong link onto station 0 contradicts the copy the free space chose";
  EXPECT_TRUE(r.complete());
  // Without the judge, station 1 stays ambiguous at the twin placement.
  NetworkParams off;
  off.free_space.enabled = false;
  const NetworkResult before = adjustRegisteredLinks(st, links, model, off);
  EXPECT_TRUE(before.isAmbiguous(1));
  EXPECT_GT(RigidTransform::translationError(*before.adjustment.poses[1], *t.truth[1]), 3.0);
}

/// Stations 0 and 2 on the model and joined by a link (a loop through the model: both
/// confirmed), station 1 onto the model by a usable link at `one_on_model` (its only link to
/// the model), plus `more` links.
NetworkResult withStationOneOnTheModel(const RigidTransform& one_on_model, std::vector<Link> more = {},
                                       NetworkParams params = {}) {
  const TwinRooms& t = twinRooms();
  const std::vector<Station>& st = stationsAndModel();
  const std::size_t model = 3;
  std::vector<Link> links{handLink(0, model, t.truth[0]->inverse(), "model"),
                          handLink(2, model, t.truth[2]->inverse(), "model"),
                          handLink(0, 2, t.truth[0]->inverse() * *t.truth[2], "layout"),
                          handLink(1, model, one_on_model.inverse(), "model")};
  links.insert(links.end(), more.begin(), more.end());
  return adjustRegisteredLinks(st, links, model, params);
}

TEST(FreeSpaceJudge, AStationOneUnconfirmedLinkPlacesIsJudgedAndObservesOnceSettled) {
  const TwinRooms& t = twinRooms();
  const NetworkResult r = withStationOneOnTheModel(*t.truth[1]);
  EXPECT_EQ(r.unchecked, std::vector<std::size_t>{1}) << "0 and 2 close a loop through the model";
  EXPECT_TRUE(r.placed(1));
  EXPECT_EQ(r.free_space.settled, std::vector<std::size_t>{1});
  EXPECT_TRUE(r.contested.empty());
  EXPECT_TRUE(r.complete());
  const std::vector<Station>& st = stationsAndModel();
  const auto report = networkReportToJson(r, st);
  EXPECT_TRUE(report["stations"][1].value("unchecked", false));
  EXPECT_EQ(report["network"]["unchecked"], nlohmann::json::array({st[1].name}));
  EXPECT_NE(networkReportToText(r, st).find("one unchecked link placed it, settled by the free space"),
            std::string::npos);
}

TEST(FreeSpaceJudge, AUsableLinkToTheBimPlacingAStationInTheTwinRoomIsContested) {
  // The BIM link is usable, nothing checks it, and it puts station 1 in room 1, where the
  // confirmed stations saw through its furniture: ambiguous, not placed.
  const TwinRooms& t = twinRooms();
  const NetworkResult r = withStationOneOnTheModel(t.twin * *t.truth[1]);
  EXPECT_EQ(r.unchecked, std::vector<std::size_t>{1});
  EXPECT_EQ(r.contested, std::vector<std::size_t>{1});
  EXPECT_TRUE(r.isAmbiguous(1));
  EXPECT_FALSE(r.placed(1));
  EXPECT_FALSE(r.complete());
  ASSERT_EQ(r.free_space.stations.size(), 1u);
  EXPECT_FALSE(r.free_space.stations[0].placements[0].clean) << r.free_space.stations[0].why;
  const std::vector<Station>& st = stationsAndModel();
  const auto report = networkReportToJson(r, st);
  EXPECT_EQ(report["network"]["contested"], nlohmann::json::array({st[1].name}));
  EXPECT_EQ(report["stations"][1]["ambiguous_why"].get<std::string>().rfind("contested:", 0), 0u);
  EXPECT_EQ(networkExitCode(r), 2);
  EXPECT_NE(networkReportToText(r, st).find("AMBIGUOUS (contested"), std::string::npos);
  // Without the judge, the same links place it there.
  NetworkParams off;
  off.free_space.enabled = false;
  const NetworkResult before = withStationOneOnTheModel(t.twin * *t.truth[1], {}, off);
  EXPECT_TRUE(before.placed(1));
  EXPECT_GT(RigidTransform::translationError(*before.adjustment.poses[1], *t.truth[1]), 3.0);
}

TEST(FreeSpaceJudge, AnAmbiguousLinkOfTheUncheckedStationOffersTheRightPlacement) {
  // Station 1's link onto station 0 was ambiguous: its chosen placement the twin, its competing
  // one the truth. The free space chooses the truth; that link is taken as true at it and the
  // wrong link to the BIM is dropped.
  const TwinRooms& t = twinRooms();
  const RigidTransform twin1 = t.twin * *t.truth[1];
  Link ambiguous = handLink(0, 1, t.truth[0]->inverse() * twin1, "layout", false);
  ambiguous.alternatives.push_back({t.truth[0]->inverse() * *t.truth[1], "competing", 0.9, 0.002});
  const NetworkResult r = withStationOneOnTheModel(twin1, {ambiguous});
  ASSERT_TRUE(r.adjustment.poses[1]);
  EXPECT_TRUE(r.placed(1));
  EXPECT_LT(RigidTransform::translationError(*r.adjustment.poses[1], *t.truth[1]), 0.001);
  EXPECT_EQ(r.links[4].decision, kFreeSpaceDecision);
  EXPECT_TRUE(r.links[4].accepted);
  EXPECT_LT(RigidTransform::translationError(r.links[4].transform, ambiguous.alternatives[0].transform), 1e-9);
  bool bim_dropped = false;
  for (std::size_t k = 0; k < r.adjusted.size(); ++k)
    if (r.adjusted[k] == 3) bim_dropped = r.adjustment.links[k].dropped;
  EXPECT_TRUE(bim_dropped) << "the BIM link contradicts the placement the free space chose";
  EXPECT_TRUE(r.complete());
}

TEST(FreeSpaceJudge, UncheckedStationsAreThoseOneBridgePlaces) {
  const TwinRooms& t = twinRooms();
  const NetworkResult r = withStationOneOnTheModel(*t.truth[1]);
  EXPECT_EQ(uncheckedStations(stationsAndModel(), r), std::vector<std::size_t>{1});
  // The station settled is confirmed now: the report says how it was placed.
  EXPECT_NE(r.free_space.stations.at(0).why.find("settled by the free space"), std::string::npos);
}

TEST(FreeSpaceJudge, DisabledOrNothingAmbiguousJudgesNothing) {
  const TwinRooms& t = twinRooms();
  FreeSpaceJudgeParams off;
  off.enabled = false;
  EXPECT_FALSE(judgeByFreeSpace(t.stations, t.truth, {1}, {0, 2}, {}, off, PoseGraphParams{}, VisibilityParams{}).ran);
  EXPECT_FALSE(judgeByFreeSpace(t.stations, t.truth, {}, {0, 2}, {}, FreeSpaceJudgeParams{}, PoseGraphParams{}, VisibilityParams{}).ran);
}

}  // namespace
}  // namespace plumb
