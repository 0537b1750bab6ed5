// The dispatcher: extension + content sniffing, wrong-extension / empty / garbage / truncated
// files, LAZ, model vs point files, and write dispatch for every point format.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/ply/ply_writer.hpp"
#include "io/sniff.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
std::string readError(const std::filesystem::path& p) {
  try {
    readFile(p);
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}
PointCloud smallCloud() {
  PointCloud c;
  for (int i = 0; i < 20; ++i) {
    c.positions.emplace_back(0.1f * i, 1.f, 2.f - 0.05f * i);
    c.colors.push_back({static_cast<std::uint8_t>(10 * i), 0, 255});
    c.intensity.push_back(static_cast<float>(i));
  }
  return c;
}
}  // namespace

TEST(Dispatch, Sniffing) {
  EXPECT_EQ(sniffContent("ply\nformat ascii 1.0\n", 100).format, FileFormat::Ply);
  EXPECT_EQ(sniffContent("LASF....", 100).format, FileFormat::Las);
  EXPECT_EQ(sniffContent("ASTM-E57", 100).format, FileFormat::E57);
  EXPECT_EQ(sniffContent("ISO-10303-21;\n", 100).format, FileFormat::Ifc);
  EXPECT_EQ(sniffContent("# .PCD v0.7\nVERSION 0.7\n", 100).format, FileFormat::Pcd);
  EXPECT_EQ(sniffContent("# comment\nv 1 2 3\n", 100).format, FileFormat::Obj);
  EXPECT_EQ(sniffContent("1.0 2.0 3.0\n", 100).format, FileFormat::Text);
  EXPECT_FALSE(sniffContent("1.0 2.0 3.0\n", 100).strong);
  EXPECT_EQ(sniffContent("PK\x03\x04zip", 100).description, "a ZIP archive");
  std::string stl(84, ' ');
  stl[80] = 2;
  stl[81] = stl[82] = stl[83] = 0;
  EXPECT_EQ(sniffContent(stl, 184).format, FileFormat::Stl);
}

TEST(Dispatch, WrongExtensionSaysWhatTheContentIs) {
  const auto dir = test::scratchDir("dispatch_wrong_ext");
  writePly(dir / "cloud.ply", smallCloud());
  std::filesystem::copy_file(dir / "cloud.ply", dir / "cloud.pcd");
  std::string m = readError(dir / "cloud.pcd");
  EXPECT_NE(m.find("cloud.pcd: the extension says PCD but the content looks like a PLY file"), std::string::npos) << m;
  std::filesystem::copy_file(test::sharedData("las/simple1_1.las"), dir / "points.xyz");
  m = readError(dir / "points.xyz");
  EXPECT_NE(m.find("points.xyz: the extension says text (XYZ/CSV/PTS) but the content looks like a LAS/LAZ file"),
            std::string::npos)
      << m;
  // Unknown extension with recognisable content: read by content.
  std::filesystem::copy_file(dir / "cloud.ply", dir / "cloud.bin");
  EXPECT_EQ(std::get<Dataset>(readFile(dir / "cloud.bin")).pointCount(), 20u);
  test::writeAll(dir / "zip.ply", std::string("PK\x03\x04", 4) + std::string(100, 'x'));
  m = readError(dir / "zip.ply");
  EXPECT_NE(m.find("the content looks like a ZIP archive"), std::string::npos) << m;
}

TEST(Dispatch, EmptyGarbageTruncatedMissing) {
  const auto dir = test::scratchDir("dispatch_bad");
  for (const char* name : {"e.ply", "e.pcd", "e.xyz", "e.e57", "e.las", "e.ifc", "e.obj"}) {
    test::writeAll(dir / name, "");
    const std::string m = readError(dir / name);
    EXPECT_NE(m.find(std::string(name) + ": file is empty (0 bytes)"), std::string::npos) << m;
  }
  std::string garbage(4096, '\0');
  for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = static_cast<char>((i * 7919) % 251);
  for (const char* name : {"g.ply", "g.pcd", "g.xyz", "g.e57", "g.las", "g.ifc", "g.stl", "g.glb"}) {
    test::writeAll(dir / name, garbage);
    const std::string m = readError(dir / name);
    EXPECT_NE(m.find(name), std::string::npos) << m;
    EXPECT_NE(m.find("binary data"), std::string::npos) << m;
  }
  // Truncated real files: PLY (location checked in test_io_ply), PCD, LAS, E57.
  writePly(dir / "t.ply", smallCloud());
  auto truncate = [&](const std::filesystem::path& src, const std::string& name, double keep) {
    const std::string b = test::readAll(src);
    test::writeAll(dir / name, b.substr(0, static_cast<std::size_t>(b.size() * keep)));
    return readError(dir / name);
  };
  EXPECT_NE(truncate(dir / "t.ply", "t2.ply", 0.8).find("truncated data: expected 20 vertices"), std::string::npos);
  EXPECT_NE(truncate(test::sharedData("pcd/capture0002.pcd"), "t.pcd", 0.7).find("t.pcd: truncated data"),
            std::string::npos);
  const std::string las = truncate(test::sharedData("las/simple1_1.las"), "t.las", 0.6);
  EXPECT_NE(las.find("t.las"), std::string::npos) << las;
  const std::string e57 = truncate(test::sharedData("e57/bunnyFloat.e57"), "t.e57", 0.6);
  EXPECT_NE(e57.find("t.e57"), std::string::npos) << e57;
  EXPECT_NE(readError(dir / "missing.ply").find("missing.ply: no such file"), std::string::npos);
  EXPECT_NE(readError(dir).find("is a directory"), std::string::npos);
}

