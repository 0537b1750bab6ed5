// assimp import of the shared IFC files (element counts verified by verify_shared_data.py's
// entity regex and shared/data/README.md), axis conversion, the IFC4 failure message, the
// IFC++ import where assimp fails (and against assimp where both read), and OBJ/STL/glTF round
// trips.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/error.hpp"
#include "io/mesh/mesh_io.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
/// Element counts per IFC type, as counted in the file by an independent regex pass.
void expectElementCounts(const BimModel& m,
                         const std::vector<std::pair<std::string, std::size_t>>& expected) {
  for (const auto& [type, count] : expected)
    EXPECT_EQ(m.elementCountOfType(type), count) << type;
}
}  // namespace

TEST(Mesh, DuplexElementCountsAndZUp) {
  const BimModel m = readMesh(test::sharedData("ifc/duplex.ifc"));
  // File: IFCWALL 1 + IFCWALLSTANDARDCASE 56, IFCWINDOW 24, IFCDOOR 14, IFCSLAB 21 (README too),
  // IFCBEAM 8, IFCCOVERING 13, IFCFOOTING 7, IFCMEMBER 4, IFCRAILING 4, IFCSTAIRFLIGHT 2,
  // IFCFURNISHINGELEMENT 61. Spaces and openings carry no surface geometry through assimp.
  expectElementCounts(m, {{"IfcWall", 57}, {"IfcWindow", 24}, {"IfcDoor", 14}, {"IfcSlab", 21},
                          {"IfcBeam", 8}, {"IfcCovering", 13}, {"IfcFooting", 7}, {"IfcMember", 4},
                          {"IfcRailing", 4}, {"IfcStairFlight", 2}, {"IfcFurnishingElement", 61},
                          {"IfcOpeningElement", 0}});
  EXPECT_EQ(m.elements.size(), 215u);  // the sum of the above
  EXPECT_EQ(m.triangle_element.size(), m.mesh.triangleCount());
  // The duplex is ~8 m high (README): Z must carry the height after the Y-up -> Z-up turn.
  const Bounds b = m.mesh.bounds();
  EXPECT_GT(b.size().z(), 7.5);
  EXPECT_LT(b.size().z(), 9.0);
  // Elements keep names and GlobalIds.
  bool found = false;
  for (const auto& e : m.elements)
    if (e.guid == "2O2Fr$t4X7Zf8NOew3FNtn") {
      found = true;
      EXPECT_EQ(e.type, "IfcWall");
      EXPECT_EQ(e.name, "BasicWall:Exterior-BrickonBlock:138062");
    }
  EXPECT_TRUE(found);
  // Walls stand vertically: most wall triangle area has a horizontal normal.
  double vertical = 0, total = 0;
  for (auto t : m.trianglesOfType("IfcWall")) {
    const double a = m.mesh.triangleArea(t);
    total += a;
    if (std::abs(m.mesh.triangleNormal(t).z()) < 0.1) vertical += a;
  }
  EXPECT_GT(vertical / total, 0.6);
}

TEST(Mesh, TestedSampleProject) {
  const BimModel m = readMesh(test::sharedData("ifc/tested_sample_project.ifc"));
  // File: IFCWALLSTANDARDCASE 3, IFCWINDOW 9, IFCDOOR 1, IFCSLAB 2, IFCMEMBER 31, IFCPLATE 12,
  // IFCFURNISHINGELEMENT 35 (README: walls 3, windows 9, door 1, slabs 2).
  expectElementCounts(m, {{"IfcWall", 3}, {"IfcWindow", 9}, {"IfcDoor", 1}, {"IfcSlab", 2},
                          {"IfcMember", 31}, {"IfcPlate", 12}, {"IfcFurnishingElement", 35}});
  const Bounds b = m.mesh.bounds();
  EXPECT_GT(b.size().z(), 3.0);  // slab to wall top, Z up
  EXPECT_LT(b.size().z(), 4.5);
}

