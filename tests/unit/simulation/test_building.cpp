// Parametric buildings: element types and counts, exact sharp edges, truth planes, JSON.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>

#include "common/error.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/ground_truth_json.hpp"
#include "simulation/presets.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

TEST(Building, EveryPresetGeneratesATypedModel) {
  const auto names = buildingPresetNames();
  ASSERT_GE(names.size(), 5u);
  for (const auto& name : names) {
    if (name == "big-office") continue;  // benchmarks only
    const auto b = generateBuilding(buildingPreset(name));
    SCOPED_TRACE(name);
    EXPECT_GT(b.model.mesh.triangleCount(), 100u);
    ASSERT_EQ(b.model.triangle_element.size(), b.model.mesh.triangleCount());
    std::set<std::uint32_t> used(b.model.triangle_element.begin(), b.model.triangle_element.end());
    EXPECT_EQ(used.size(), b.model.elements.size()) << "every element owns triangles";
    for (const auto& e : b.model.elements)
      EXPECT_TRUE(e.type == "IfcWall" || e.type == "IfcSlab" || e.type == "IfcWindow" ||
                  e.type == "IfcDoor" || e.type == "IfcFurnishingElement") << e.type;
    EXPECT_GT(b.model.elementCountOfType("IfcWindow"), 0u);
    EXPECT_GT(b.model.elementCountOfType("IfcDoor"), 0u);
    EXPECT_FALSE(buildingPresetDescription(name).empty());
  }
  EXPECT_THROW(buildingPreset("castle"), InputError);
}

TEST(Building, TwoRoomsCounts) {
  const auto b = generateBuilding(buildingPreset("two-rooms"));
  // 2 x 1 rooms: u-lines 0,1,2 (3 segments) + v-lines 0,1 (2 x 2 segments) = 7 walls.
  EXPECT_EQ(b.model.elementCountOfType("IfcWall"), 7u);
  EXPECT_EQ(b.model.elementCountOfType("IfcSlab"), 2u);  // ground + roof
  EXPECT_EQ(b.model.elementCountOfType("IfcDoor"), 2u);  // entrance + interior door
  // Windows: one per exterior segment except the entrance one: 6 - 1 = 5.
  EXPECT_EQ(b.model.elementCountOfType("IfcWindow"), 5u);
  // Every opening is described on both faces of its wall.
  EXPECT_EQ(b.truth.openings.size(), 2u * 7u);
  // Bounds: walls centred on plan lines 0..8 x 0..5 with 0.4 m exterior walls.
  const Bounds bb = b.model.mesh.bounds();
  EXPECT_NEAR(bb.min.x(), -0.2, 1e-9);
  EXPECT_NEAR(bb.max.x(), 8.2, 1e-9);
  EXPECT_NEAR(bb.max.y(), 5.2, 1e-9);
  EXPECT_NEAR(bb.max.z(), 3.25, 1e-9);
  ASSERT_EQ(b.truth.footprint.size(), 4u);
}

TEST(Building, LAndUFootprints) {
  EXPECT_EQ(generateBuilding(buildingPreset("l-shaped")).truth.footprint.size(), 6u);
  EXPECT_EQ(generateBuilding(buildingPreset("u-shaped")).truth.footprint.size(), 8u);
}

// Mesh edges (by vertex index pair) whose adjacent triangles are not coplanar, computed here
// independently from the triangles, must be exactly covered by the truth's sharp edges.
TEST(Building, SharpEdgesAreExactlyTheMeshSharpEdges) {
  for (const char* name : {"two-rooms", "house", "l-shaped", "non-manhattan"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const auto& m = b.model.mesh;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
      if (b.glass_triangles[t]) continue;
      for (int k = 0; k < 3; ++k) {
        auto a = m.triangles[t][static_cast<std::size_t>(k)], c = m.triangles[t][static_cast<std::size_t>((k + 1) % 3)];
        edges[{std::min(a, c), std::max(a, c)}].push_back(t);
      }
    }
    double sharp_length = 0.0;
    std::size_t boundary = 0;
    for (const auto& [e, tris] : edges) {
      if (tris.size() == 1) ++boundary;
      bool sharp = tris.size() != 2;
      if (tris.size() == 2) sharp = m.triangleNormal(tris[0]).dot(m.triangleNormal(tris[1])) < 1.0 - 1e-9;
      if (!sharp) continue;
      const Eigen::Vector3d p = m.vertices[e.first], q = m.vertices[e.second];
      sharp_length += (q - p).norm();
      bool covered = false;
      for (const auto& s : b.truth.sharp_edges) {
        const Eigen::Vector3d d = s.direction();
        auto off = [&](const Eigen::Vector3d& x) { return ((x - s.a) - (x - s.a).dot(d) * d).norm(); };
        auto along = [&](const Eigen::Vector3d& x) { return (x - s.a).dot(d); };
        if (off(p) < 1e-9 && off(q) < 1e-9 && along(p) > -1e-9 && along(q) > -1e-9 &&
            along(p) < s.length() + 1e-9 && along(q) < s.length() + 1e-9) {
          covered = true;
          break;
        }
      }
      ASSERT_TRUE(covered) << "mesh sharp edge " << p.transpose() << " - " << q.transpose();
    }
    EXPECT_EQ(boundary, 0u) << "the solid is watertight";
    double truth_length = 0.0;
    for (const auto& s : b.truth.sharp_edges) truth_length += s.length();
    EXPECT_NEAR(truth_length, sharp_length, 1e-6);
    EXPECT_GT(b.truth.sharp_edges.size(), 50u);
  }
}