TEST(Dispatch, LazIsExplained) {
  const auto dir = test::scratchDir("dispatch_laz");
  std::filesystem::copy_file(test::sharedData("las/simple1_1.las"), dir / "x.laz");
  const std::string m = readError(dir / "x.laz");
  EXPECT_NE(m.find("x.laz: LAZ is compressed LAS"), std::string::npos) << m;
  EXPECT_NE(m.find("laszip"), std::string::npos) << m;
  EXPECT_NE(m.find("las2las"), std::string::npos) << m;
}

TEST(Dispatch, ModelsAndPointsAreNotMixedUp) {
  const auto model = test::sharedData("ifc/tested_sample_project.ifc");
  EXPECT_TRUE(std::holds_alternative<BimModel>(readFile(model)));
  try {
    readDataset(model);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("holds a mesh/BIM model, not a point cloud"), std::string::npos);
  }
  try {
    readModel(test::sharedData("pcd/room_scan1.pcd"));
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("holds points, not a mesh"), std::string::npos);
  }
  EXPECT_EQ(readDataset(test::sharedData("pcd/room_scan1.pcd")).pointCount(), 112586u);
}

TEST(Dispatch, SurveyFormatsThroughTheDispatcher) {
  // README: simple1_4.las LAS 1.4 PF7, 22,600 points; A_B.e57 2 scans (2 + 4 points).
  EXPECT_EQ(readDataset(test::sharedData("las/simple1_4.las")).pointCount(), 22600u);
  const Dataset ab = readDataset(test::sharedData("e57/A_B.e57"));
  ASSERT_EQ(ab.scans.size(), 2u);
  EXPECT_EQ(ab.scans[0].cloud.size() + ab.scans[1].cloud.size(), 6u);
}

TEST(Dispatch, WriteEveryPointFormatAndReadBack) {
  const auto dir = test::scratchDir("dispatch_write");
  Dataset d = Dataset::fromCloud(smallCloud(), "s");
  d.scans[0].pose = RigidTransform::fromYaw(0.5, {10, 20, 1});  // formats with one cloud merge poses
  d.scans[0].has_pose = true;
  const Bounds expected = d.bounds();
  for (const char* name : {"o.ply", "o.pcd", "o.xyz", "o.csv", "o.e57", "o.las"}) {
    SCOPED_TRACE(name);
    writeDataset(dir / name, d);
    const Dataset r = readDataset(dir / name);
    ASSERT_EQ(r.pointCount(), 20u);
    const Bounds b = r.bounds();
    EXPECT_LT((b.min - expected.min).norm(), 2e-4);
    EXPECT_LT((b.max - expected.max).norm(), 2e-4);
  }
  EXPECT_THROW(writeDataset(dir / "o.obj", d), FileError);
  EXPECT_THROW(writeDataset(dir / "o.laz", d), FileError);
  EXPECT_THROW(writeDataset(dir / "o.unknown", d), FileError);
}

TEST(Dispatch, ModelWriteAndPlyMeshIsAModel) {
  const auto dir = test::scratchDir("dispatch_model");
  const BimModel m = readModel(test::sharedData("ifc/tested_sample_project.ifc"));
  writeModel(dir / "m.ply", m);
  const BimModel r = readModel(dir / "m.ply");
  EXPECT_EQ(r.mesh.triangleCount(), m.mesh.triangleCount());
  EXPECT_EQ(r.elementCountOfType("IfcWindow"), 9u);
  EXPECT_EQ(r.elementTypeCounts(), m.elementTypeCounts());
  EXPECT_TRUE(std::holds_alternative<BimModel>(readFile(dir / "m.ply")));
  writeModel(dir / "m.stl", m);
  EXPECT_NEAR(readModel(dir / "m.stl").mesh.area(), m.mesh.area(), 1e-3 * m.mesh.area());
  EXPECT_THROW(writeModel(dir / "m.e57", m), FileError);
}