TEST(Mesh, IfcOpenHouse) {
  const BimModel m = readMesh(test::sharedData("ifc/IfcOpenHouse_IFC4.ifc"));
  // File: IFCWALLSTANDARDCASE 4, IFCDOOR 1, IFCSLAB 2, IFCFOOTING 1, IFCMEMBER 20, IFCPLATE 5,
  // IFCSTAIRFLIGHT 1, IFCWINDOW 5. The 5 windows are aggregates of 4 frame members + 1 pane each;
  // assimp 5.2 hands over the parts (IfcMember/IfcPlate), not IfcWindow nodes.
  expectElementCounts(m, {{"IfcWall", 4}, {"IfcDoor", 1}, {"IfcSlab", 2}, {"IfcFooting", 1},
                          {"IfcMember", 20}, {"IfcPlate", 5}, {"IfcStairFlight", 1},
                          {"IfcWindow", 0}});
  // The file is in millimetres: assimp applies the unit, so walls are metres tall, not 1000x.
  const Bounds walls = [&] {
    Bounds b;
    for (auto t : m.trianglesOfType("IfcWall"))
      for (auto v : m.mesh.triangles[t]) b.extend(m.mesh.vertices[v]);
    return b;
  }();
  EXPECT_GT(walls.size().z(), 2.0);
  EXPECT_LT(walls.size().z(), 8.0);
  EXPECT_LT(walls.size().x(), 30.0);
}

TEST(Mesh, AssimpAloneRejectsFzkWithActionableError) {
  const auto path = test::sharedData("ifc/AC20-FZK-Haus.ifc");
  try {
    readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::assimp);
    FAIL() << "assimp 5.2 is expected to reject this IFC4 file";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("AC20-FZK-Haus.ifc"), std::string::npos) << m;
    EXPECT_NE(m.find("schema IFC4"), std::string::npos) << m;
    EXPECT_NE(m.find("entity #20909 (IfcSpace)"), std::string::npos) << m;
    EXPECT_NE(m.find("IFC2X3"), std::string::npos) << m;
    EXPECT_NE(m.find("glTF/OBJ"), std::string::npos) << m;
    EXPECT_EQ(e.where().line.value_or(0), 11879u);  // grep -n '^#20909=' AC20-FZK-Haus.ifc
  }
}

TEST(Mesh, IfcppReadsTheIfc4ThatAssimpRejects) {
  // File and shared/data/README.md: IfcWall 13, IfcWindow 11, IfcDoor 5, IfcSlab 4; a 2-storey
  // house about 12 x 10 m and 6-7 m high (walls, windows, roof).
  const BimModel m = readMesh(test::sharedData("ifc/AC20-FZK-Haus.ifc"));
  expectElementCounts(m, {{"IfcWall", 13}, {"IfcWindow", 11}, {"IfcDoor", 5}, {"IfcSlab", 4}});
  EXPECT_EQ(m.format, "ifc");
  EXPECT_GT(m.mesh.triangleCount(), 5000u);
  ASSERT_EQ(m.triangle_element.size(), m.mesh.triangleCount());
  for (const BimElement& e : m.elements) EXPECT_EQ(e.guid.size(), 22u) << e.type << " " << e.name;
  const Eigen::Vector3d size = m.mesh.bounds().size();
  EXPECT_GT(size.x(), 10.0);
  EXPECT_LT(size.x(), 20.0);
  EXPECT_GT(size.z(), 5.0);
  EXPECT_LT(size.z(), 9.0);
}

TEST(Mesh, IfcppAndAssimpAgreeOnTheDuplex) {
  const auto path = test::sharedData("ifc/duplex.ifc");
  const BimModel a = readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::assimp);
  const BimModel i = readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::ifcpp);
  for (const char* type : {"IfcWall", "IfcWindow", "IfcDoor", "IfcSlab"})
    EXPECT_EQ(i.elementCountOfType(type), a.elementCountOfType(type)) << type;
  // The same frame (Z up, metres, same origin): the wall boxes agree to the centimetre.
  const auto wallBounds = [](const BimModel& m) {
    Bounds b;
    for (auto t : m.trianglesOfType("IfcWall"))
      for (auto v : m.mesh.triangles[t]) b.extend(m.mesh.vertices[v]);
    return b;
  };
  EXPECT_LT((wallBounds(a).min - wallBounds(i).min).norm(), 0.01);
  EXPECT_LT((wallBounds(a).max - wallBounds(i).max).norm(), 0.01);
}

