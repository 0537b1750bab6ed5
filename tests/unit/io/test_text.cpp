// Text point files: delimiters, header lines, PTS count lines, column guessing, errors, writing.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "io/text/text_io.hpp"
#include "io/text/text_layout.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {
PointCloud readCloud(const std::filesystem::path& p) {
  Dataset d = readText(p);
  EXPECT_EQ(d.scans.size(), 1u);
  return d.scans.at(0).cloud;
}
std::string errorOf(const std::filesystem::path& p) {
  try {
    readText(p);
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(Text, CsvHeaderNamesColumnsInAnyOrder) {
  const auto dir = test::scratchDir("text_csv");
  test::writeAll(dir / "a.csv", "intensity,X,Y,Z,red,green,blue,nx,ny,nz,temperature\n"
                                "5,1.5,2.5,3.5,255,128,0,0,0,1,21.5\n6,4,5,6,1,2,3,1,0,0,22\n");
  const PointCloud c = readCloud(dir / "a.csv");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.world(0), Eigen::Vector3d(1.5, 2.5, 3.5));
  EXPECT_EQ(c.colors[0], (Rgb8{255, 128, 0}));
  EXPECT_EQ(c.intensity, (Column<float>{5, 6}));
  EXPECT_EQ(c.normals[1], Eigen::Vector3f(1, 0, 0));
  ASSERT_NE(c.findScalarField("temperature"), nullptr);
  EXPECT_FLOAT_EQ(c.findScalarField("temperature")->values[0], 21.5f);
}

TEST(Text, PtsWithCountLinesAndGuessedColumns) {
  const auto dir = test::scratchDir("text_pts");
  // Leica PTS: count line, then x y z intensity r g b; a second block with its own count.
  test::writeAll(dir / "a.pts", "2\n1 2 3 -200 10 20 30\n4 5 6 150 40 50 60\n1\n7 8 9 0 70 80 90\n");
  const PointCloud c = readCloud(dir / "a.pts");
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c.intensity, (Column<float>{-200, 150, 0}));
  EXPECT_EQ(c.colors[2], (Rgb8{70, 80, 90}));
}

TEST(Text, SemicolonWithDecimalCommaAndTabs) {
  const auto dir = test::scratchDir("text_semicolon");
  test::writeAll(dir / "a.txt", "1,5;2,25;3\r\n4;5;6,75\r\n");
  PointCloud c = readCloud(dir / "a.txt");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.world(0), Eigen::Vector3d(1.5, 2.25, 3));
  EXPECT_EQ(c.world(1), Eigen::Vector3d(4, 5, 6.75));
  test::writeAll(dir / "b.xyz", "# scanner export\n1\t2\t3\t0.5\n\n4 \t5\t6\t0.25\n");
  c = readCloud(dir / "b.xyz");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.intensity, (Column<float>{0.5f, 0.25f}));
}

TEST(Text, SixColumnsAreColoursOrNormals) {
  const auto dir = test::scratchDir("text_six");
  test::writeAll(dir / "rgb.xyz", "0 0 0 255 0 12\n1 1 1 3 4 5\n");
  EXPECT_TRUE(readCloud(dir / "rgb.xyz").hasColors());
  test::writeAll(dir / "n.xyz", "0 0 0 0.6 0 0.8\n1 1 1 0 1 0\n");
  const PointCloud c = readCloud(dir / "n.xyz");
  EXPECT_FALSE(c.hasColors());
  ASSERT_TRUE(c.hasNormals());
  EXPECT_FLOAT_EQ(c.normals[0].z(), 0.8f);
}

TEST(Text, GeoreferencedCoordinatesGetAnOffset) {
  const auto dir = test::scratchDir("text_georef");
  test::writeAll(dir / "g.xyz", "652000.1234 6862000.5678 35.0001\n652001.0004 6862001.0008 36.0002\n");
  const PointCloud c = readCloud(dir / "g.xyz");
  EXPECT_EQ(c.offset, Eigen::Vector3d(652001, 6862001, 36));  // median of the sampled rows, 1 m
  EXPECT_NEAR(c.world(1).x(), 652001.0004, 1e-6);
  EXPECT_NEAR(c.world(0).y(), 6862000.5678, 1e-6);
}

