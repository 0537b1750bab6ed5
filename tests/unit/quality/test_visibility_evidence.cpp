// Free-space evidence (quality/visibility_evidence.hpp) on small synthetic scenes, and the
// verdict rule (quality/visibility_verdict.hpp).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "quality/visibility_evidence.hpp"
#include "quality/quality_report.hpp"
#include "quality/structure_evidence.hpp"
#include "quality/visibility_verdict.hpp"

using namespace plumb;

namespace {

/// Points on the plane x = `x`, y and z in [-h, h], every `step` metres.
PointCloud wallAtX(double x, double h = 2.0, double step = 0.02) {
  PointCloud c;
  for (double y = -h; y <= h; y += step)
    for (double z = -h; z <= h; z += step) c.positions.push_back(Eigen::Vector3f(x, y, z));
  return c;
}

VisibilityEvidence against(const PointCloud& observer, const PointCloud& tested) {
  return freeSpaceEvidence(observer, Eigen::Vector3d::Zero(), tested, std::nullopt,
                           RigidTransform(), VisibilityParams{});
}

}  // namespace

TEST(FreeSpace, APointInFrontOfAMeasuredSurfaceContradicts) {
  const PointCloud wall = wallAtX(5.0);
  const auto e = against(wall, wallAtX(3.0, 1.0, 0.05));  // between the scanner and its wall
  ASSERT_TRUE(e.available);
  EXPECT_GT(e.tested, 500u);
  EXPECT_EQ(e.contradicting, e.tested);
  EXPECT_DOUBLE_EQ(e.contradiction_ratio, 1.0);
}

TEST(FreeSpace, APointBehindTheSurfaceIsNoEvidenceAndOneOnItIsConsistent) {
  const PointCloud wall = wallAtX(5.0);
  const auto behind = against(wall, wallAtX(7.0, 1.0, 0.05));
  EXPECT_TRUE(behind.available);
  EXPECT_EQ(behind.visible, 0u);  // occluded: the scanner could not see there
  EXPECT_EQ(behind.contradicting, 0u);
  const auto on = against(wall, wallAtX(5.03, 1.0, 0.05));  // 3 cm off: within the margin
  EXPECT_EQ(on.consistent, on.tested);
  EXPECT_EQ(on.contradicting, 0u);
  EXPECT_DOUBLE_EQ(on.expected_overlap, 1.0);
  // Outside the scanned directions (a wall 2 m high seen up to 2 m): no evidence.
  PointCloud above;
  above.positions.push_back(Eigen::Vector3f(3.0f, 0.0f, 6.0f));
  EXPECT_EQ(against(wall, above).visible, 0u);
}

TEST(FreeSpace, MissingSensorOriginsMeanNoEvidenceNotGoodEvidence) {
  const PointCloud wall = wallAtX(5.0);
  const auto e = freeSpaceEvidence(wall, std::nullopt, wallAtX(3.0), std::nullopt,
                                   RigidTransform(), VisibilityParams{});
  EXPECT_FALSE(e.available);
  EXPECT_FALSE(e.missing_reason.empty());
  EXPECT_EQ(e.tested, 0u);
  EXPECT_FALSE(e.conclusive(VisibilityParams{}));
}

TEST(FreeSpace, PerPointSensorOriginsAndTheTransformAreUsed) {
  // Two stations (x = 0 and x = 10) facing a wall at x = 5 from both sides.
  PointCloud a = wallAtX(4.95), b = wallAtX(5.05);
  a.sensor_origins.assign(a.size(), Eigen::Vector3f(0, 0, 0));
  b.sensor_origins.assign(b.size(), Eigen::Vector3f(10, 0, 0));
  PointCloud both = a;
  both.append(b);
  const PointCloud probe = wallAtX(0.0, 0.5, 0.05);  // moved to x = 2 or x = 8: seen through
  const VisibilityParams p;
  for (double x : {2.0, 8.0}) {
    const RigidTransform move(Eigen::Matrix3d::Identity(), Eigen::Vector3d(x, 0, 0));
    const auto e = freeSpaceEvidence(both, std::nullopt, probe, std::nullopt, move, p);
    EXPECT_EQ(e.stations, 2u);
    EXPECT_EQ(e.contradicting, e.tested) << x;
  }
  // Moved onto the wall: consistent.
  const RigidTransform onto(Eigen::Matrix3d::Identity(), Eigen::Vector3d(5.0, 0, 0));
  const auto e = freeSpaceEvidence(both, std::nullopt, probe, std::nullopt, onto, p);
  EXPECT_EQ(e.contradicting, 0u);
  EXPECT_EQ(e.consistent, e.tested);
}