namespace {
std::size_t countOn(const BimModel& m, const std::string& type, const std::string& storey) {
  std::size_t n = 0;
  for (const BimElement& e : m.elements) n += e.type == type && e.storey == storey;
  return n;
}
/// Elements of each (type, storey), as ifc_storeys.py counts them in the STEP text.
struct StoreyCount {
  const char* type;
  const char* storey;
  std::size_t count;
};
void expectStoreys(const BimModel& m, const std::vector<StoreyCount>& expected) {
  std::map<std::string, std::size_t> seen;  // for the failure message
  for (const BimElement& e : m.elements) ++seen["'" + e.storey + "' " + e.type];
  std::string all;
  for (const auto& [k, n] : seen) all += k + " x" + std::to_string(n) + "; ";
  for (const StoreyCount& c : expected)
    EXPECT_EQ(countOn(m, c.type, c.storey), c.count) << c.type << " on " << c.storey << "; the model has " << all;
}
const std::vector<StoreyCount> kDuplexStoreys{
    {"IfcWall", "Level 1", 21}, {"IfcWall", "Level 2", 25}, {"IfcWall", "Roof", 4},      {"IfcWall", "T/FDN", 7},
    {"IfcWindow", "Level 1", 4}, {"IfcWindow", "Level 2", 18}, {"IfcWindow", "Roof", 2}, {"IfcDoor", "Level 1", 6},
    {"IfcDoor", "Level 2", 8},  {"IfcSlab", "Roof", 1}};
}  // namespace

TEST(Mesh, BothIfcReadersKeepTheStoreyOfEachElement) {
  const auto path = test::sharedData("ifc/duplex.ifc");
  expectStoreys(readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::assimp), kDuplexStoreys);
  expectStoreys(readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::ifcpp), kDuplexStoreys);
  // The IFC4 house (IFC++ only): Erdgeschoss and Dachgeschoss.
  expectStoreys(readMesh(test::sharedData("ifc/AC20-FZK-Haus.ifc")),
                {{"IfcWall", "Erdgeschoss", 9}, {"IfcWall", "Dachgeschoss", 4}, {"IfcWindow", "Erdgeschoss", 9},
                 {"IfcWindow", "Dachgeschoss", 2}, {"IfcDoor", "Erdgeschoss", 5}, {"IfcSlab", "Dachgeschoss", 3}});
}

TEST(Mesh, IfcppReadsOnlyIfc) {
  const auto dir = test::scratchDir("mesh_ifcpp_obj");
  test::writeAll(dir / "a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  try {
    readMesh(dir / "a.obj", nullptr, ImportLimits::fromEnvironment(), ModelParser::ifcpp);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("IFC++ reads only IFC files"), std::string::npos) << e.what();
  }
}

TEST(Mesh, IfcNodeNames) {
  auto e = elementFromIfcNodeName("IfcWallStandardCase_Basic Wall_x_2O2Fr$t4X7Zf8NOew3FNtn");
  EXPECT_EQ(e.type, "IfcWall");
  EXPECT_EQ(e.name, "Basic Wall_x");
  EXPECT_EQ(e.guid, "2O2Fr$t4X7Zf8NOew3FNtn");
  e = elementFromIfcNodeName("IfcSlabElementedCase_2O2Fr$t4X7Zf8NOew3FNtn");
  EXPECT_EQ(e.type, "IfcSlab");
  EXPECT_EQ(e.name, "");
  e = elementFromIfcNodeName("Cube.001");
  EXPECT_EQ(e.type, "");
  EXPECT_EQ(e.name, "Cube.001");
}

