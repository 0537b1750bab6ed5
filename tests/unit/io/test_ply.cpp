// PLY reader/writer: round trips in every encoding, double coordinates, custom properties,
// faces with element ids, hand-written files, and errors with their locations.
#include <gtest/gtest.h>

#include <cstring>

#include "common/error.hpp"
#include "io/ply/ply_reader.hpp"
#include "io/ply/ply_writer.hpp"
#include "support/test_support.hpp"

using namespace plumb;
namespace fs = std::filesystem;

namespace {

PointCloud sampleCloud(std::size_t n) {
  PointCloud c;
  for (std::size_t i = 0; i < n; ++i) {
    c.positions.emplace_back(0.5f * i, -0.25f * i + 1.f, 3.f + 0.125f * (i % 7));
    c.normals.emplace_back(0.f, 0.6f, 0.8f);
    c.colors.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i), 7});
    c.intensity.push_back(100.f + i);
  }
  c.scalar_fields.push_back({"deviation", {}});
  for (std::size_t i = 0; i < n; ++i) c.scalar_fields[0].values.push_back(0.001f * i);
  return c;
}

void expectSameCloud(const PointCloud& a, const PointCloud& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_LT((a.world(i) - b.world(i)).norm(), 1e-6) << i;
    EXPECT_EQ(a.colors[i], b.colors[i]) << i;
    EXPECT_FLOAT_EQ(a.intensity[i], b.intensity[i]);
    EXPECT_LT((a.normals[i] - b.normals[i]).norm(), 1e-6f);
  }
  ASSERT_NE(b.findScalarField("deviation"), nullptr);
  EXPECT_EQ(b.findScalarField("deviation")->values, a.scalar_fields[0].values);
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

class PlyRoundTrip : public ::testing::TestWithParam<ply::Encoding> {};

TEST_P(PlyRoundTrip, AllAttributesSurvive) {
  const auto dir = test::scratchDir("ply_roundtrip_" + std::to_string(static_cast<int>(GetParam())));
  const PointCloud c = sampleCloud(300);
  PlyWriteOptions o;
  o.encoding = GetParam();
  writePly(dir / "c.ply", c, o);
  const PlyData d = readPly(dir / "c.ply");
  EXPECT_EQ(d.header.encoding, GetParam());
  EXPECT_FALSE(d.has_faces);
  EXPECT_TRUE(d.vertices.offset.isZero());
  expectSameCloud(c, d.vertices);
}

INSTANTIATE_TEST_SUITE_P(Encodings, PlyRoundTrip,
                         ::testing::Values(ply::Encoding::Ascii, ply::Encoding::BinaryLittleEndian,
                                           ply::Encoding::BinaryBigEndian));

TEST(Ply, GeoreferencedCoordinatesKeepMillimetres) {
  // Lambert-93-like coordinates: written as double world values, read back with an offset.
  const auto dir = test::scratchDir("ply_georef");
  PointCloud c;
  c.offset = {652000.0, 6862000.0, 35.0};
  for (int i = 0; i < 50; ++i) c.positions.emplace_back(0.0013f * i, 12.3456f, -0.5f + 0.001f * i);
  for (auto enc : {ply::Encoding::BinaryBigEndian, ply::Encoding::Ascii}) {
    PlyWriteOptions o;
    o.encoding = enc;
    writePly(dir / "g.ply", c, o);
    const auto text = test::readAll(dir / "g.ply");
    EXPECT_NE(text.find("property double x"), std::string::npos);
    const PlyData d = readPly(dir / "g.ply");
    EXPECT_EQ(d.vertices.offset, Eigen::Vector3d(652000.0, 6862012.0, 35.0));  // first point rounded
    for (int i = 0; i < 50; ++i) EXPECT_LT((d.vertices.world(i) - c.world(i)).norm(), 1e-6);
  }
}