namespace {

/// A model with one rectangle per element in the plane x = `x` (y in [y0, y1], z in [-2, 2]).
void addRectangle(BimModel& m, double x, double y0, double y1, const std::string& type) {
  const auto base = static_cast<std::uint32_t>(m.mesh.vertices.size());
  for (double y : {y0, y1})
    for (double z : {-2.0, 2.0}) m.mesh.vertices.emplace_back(x, y, z);
  m.mesh.triangles.push_back({base, base + 1, base + 2});
  m.mesh.triangles.push_back({base + 1, base + 3, base + 2});
  m.elements.push_back({type, type + " 1", ""});
  const auto e = static_cast<std::uint32_t>(m.elements.size() - 1);
  m.triangle_element.insert(m.triangle_element.end(), 2, e);
}

/// Points on x = `x`, y in [y0, y1], z in [-1, 1].
PointCloud patch(double x, double y0, double y1) {
  PointCloud c;
  for (double y = y0; y <= y1; y += 0.05)
    for (double z = -1.0; z <= 1.0; z += 0.05) c.positions.push_back(Eigen::Vector3f(x, y, z));
  return c;
}

}  // namespace

TEST(ModelRays, ARayThroughAWallContradictsOneThroughAWindowDoesNot) {
  BimModel m;
  addRectangle(m, 5.0, -3.0, 0.0, "IfcWallStandardCase");
  addRectangle(m, 5.0, 0.0, 3.0, "IfcWindow");
  const VisibilityParams p;
  const Eigen::Vector3d station = Eigen::Vector3d::Zero();
  // Points 3 m behind the wall: the laser would have stopped on it.
  const auto wall = modelRayEvidence(patch(8.0, -2.5, -0.5), station, m, RigidTransform(), p);
  ASSERT_TRUE(wall.available);
  EXPECT_GT(wall.tested, 100u);
  EXPECT_EQ(wall.contradicting, wall.tested);
  // The same behind the window: glass is seen through, no evidence either way.
  const auto window = modelRayEvidence(patch(8.0, 0.5, 2.5), station, m, RigidTransform(), p);
  EXPECT_EQ(window.contradicting, 0u);
  EXPECT_EQ(window.visible, 0u);
  // Points on the wall: consistent.
  const auto on = modelRayEvidence(patch(5.02, -2.5, -0.5), station, m, RigidTransform(), p);
  EXPECT_EQ(on.consistent, on.tested);
  // Every element counts when structural_only is off.
  VisibilityParams all = p;
  all.structural_only = false;
  const auto any = modelRayEvidence(patch(8.0, 0.5, 2.5), station, m, RigidTransform(), all);
  EXPECT_EQ(any.contradicting, any.tested);
}

TEST(ModelRays, TheMarginGrowsAtGrazingIncidence) {
  BimModel m;
  addRectangle(m, 5.0, -40.0, 40.0, "IfcWall");
  const VisibilityParams p;
  // Seen from (0, -1, 0): at y = 24 the ray meets the wall at about 78 degrees incidence, where
  // a 6 cm misalignment across the wall moves the crossing 0.3 m along the ray.
  const Eigen::Vector3d station(0, -1, 0);
  PointCloud grazing;
  grazing.positions.push_back(Eigen::Vector3f(5.06f, 24.0f, 0.0f));
  const auto g = modelRayEvidence(grazing, station, m, RigidTransform(), p);
  EXPECT_EQ(g.consistent, 1u);
  EXPECT_EQ(g.contradicting, 0u);
  // The same 0.3 m beyond the wall at normal incidence is a contradiction.
  PointCloud square;
  square.positions.push_back(Eigen::Vector3f(5.3f, -1.0f, 0.0f));
  EXPECT_EQ(modelRayEvidence(square, station, m, RigidTransform(), p).contradicting, 1u);
}

TEST(ModelRays, WithoutSensorOriginsThereIsNoEvidence) {
  BimModel m;
  addRectangle(m, 5.0, -3.0, 3.0, "IfcWall");
  const auto e = modelRayEvidence(patch(8.0, -2, 2), std::nullopt, m, RigidTransform(), {});
  EXPECT_FALSE(e.available);
  EXPECT_FALSE(e.missing_reason.empty());
}