TEST(Mesh, ObjGroupsBecomeElementsAndObjStlRoundTrip) {
  const auto dir = test::scratchDir("mesh_obj");
  test::writeAll(dir / "a.obj",
                 "# two objects\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 3\n"
                 "o floor\nf 1 2 3 4\no pole\nf 1 2 5\n");
  const BimModel m = readMesh(dir / "a.obj");
  ASSERT_EQ(m.mesh.triangleCount(), 3u);
  ASSERT_EQ(m.elements.size(), 2u);
  EXPECT_EQ(m.elements[0].name, "floor");
  EXPECT_EQ(m.elements[1].name, "pole");
  EXPECT_NEAR(m.mesh.area(), 1.0 + 1.5, 1e-9);
  EXPECT_NEAR(m.mesh.bounds().size().z(), 3.0, 1e-9);  // OBJ kept as is (Z up)
  for (const char* out : {"b.obj", "b.stl"}) {
    writeMesh(dir / out, m);
    const BimModel r = readMesh(dir / out);
    EXPECT_EQ(r.mesh.triangleCount(), 3u) << out;
    EXPECT_NEAR(r.mesh.area(), 2.5, 1e-6) << out;
    EXPECT_NEAR(r.mesh.bounds().size().z(), 3.0, 1e-6) << out;
  }
  EXPECT_THROW(writeMesh(dir / "c.fbx", m), FileError);
}

// Plumb's own OBJ export names each group "<IfcType>_<name>" (issue 14: registration on chosen
// elements needs the types): reading the file back gives the typed elements again.
TEST(Mesh, ObjGroupsNamedByIfcTypeKeepTheirTypes) {
  EXPECT_TRUE(looksLikeIfcNodeName("IfcWall_W1"));
  EXPECT_TRUE(looksLikeIfcNodeName("IfcSlab"));
  EXPECT_FALSE(looksLikeIfcNodeName("Ifcwall_W1"));
  EXPECT_FALSE(looksLikeIfcNodeName("Ifc2_x"));
  EXPECT_FALSE(looksLikeIfcNodeName("floor"));
  const auto dir = test::scratchDir("mesh_obj_types");
  test::writeAll(dir / "a.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 3\n"
                                "g IfcSlab_Floor\nf 1 2 3\ng IfcColumn_C1\nf 1 2 4\ng pole\nf 2 3 4\n");
  const BimModel m = readMesh(dir / "a.obj");
  writeMesh(dir / "b.obj", m);
  const BimModel r = readMesh(dir / "b.obj");
  ASSERT_EQ(r.elements.size(), 3u);
  EXPECT_EQ(r.elements[0].type, "IfcSlab");
  EXPECT_EQ(r.elements[0].name, "Floor");
  EXPECT_EQ(r.elements[1].type, "IfcColumn");
  EXPECT_EQ(r.elements[2].type, "");
  EXPECT_EQ(r.elements[2].name, "pole");
  EXPECT_EQ(r.trianglesOfType("IfcColumn").size(), 1u);
}

TEST(Mesh, GltfIsTurnedZUp) {
  // One triangle, 2 m along glTF's +Y (up): must come out 2 m along +Z.
  const auto dir = test::scratchDir("mesh_gltf");
  // 3 float32 vertices (0,0,0) (1,0,0) (0,2,0) = 36 bytes, base64-encoded.
  test::writeAll(dir / "t.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0,"name":"tri"}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,2,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAEAAAAAA"}]})");
  const BimModel m = readMesh(dir / "t.gltf");
  ASSERT_EQ(m.mesh.triangleCount(), 1u);
  EXPECT_NEAR(m.mesh.bounds().size().z(), 2.0, 1e-6);
  EXPECT_NEAR(m.mesh.bounds().size().y(), 0.0, 1e-6);
  EXPECT_NEAR(m.mesh.bounds().max.z(), 2.0, 1e-6);  // +Y -> +Z (not -Z)
  EXPECT_EQ(m.elements.at(0).name, "tri");
}

TEST(Mesh, EmptyAndGarbageFiles) {
  const auto dir = test::scratchDir("mesh_bad");
  test::writeAll(dir / "e.obj", "");
  EXPECT_THROW(readMesh(dir / "e.obj"), FileError);
  test::writeAll(dir / "g.ifc", "ISO-10303-21;\nHEADER;\nthis is not STEP\n");
  try {
    readMesh(dir / "g.ifc");
    FAIL();
  } catch (const FileError& e) {  // assimp refuses it, and so does IFC++ after it
    EXPECT_NE(std::string(e.what()).find("g.ifc"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("IFC++ cannot read it either"), std::string::npos) << e.what();
  }
}