TEST(Text, ErrorsNameFileAndLine) {
  const auto dir = test::scratchDir("text_errors");
  test::writeAll(dir / "a.xyz", "1 2 3\n4 5 6\n7 8\n");
  std::string m = errorOf(dir / "a.xyz");
  EXPECT_NE(m.find("a.xyz: expected 3 values, found 2 (at point 2, line 3)"), std::string::npos) << m;
  test::writeAll(dir / "b.csv", "x,y,z\n1,2,3\n1,2,zz\n");
  m = errorOf(dir / "b.csv");
  EXPECT_NE(m.find("'zz' is not a number (column 3)"), std::string::npos) << m;
  EXPECT_NE(m.find("line 3"), std::string::npos) << m;
  test::writeAll(dir / "c.xyz", "");
  EXPECT_NE(errorOf(dir / "c.xyz").find("file is empty"), std::string::npos);
  test::writeAll(dir / "d.xyz", std::string("ab\0cd", 5));
  EXPECT_NE(errorOf(dir / "d.xyz").find("binary content"), std::string::npos);
  test::writeAll(dir / "e.csv", "x,y,z\n");
  EXPECT_NE(errorOf(dir / "e.csv").find("no data lines"), std::string::npos);
  test::writeAll(dir / "f.csv", "a,b,c\n1,2,3\n");
  EXPECT_NE(errorOf(dir / "f.csv").find("exactly one x, one y and one z"), std::string::npos);
  test::writeAll(dir / "g.xyz", "1 2\n3 4\n");
  EXPECT_NE(errorOf(dir / "g.xyz").find("at least x y z"), std::string::npos);
}

TEST(Text, WriteThenReadBack) {
  const auto dir = test::scratchDir("text_write");
  PointCloud c;
  c.positions = {{0.1f, 0.2f, 0.3f}, {1e-3f, -5.5f, 7.25f}};
  c.colors = {{1, 2, 3}, {4, 5, 6}};
  c.intensity = {0.5f, 1.5f};
  c.scalar_fields.push_back({"deviation", {0.01f, -0.02f}});
  for (const char* name : {"w.csv", "w.xyz"}) {
    writeText(dir / name, c);
    const PointCloud r = readCloud(dir / name);
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r.positions, c.positions);  // shortest exact float text
    EXPECT_EQ(r.colors, c.colors);
    EXPECT_EQ(r.intensity, c.intensity);
    ASSERT_NE(r.findScalarField("deviation"), nullptr);
    EXPECT_EQ(r.findScalarField("deviation")->values, c.scalar_fields[0].values);
  }
  EXPECT_EQ(test::readAll(dir / "w.csv").substr(0, 32), "x,y,z,red,green,blue,intensity,d");
}

// The layout steps of readText alone.
namespace {
/// The FileError of f, or "no error".
template <class F>
FileError errorFrom(F&& f) {
  try {
    f();
  } catch (const FileError& e) {
    return e;
  }
  return FileError("none", "no error");
}
}  // namespace

TEST(TextLayout, ACommentIsAHeaderOnlyWhenItNamesThreeCoordinates) {
  using text::commentHeaderNames;
  EXPECT_EQ(commentHeaderNames("# X Y Z intensity"), (std::vector<std::string>{"X", "Y", "Z", "intensity"}));
  EXPECT_EQ(commentHeaderNames("//x,y,z,red"), (std::vector<std::string>{"x", "y", "z", "red"}));
  EXPECT_EQ(commentHeaderNames("# scanner export"), std::nullopt);
  EXPECT_EQ(commentHeaderNames("# x y time"), std::nullopt);
  std::string wide = "# x y z";
  for (int k = 0; k < 254; ++k) wide += " s";  // 257 names: more than the columns accepted
  EXPECT_EQ(commentHeaderNames(wide), std::nullopt);
}