TEST(Building, WallThicknessFromTruthPlanes) {
  const auto b = generateBuilding(buildingPreset("two-rooms"));
  // The exterior wall at u = 0: exterior face normal -x at x = -0.2, interior face +x at 0.2.
  bool ext = false, in = false;
  for (const auto& p : b.truth.planes) {
    if (p.element_type != "IfcWall") continue;
    if (p.face == "exterior" && p.normal.isApprox(-Eigen::Vector3d::UnitX()) && std::abs(p.offset - 0.2) < 1e-9) ext = true;
    if (p.face == "interior" && p.normal.isApprox(Eigen::Vector3d::UnitX()) && std::abs(p.offset - 0.2) < 1e-9) in = true;
  }
  EXPECT_TRUE(ext);
  EXPECT_TRUE(in);
}

TEST(Building, OpeningCornersCounterClockwiseFromOutside) {
  const auto b = generateBuilding(buildingPreset("house"));
  std::size_t exterior = 0;
  for (const auto& o : b.truth.openings) {
    const auto& c = o.corners;
    // Seen from the side the face looks at (along -normal), corners turn counter-clockwise.
    EXPECT_GT((c[1] - c[0]).cross(c[3] - c[0]).dot(o.face_normal), 0.0);
    EXPECT_NEAR(c[0].z(), c[1].z(), 1e-12);
    EXPECT_GT(c[3].z(), c[0].z());
    if (o.face == "exterior") ++exterior;
  }
  EXPECT_EQ(exterior, b.model.elementCountOfType("IfcWindow") + 1);  // + entrance door
}

TEST(Building, NonManhattanWallAngles) {
  const auto b = generateBuilding(buildingPreset("non-manhattan"));
  std::set<long> angles;
  for (const auto& p : b.truth.planesWithFace("exterior")) {
    if (p->element_type != "IfcWall") continue;
    angles.insert(std::lround(std::atan2(p->normal.y(), p->normal.x()) * 180.0 / M_PI));
  }
  // Faces of a 60-degree parallelogram: normals at -90, 90 (v walls) and -30, 150 (u walls).
  EXPECT_EQ(angles, (std::set<long>{-90, -30, 90, 150}));
  // Exterior walls keep their perpendicular thickness: the faces of the wall on u = 0 are at
  // signed distances -0.2 and +0.2 along the u-plane normal (sin 60, -cos 60, 0).
  const Eigen::Vector3d nu(std::sin(M_PI / 3), -std::cos(M_PI / 3), 0.0);
  double lo = 1e9, hi = -1e9;
  for (const auto& p : b.truth.planes) {
    const double c = p.normal.dot(nu);
    if (p.element_type != "IfcWall" || std::abs(std::abs(c) - 1.0) > 1e-9) continue;
    const double d = p.offset * c;  // offset along +nu
    if (std::abs(d) > 1.0) continue;
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  EXPECT_NEAR(lo, -0.2, 1e-9);
  EXPECT_NEAR(hi, 0.2, 1e-9);
}

TEST(Building, SpecJsonRoundTripAndErrors) {
  const BuildingSpec s = buildingPreset("l-shaped");
  const BuildingSpec r = buildingSpecFromJson(buildingSpecToJson(s));
  EXPECT_EQ(r.mask, s.mask);
  EXPECT_EQ(r.column_widths, s.column_widths);
  EXPECT_DOUBLE_EQ(r.exterior_wall_thickness, 0.45);
  EXPECT_THROW(buildingSpecFromJson(nlohmann::json{{"storeys", 0}}), InputError);
  EXPECT_THROW(buildingSpecFromJson(nlohmann::json{{"colour", "red"}}), InputError);
  EXPECT_THROW(buildingSpecFromJson(nlohmann::json{{"mask", {"#.", ".#"}}, {"column_widths", {4, 4}},
                                                   {"row_depths", {4, 4}}}), InputError);  // not connected
  const auto dir = test::scratchDir("simulation-spec");
  test::writeAll(dir / "bad.json", "{\"storeys\": 2,\n \"oops\"");
  try {
    readBuildingSpec((dir / "bad.json").string());
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos);
  }
}

TEST(Building, TruthJsonRoundTrip) {
  const auto b = generateBuilding(buildingPreset("house"));
  const auto dir = test::scratchDir("simulation-truth");
  writeBuildingTruth(dir / "ground_truth.json", b);
  const BuildingTruth t = readBuildingTruth(dir / "ground_truth.json");
  ASSERT_EQ(t.planes.size(), b.truth.planes.size());
  ASSERT_EQ(t.openings.size(), b.truth.openings.size());
  ASSERT_EQ(t.sharp_edges.size(), b.truth.sharp_edges.size());
  EXPECT_EQ(t.glass_edges.size(), 4 * b.model.elementCountOfType("IfcWindow"));
  EXPECT_TRUE(t.openings[3].corners[2].isApprox(b.truth.openings[3].corners[2]));
  EXPECT_EQ(t.planes[5].face, b.truth.planes[5].face);
}

}  // namespace
}  // namespace plumb