namespace {

/// Free-space evidence of one direction with `contradiction_ratio` of 1000 visible points.
VerdictEvidence freeSpace(double contradiction_ratio, bool available = true) {
  VerdictEvidence ev;
  auto& v = ev.visibility;
  v.computed = true;
  v.source_in_target.available = available;
  v.source_in_target.missing_reason = available ? "" : "the target has no sensor origins";
  v.source_in_target.what = "source points in the target's free space";
  v.source_in_target.visible = 1000;
  v.source_in_target.tested = 2000;
  v.source_in_target.contradicting = static_cast<std::size_t>(1000 * contradiction_ratio);
  v.source_in_target.consistent = 1000 - v.source_in_target.contradicting;
  v.source_in_target.contradiction_ratio = contradiction_ratio;
  v.source_in_target.expected_overlap = 0.5;
  summarizeVisibility(v, ev.visibility_params);
  return ev;
}

/// A report that passes every rule but the free-space one: a refinement holding all six
/// directions, 40% overlap, 8 mm RMS.
QualityReport assessWith(const VerdictEvidence& ev) {
  GlobalRegistrationResult g;
  g.status = RegistrationStatus::Success;
  g.method = "planes";
  RefineResult r;
  r.rms = 0.008;
  r.overlap = 0.4;
  r.inliers = 5000;
  r.normal_matrix = Eigen::Matrix<double, 6, 6>::Identity();
  r.direction_resistance.fill(0.4);
  return assessRegistration(g, &r, {}, {}, &ev);
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST(VisibilityVerdict, ManyContradictionsFailFewWarnNoneSayWhatTheVerdictRestsOn) {
  const VisibilityParams p;
  const QualityReport fail = assessWith(freeSpace(0.6));
  EXPECT_FALSE(fail.success);
  EXPECT_EQ(fail.status, "contradicted");
  EXPECT_NE(fail.verdict.find("60.0%"), std::string::npos) << fail.verdict;
  EXPECT_NE(fail.verdict.find("another building or a wrong placement"), std::string::npos);
  EXPECT_NE(fail.verdict.find("point RMS 8 mm"), std::string::npos) << fail.verdict;

  const QualityReport warn = assessWith(freeSpace(0.5 * (p.warn_ratio + p.fail_ratio)));
  EXPECT_TRUE(warn.success);
  ASSERT_EQ(warn.warnings.size(), 1u);
  EXPECT_NE(warn.warnings[0].find("check visually"), std::string::npos);
  EXPECT_EQ(warn.verdict.find("the result can be used"), std::string::npos) << warn.verdict;
  EXPECT_EQ(occurrences(warn.verdict, "CHECK VISUALLY: 1 warning(s)"), 1u) << warn.verdict;
  EXPECT_EQ(warn.level, VerdictLevel::CheckVisually);
  EXPECT_EQ(fail.level, VerdictLevel::Failed);

  const QualityReport good = assessWith(freeSpace(0.01));
  EXPECT_TRUE(good.success);
  EXPECT_TRUE(good.warnings.empty());
  EXPECT_EQ(occurrences(good.verdict, "the result can be used"), 1u) << good.verdict;
  EXPECT_NE(good.verdict.find("Free space agrees"), std::string::npos) << good.verdict;
  EXPECT_NE(good.verdict.find("(refinement matched 40.0%)"), std::string::npos) << good.verdict;
  EXPECT_EQ(good.level, VerdictLevel::Usable);

  const QualityReport missing = assessWith(freeSpace(0.0, /*available=*/false));
  EXPECT_TRUE(missing.success);
  EXPECT_NE(missing.verdict.find("No free-space evidence (the target has no sensor origins)"),
            std::string::npos)
      << missing.verdict;

  const auto j = nlohmann::json::parse(qualityReportToJson(fail));
  EXPECT_DOUBLE_EQ(j["visibility"]["contradiction_ratio"].get<double>(), 0.6);
  EXPECT_EQ(j["visibility"]["source_in_target"]["visible"], 1000);
  EXPECT_FALSE(j["visibility"]["source_in_target"]["structure"]["available"].get<bool>());
  EXPECT_TRUE(j["visibility"]["target_in_source"]["available"] == false);
}

namespace {

/// A plane of `area` m^2 whose inliers are the cloud points first .. first + n - 1.
PlanarPolygon planeOver(std::uint32_t first, std::uint32_t n, double area) {
  PlanarPolygon pl;
  pl.area = area;
  for (std::uint32_t i = first; i < first + n; ++i) pl.inliers.push_back(i);
  return pl;
}

/// Every cloud point 0 .. n-1 tested, with the sighting `of(i)`.
template <class F>
TestedSightings sightingsOf(std::size_t n, F of, bool occluded_unexplained) {
  TestedSightings t;
  t.occluded_unexplained = occluded_unexplained;
  for (std::size_t i = 0; i < n; ++i) {
    t.index.push_back(i);
    t.sighting.push_back(of(i));
  }
  return t;
}

}  // namespace

TEST(StructureEvidence, AWallInSeenThroughSpaceIsUnexplainedScatteredContradictionsAreNot) {
  // Points 0-99: a 12 m^2 wall, all seen through; 100-399: a 36 m^2 floor, one point in ten
  // seen through (noise); 400-449: a 2 m^2 cupboard, all seen through (below the plane area).
  const std::vector<PlanarPolygon> planes = {planeOver(0, 100, 12.0), planeOver(100, 300, 36.0),
                                             planeOver(400, 50, 2.0)};
  const auto sighting = [](std::size_t i) {
    if (i < 100 || i >= 400) return Sighting::Contradicting;
    return i % 10 == 0 ? Sighting::Contradicting : Sighting::Consistent;
  };
  const VisibilityParams p;
  const auto e = structureEvidence(planes, 450, sightingsOf(450, sighting, false), p);
  ASSERT_TRUE(e.available);
  EXPECT_EQ(e.large_planes, 2u);
  EXPECT_EQ(e.judged_planes, 2u);
  EXPECT_EQ(e.unexplained_planes, 1u);
  EXPECT_DOUBLE_EQ(e.judged_area, 48.0);
  EXPECT_DOUBLE_EQ(e.unexplained_area_ratio, 12.0 / 48.0);
  EXPECT_DOUBLE_EQ(e.point_ratio, 130.0 / 400.0);
  EXPECT_DOUBLE_EQ(e.worst_plane_fraction, 1.0);
  EXPECT_DOUBLE_EQ(e.worst_plane_area, 12.0);
  EXPECT_TRUE(e.conclusive(p));
}

TEST(StructureEvidence, InFrontOfTheModelIsUnexplainedBehindAnotherScanIsNoEvidence) {
  const std::vector<PlanarPolygon> planes = {planeOver(0, 100, 12.0), planeOver(100, 100, 12.0)};
  const auto sighting = [](std::size_t i) {
    return i < 100 ? Sighting::Occluded : Sighting::Consistent;
  };
  const VisibilityParams p;
  const auto model = structureEvidence(planes, 200, sightingsOf(200, sighting, true), p);
  EXPECT_DOUBLE_EQ(model.unexplained_area_ratio, 0.5);
  const auto scan = structureEvidence(planes, 200, sightingsOf(200, sighting, false), p);
  EXPECT_EQ(scan.judged_planes, 1u);  // the occluded wall says nothing
  EXPECT_DOUBLE_EQ(scan.unexplained_area_ratio, 0.0);
  const auto none = structureEvidence({planeOver(0, 10, 1.0)}, 10, sightingsOf(10, sighting, true), p);
  EXPECT_FALSE(none.available);
  EXPECT_FALSE(none.missing_reason.empty());
}

namespace {

/// Few contradicting points (1%), but `ratio` of 200 m^2 of judged large planes unexplained.
VerdictEvidence structureOnly(double ratio) {
  VerdictEvidence ev = freeSpace(0.01);
  StructureEvidence& st = ev.visibility.source_in_target.structure;
  st.available = true;
  st.large_planes = st.judged_planes = 10;
  st.unexplained_planes = ratio > 0 ? 1 : 0;
  st.judged_area = 200.0;
  st.unexplained_area = 200.0 * ratio;
  st.unexplained_area_ratio = ratio;
  summarizeVisibility(ev.visibility, ev.visibility_params);
  return ev;
}

}  // namespace

TEST(VisibilityVerdict, UnexplainedStructureFailsOrWarnsThoughFewPointsContradict) {
  const VisibilityParams p;
  const QualityReport fail = assessWith(structureOnly(2.0 * p.structure_fail_ratio));
  EXPECT_FALSE(fail.success);
  EXPECT_EQ(fail.status, "contradicted");
  EXPECT_NE(fail.verdict.find("large planes"), std::string::npos) << fail.verdict;
  EXPECT_NE(fail.verdict.find("another building or a wrong placement"), std::string::npos);

  const QualityReport warn =
      assessWith(structureOnly(0.5 * (p.structure_warn_ratio + p.structure_fail_ratio)));
  EXPECT_TRUE(warn.success);
  EXPECT_EQ(warn.level, VerdictLevel::CheckVisually);
  ASSERT_EQ(warn.warnings.size(), 1u);
  EXPECT_EQ(warn.warnings[0].rfind("structure:", 0), 0u) << warn.warnings[0];

  const QualityReport good = assessWith(structureOnly(0.0));
  EXPECT_EQ(good.level, VerdictLevel::Usable) << good.verdict;
  EXPECT_NE(good.verdict.find("0.0% of the large planes it could judge are unexplained"),
            std::string::npos) << good.verdict;
  const auto j = nlohmann::json::parse(qualityReportToJson(fail));
  EXPECT_DOUBLE_EQ(j["visibility"]["unexplained_structure"].get<double>(),
                   2.0 * p.structure_fail_ratio);
  EXPECT_DOUBLE_EQ(j["visibility"]["source_in_target"]["structure"]["judged_area_m2"].get<double>(),
                   200.0);
}