TEST(Ply, HandWrittenAsciiWithCustomTypes) {
  const auto dir = test::scratchDir("ply_hand");
  test::writeAll(dir / "h.ply",
                 "ply\r\nformat ascii 1.0\r\ncomment hand made\r\nobj_info x\r\nelement vertex 3\r\n"
                 "property double x\r\nproperty double y\r\nproperty double z\r\n"
                 "property ushort red\r\nproperty ushort green\r\nproperty ushort blue\r\n"
                 "property float scalar_intensity\r\nproperty short label\r\n"
                 "property list uchar int junk\r\nend_header\r\n"
                 "1 2 3 65535 256 0 0.5 -4 2 7 8\r\n\r\n4 5 6 0 0 0 1.5 12 0\r\n7 8 9.25 512 512 512 2 3 1 1\r\n");
  const PlyData d = readPly(dir / "h.ply");
  ASSERT_EQ(d.vertices.size(), 3u);
  EXPECT_EQ(d.vertices.world(2), Eigen::Vector3d(7, 8, 9.25));
  EXPECT_EQ(d.vertices.colors[0], (Rgb8{255, 1, 0}));  // 16-bit colours: high byte
  EXPECT_EQ(d.vertices.colors[2], (Rgb8{2, 2, 2}));
  EXPECT_FLOAT_EQ(d.vertices.intensity[1], 1.5f);
  ASSERT_NE(d.vertices.findScalarField("label"), nullptr);
  EXPECT_EQ(d.vertices.findScalarField("label")->values, (Column<float>{-4, 12, 3}));
  EXPECT_EQ(d.header.comments.size(), 2u);
}

TEST(Ply, MeshWithElementIdsRoundTrip) {
  const auto dir = test::scratchDir("ply_mesh");
  BimModel m;
  m.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 2}};
  m.mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}};
  m.triangle_element = {0, 0, 1};
  m.elements = {{"IfcSlab", "Floor 1", "g1"}, {"IfcWall", "Basic Wall: 200mm", "g2"}};
  for (auto enc : {ply::Encoding::Ascii, ply::Encoding::BinaryLittleEndian, ply::Encoding::BinaryBigEndian}) {
    PlyWriteOptions o;
    o.encoding = enc;
    writePlyMesh(dir / "m.ply", m, o);
    PlyData d = readPly(dir / "m.ply");
    ASSERT_TRUE(d.has_faces);
    const BimModel r = plyToModel(std::move(d), dir / "m.ply");
    EXPECT_EQ(r.mesh.triangles, m.mesh.triangles);
    EXPECT_EQ(r.mesh.vertices, m.mesh.vertices);
    EXPECT_EQ(r.triangle_element, m.triangle_element);
    ASSERT_EQ(r.elements.size(), 2u);
    EXPECT_EQ(r.elements[1].type, "IfcWall");
    EXPECT_EQ(r.elements[1].name, "Basic Wall: 200mm");
    EXPECT_EQ(r.elementCountOfType("IfcSlab"), 1u);
  }
}

