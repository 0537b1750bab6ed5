// Every method against a model target (issue 14): one simulated TLS station in an office or
// in the corridor of the generated office floor, moved by a random pose, registered onto the
// model with `planes` (the BIM's own polygons), `openings` (its IfcWindow/IfcDoor elements
// on both wall faces) and `auto`, each within 1 cm and 0.05 deg of the truth.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cstdio>
#include <map>

#include "model/dataset.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "simulation/scan_scene.hpp"
#include "simulation/tls_scanner.hpp"

namespace plumb {
namespace {

struct Station {
  GeneratedBuilding building;
  PointCloud cloud;  ///< model frame, sensor origins
  Eigen::Vector3d position;
  FeatureSet model_features;
};

/// The office floor scanned from the centre of one plan cell (0.5 deg steps, 3 mm noise).
const Station& station(bool corridor) {
  static std::map<bool, Station> cache;
  auto it = cache.find(corridor);
  if (it != cache.end()) return it->second;
  Station s{generateBuilding(buildingPreset("office-floor")), {}, {}, {}};
  const auto centres = roomCentres(s.building.spec, 0);
  // Rows are 5 m offices, the 2 m corridor, 5 m offices: the corridor cells lie at v = 6 m.
  for (const auto& c : centres)
    if ((std::abs(c.y() - 6.0) < 0.5) == corridor) {
      s.position = c;
      break;
    }
  const ScanScene scene(s.building.model, s.building.glass_triangles);
  TlsParams tp;
  tp.azimuth_step_deg = tp.elevation_step_deg = 0.5;
  tp.noise_mm = 3.0;
  Dataset d;
  d.scans.push_back(simulateTls(scene, s.position, tp, 41));
  s.cloud = d.merged(true);
  s.cloud.removeNonFinite();
  RegistrationSide side;
  side.model = &s.building.model;
  s.model_features = extractFeatures(side, PipelineParams{}, false);
  return cache.emplace(corridor, std::move(s)).first->second;
}

struct Outcome {
  PipelineResult result;
  double rotation_deg = 0.0, translation_m = 0.0;
};

Outcome registerOnModel(const Station& s, const PipelineParams& p, const RigidTransform& pose) {
  PointCloud moved = s.cloud;
  moved.transform(pose);
  RegistrationSide src, tgt;
  src.cloud = &moved;
  tgt.model = &s.building.model;
  tgt.features = &s.model_features;
  Outcome o{registerData(src, tgt, p), 0.0, 0.0};
  const RigidTransform truth = pose.inverse();
  const Eigen::Vector3d c = moved.bounds().center();
  o.rotation_deg = RigidTransform::rotationErrorDeg(o.result.transform(), truth);
  o.translation_m = (o.result.transform().apply(c) - truth.apply(c)).norm();
  return o;
}

Outcome registerOnModel(const Station& s, const PipelineParams& p, double yaw_deg,
                        const Eigen::Vector3d& shift) {
  return registerOnModel(
      s, p, RigidTransform(Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix(), shift));
}

/// The method chain auto announced for the model target (the first such line of the log).
std::string methodChain(const PipelineResult& r) {
  for (const auto& l : r.log)
    if (l.rfind("auto: the target is a model", 0) == 0) return l;
  return "";
}

std::string logOf(const PipelineResult& r) {
  std::string s;
  for (const auto& l : r.log) s += "\n  " + l;
  return s + "\n  verdict: " + r.report.verdict;
}

TEST(BimMethods, TheModelCarriesItsPlanesFacadesAndOpenings) {
  const Station& s = station(false);
  EXPECT_GT(s.model_features.planes.size(), 20u);
  EXPECT_EQ(s.model_features.facades.size(), 4u);  // the four exterior walls
  EXPECT_EQ(s.model_features.openings.size(), s.building.truth.openings.size());
  EXPECT_FALSE(s.model_features.segments.empty());
}

class BimMethodsFromStation
    : public ::testing::TestWithParam<std::tuple<bool, RegistrationMethod>> {};

TEST_P(BimMethodsFromStation, RegistersWithinOneCentimetre) {
  const auto [corridor, method] = GetParam();
  const Station& s = station(corridor);
  PipelineParams p;
  p.method = method;
  const Outcome o = registerOnModel(s, p, 137.0, {6.0, -3.5, 0.4});
  ASSERT_TRUE(o.result.success()) << logOf(o.result);
  std::printf("%s %s: %s, %.4f deg, %.4f m\n", corridor ? "corridor" : "office",
              methodName(method).c_str(), o.result.method_used.c_str(), o.rotation_deg,
              o.translation_m);
  if (method != RegistrationMethod::Auto) EXPECT_EQ(o.result.method_used, methodName(method));
  EXPECT_LT(o.rotation_deg, 0.05) << logOf(o.result);
  EXPECT_LT(o.translation_m, 0.01) << logOf(o.result);
}

TEST(BimMethods, AutoFallsBackToTheModelPlanesWhenEdgesFindNoPlacement) {
  const Station& s = station(true);
  PipelineParams p;
  p.segments.min_matched_segments = 1e6;  // the edges find no placement (as in a bare corridor)
  const Outcome o = registerOnModel(s, p, -71.0, {-4.0, 9.0, -0.3});
  ASSERT_TRUE(o.result.success()) << logOf(o.result);
  EXPECT_NE(o.result.method_used, "segments");
  EXPECT_LT(o.rotation_deg, 0.05) << logOf(o.result);
  EXPECT_LT(o.translation_m, 0.01) << logOf(o.result);
  std::printf("corridor auto without edges: %s, %.4f deg, %.4f m\n", o.result.method_used.c_str(),
              o.rotation_deg, o.translation_m);
}

// A source that is not levelled is levelled first (orientation_search.cpp); the levelled
// features must carry the openings again (they depend on the vertical), so that auto announces
// the same methods as for a levelled source: segments, then the model's planes cross-checked
// with its openings. (Before the fix a tilted source lost its openings: "... then planes".)
// Whether the chain then ends in the same method is not asserted: on this station the planes
// of the source levelled from its own normals score ambiguously (gap 3.4 %), and a model
// target stops at an ambiguous step, before openings (reported in the issue).
TEST(BimMethods, ATiltedSourceReachesTheSameMethodsAsALevelledOne) {
  const Station& s = station(false);
  PipelineParams p;
  p.segments.min_matched_segments = 1e6;  // the edges find no placement: the fallbacks run
  const Outcome levelled = registerOnModel(s, p, -71.0, {-4.0, 9.0, -0.3});
  const RigidTransform tilt(Eigen::AngleAxisd(-71.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(25.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()).toRotationMatrix(),
                            Eigen::Vector3d(-4.0, 9.0, -0.3));
  const Outcome tilted = registerOnModel(s, p, tilt);
  const std::string chain = methodChain(levelled.result);
  EXPECT_NE(chain.find("cross-checked with openings"), std::string::npos) << logOf(levelled.result);
  EXPECT_EQ(methodChain(tilted.result), chain) << logOf(tilted.result);
  EXPECT_EQ(levelled.result.method_used, "openings") << logOf(levelled.result);
  std::printf("levelled: %s; tilted: %s (%s)\n", levelled.result.method_used.c_str(),
              tilted.result.method_used.c_str(), tilted.result.report.status.c_str());
}

INSTANTIATE_TEST_SUITE_P(
    OfficeAndCorridor, BimMethodsFromStation,
    ::testing::Combine(::testing::Bool(),
                       ::testing::Values(RegistrationMethod::Planes, RegistrationMethod::Openings,
                                         RegistrationMethod::Auto)),
    [](const auto& info) {
      return std::string(std::get<0>(info.param) ? "Corridor" : "Office") + "_" +
             methodName(std::get<1>(info.param));
    });

}  // namespace
}  // namespace plumb