TEST(TextLayout, DelimiterAndColumnNames) {
  EXPECT_EQ(text::detectDelimiter("1,5;2,5;3"), ';');  // then a comma is a decimal comma
  EXPECT_EQ(text::detectDelimiter("1,2,3"), ',');
  EXPECT_EQ(text::detectDelimiter("1\t2 3"), ' ');
  EXPECT_EQ(text::columnFromName("\"Normal_X\""), text::Col::NX);
  EXPECT_EQ(text::columnFromName("//X"), text::Col::X);
  EXPECT_EQ(text::columnFromName("Reflectance"), text::Col::I);
  EXPECT_EQ(text::columnFromName("xyz"), text::Col::Scalar);
}

TEST(TextLayout, HeaderRolesKeepOnlyCompleteTriplesAndOneIntensity) {
  using text::Col;
  const std::vector<std::string> names{"x", "y", "z", "red", "green", "i", "intensity", "nx", "ny", "nz"};
  EXPECT_EQ(text::rolesFromHeader(names, 10, 2, "h.csv"),
            (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::Scalar, Col::Scalar, Col::I, Col::Scalar, Col::NX,
                              Col::NY, Col::NZ}));
  FileError e = errorFrom([&] { text::rolesFromHeader(names, 9, 4, "h.csv"); });
  EXPECT_EQ(e.message(), "the header names 10 columns but data lines have 9 values");
  EXPECT_EQ(e.where().line, 4u);
  e = errorFrom([] { text::rolesFromHeader({"x", "y", "y"}, 3, 4, "h.csv"); });
  EXPECT_EQ(e.message(), "the header must name exactly one x, one y and one z column");
  EXPECT_EQ(e.where().line, 3u);  // the header line, before the first data line
}

TEST(TextLayout, GuessedRolesLookAtTheSampledValues) {
  using text::Col;
  EXPECT_EQ(text::guessColumns(6, {{0, 0, 0, 255, 3, 0}, {1, 1, 1, 7, 8, 9}}),
            (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::R, Col::G, Col::B}));
  EXPECT_EQ(text::guessColumns(6, {{0, 0, 0, 255, 3, 0}, {1, 1, 1, 7, 8, 256}}),
            (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::NX, Col::NY, Col::NZ}));
  EXPECT_EQ(text::guessColumns(7, {{0, 0, 0, -0.5, 1, 2, 3}}),  // PTS: x y z i r g b
            (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::I, Col::R, Col::G, Col::B}));
  EXPECT_EQ(text::guessColumns(7, {{0, 0, 0, 1, 2, 3, 0.5}}),
            (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::R, Col::G, Col::B, Col::I}));
  EXPECT_EQ(text::guessColumns(5, {}), (std::vector<Col>{Col::X, Col::Y, Col::Z, Col::Scalar, Col::Scalar}));
}

TEST(TextLayout, FirstPassFindsHeaderCountLineAndSample) {
  const std::string t = "// x y z i\n\n5\n1 2 3 4\n# note\n4 5 6 7\n8 9\n";
  const text::TextLayout l = text::scanLayout(t, "a.pts");
  EXPECT_EQ(l.names, (std::vector<std::string>{"x", "y", "z", "i"}));
  EXPECT_EQ(l.delim, ' ');
  EXPECT_EQ(l.ncols, 4u);
  EXPECT_EQ(l.data_pos, t.find("1 2 3 4"));
  EXPECT_EQ(l.data_line, 4u);
  EXPECT_EQ(l.sample, (std::vector<std::vector<double>>{{1, 2, 3, 4}, {4, 5, 6, 7}}));  // "8 9" is not sampled
  const text::TextLayout csv = text::scanLayout("x;y;z\n1,5;2;3\n", "b.csv");
  EXPECT_EQ(csv.delim, ';');
  EXPECT_EQ(csv.sample, (std::vector<std::vector<double>>{{1.5, 2, 3}}));
  FileError e = errorFrom([] { text::scanLayout("x,y,z\nu,v,w\n", "c.csv"); });
  EXPECT_EQ(e.message(), "'u,v,w' is neither a header nor numbers");
  EXPECT_EQ(e.where().line, 2u);
  e = errorFrom([] { text::scanLayout("# x y z\n1 2\n", "d.xyz"); });
  EXPECT_EQ(e.message(), "data lines have 2 value(s); at least x y z are needed");
}