TEST(Ply, PolygonsAreFanTriangulatedIntoOneElement) {
  const auto dir = test::scratchDir("ply_quads");
  test::writeAll(dir / "q.ply",
                 "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 2\nproperty list uchar uint vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n");
  BimModel m = plyToModel(readPly(dir / "q.ply"), dir / "q.ply");
  ASSERT_EQ(m.mesh.triangleCount(), 3u);
  EXPECT_EQ(m.mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
  ASSERT_EQ(m.elements.size(), 1u);
  EXPECT_EQ(m.triangle_element, (std::vector<std::uint32_t>{0, 0, 0}));
  EXPECT_NEAR(m.mesh.area(), 1.5, 1e-9);
}

TEST(Ply, OtherElementsAreSkipped) {
  const auto dir = test::scratchDir("ply_other");
  // binary: an unknown element with a list before the vertices, one after.
  std::string s = "ply\nformat binary_little_endian 1.0\nelement camera 1\nproperty list uchar float k\n"
                  "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                  "element extra 2\nproperty int a\nend_header\n";
  const float cam[2] = {1.f, 2.f};
  s.push_back(2);
  s.append(reinterpret_cast<const char*>(cam), 8);
  const float v[6] = {1, 2, 3, 4, 5, 6};
  s.append(reinterpret_cast<const char*>(v), sizeof v);
  const std::int32_t extra[2] = {9, 9};
  s.append(reinterpret_cast<const char*>(extra), sizeof extra);
  test::writeAll(dir / "o.ply", s);
  const PlyData d = readPly(dir / "o.ply");
  ASSERT_EQ(d.vertices.size(), 2u);
  EXPECT_EQ(d.vertices.world(1), Eigen::Vector3d(4, 5, 6));
}

TEST(Ply, TruncatedBinaryNamesVertexAndByte) {
  const auto dir = test::scratchDir("ply_trunc");
  writePly(dir / "t.ply", sampleCloud(100));
  std::string bytes = test::readAll(dir / "t.ply");
  const std::size_t header = bytes.find("end_header\n") + 11;
  // record: xyz 12 + normals 12 + rgb 3 + intensity 4 + deviation 4 = 35 bytes
  bytes.resize(header + 35 * 57 + 10);
  test::writeAll(dir / "t.ply", bytes);
  const std::string msg = errorOf([&] { readPly(dir / "t.ply"); });
  EXPECT_NE(msg.find("t.ply"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected 100 vertices"), std::string::npos) << msg;
  EXPECT_NE(msg.find("file ends at byte " + std::to_string(bytes.size()) + " in vertex 57"), std::string::npos) << msg;
}

TEST(Ply, TruncatedAsciiNamesLine) {
  const auto dir = test::scratchDir("ply_trunc_ascii");
  test::writeAll(dir / "a.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n1 2 3\n4 5\n");
  std::string msg = errorOf([&] { readPly(dir / "a.ply"); });
  EXPECT_NE(msg.find("too few values"), std::string::npos) << msg;
  EXPECT_NE(msg.find("vertex 1, line 9"), std::string::npos) << msg;
  test::writeAll(dir / "b.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n1 2 3\n4 5 x6\n");
  msg = errorOf([&] { readPly(dir / "b.ply"); });
  EXPECT_NE(msg.find("'x6' is not a number"), std::string::npos) << msg;
  test::writeAll(dir / "c.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nend_header\n1 2 3\n");
  msg = errorOf([&] { readPly(dir / "c.ply"); });
  EXPECT_NE(msg.find("expected 3 vertices, file ends"), std::string::npos) << msg;
  EXPECT_NE(msg.find("in vertex 1"), std::string::npos) << msg;
}

TEST(Ply, HeaderErrorsNameTheLine) {
  const auto dir = test::scratchDir("ply_header");
  struct Case {
    std::string text, expect;
  } cases[] = {
      {"ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown PLY format (expected"},
      {"ply\nformat ascii 1.0\nelement vertex -3\nend_header\n", "element count is not"},
      {"ply\nformat ascii 1.0\nproperty float x\nend_header\n", "property line before any element"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float32x x\nend_header\n", "unknown property type"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n", "no x, y and z"},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no \"end_header\""},
      {"ply\nelement vertex 1\nend_header\n", "no \"format\" line"},
      {"plx\nformat ascii 1.0\n", "does not start with the line \"ply\""},
      {"", "file is empty"},
  };
  for (const auto& c : cases) {
    test::writeAll(dir / "h.ply", c.text);
    const std::string msg = errorOf([&] { readPly(dir / "h.ply"); });
    EXPECT_NE(msg.find(c.expect), std::string::npos) << msg;
    EXPECT_NE(msg.find("h.ply"), std::string::npos) << msg;
  }
  test::writeAll(dir / "l.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty flot y\nend_header\n");
  EXPECT_NE(errorOf([&] { readPly(dir / "l.ply"); }).find("line 5"), std::string::npos);
}

TEST(Ply, FaceIndexOutOfRange) {
  const auto dir = test::scratchDir("ply_badface");
  test::writeAll(dir / "f.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  const std::string msg = errorOf([&] { readPly(dir / "f.ply"); });
  EXPECT_NE(msg.find("refers to vertex 7 but there are only 3"), std::string::npos) << msg;
}

TEST(Ply, LargeBinaryUsesSeveralWindows) {
  // > 8 MiB of records so the parallel windowed path runs with several windows.
  const auto dir = test::scratchDir("ply_large");
  PointCloud c;
  const std::size_t n = 700000;
  c.positions.resize(n);
  c.colors.resize(n);
  c.intensity.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.positions[i] = {float(i % 1000), float(i / 1000), float(i % 13)};
    c.colors[i] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), static_cast<std::uint8_t>(i >> 16)};
    c.intensity[i] = float(i);
  }
  writePly(dir / "big.ply", c);
  const PlyData d = readPly(dir / "big.ply");
  ASSERT_EQ(d.vertices.size(), n);
  EXPECT_EQ(d.vertices.positions, c.positions);
  EXPECT_EQ(d.vertices.colors, c.colors);
  EXPECT_EQ(d.vertices.intensity, c.intensity);
}

TEST(Ply, WriteIsAtomicOnFailure) {
  const auto dir = test::scratchDir("ply_atomic");
  test::writeAll(dir / "keep.ply", "old content");
  PointCloud bad;
  bad.positions.resize(3);
  bad.intensity.resize(2);  // inconsistent: writer refuses
  EXPECT_THROW(writePly(dir / "keep.ply", bad), InputError);
  EXPECT_EQ(test::readAll(dir / "keep.ply"), "old content");
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // no temporary left behind
}
