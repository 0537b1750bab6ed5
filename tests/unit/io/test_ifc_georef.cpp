// Georeferenced IFC through single-precision assimp: the site / world-system translation is
// taken out before the import and added back in double, so national coordinates (here
// Lambert-93) keep the 0.1 mm the point clouds are held to.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/error.hpp"
#include "io/mesh/ifc_georef.hpp"
#include "io/mesh/ifc_map_conversion.hpp"
#include "io/mesh/mesh_io.hpp"
#include "io/mesh/step_entities.hpp"
#include "support/ifc_prepass_checks.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

/// `ifc` (shared data) with line `from` replaced by `to` plus the extra entity line `added`.
std::filesystem::path edited(const std::string& ifc, const std::string& from, const std::string& to,
                             const std::string& added, const std::string& name) {
  std::ifstream in(test::sharedData(ifc));
  std::ostringstream out;
  std::string line;
  bool found = false;
  while (std::getline(in, line)) {
    if (line == from) {
      out << to << '\n' << added << '\n';
      found = true;
    } else {
      out << line << '\n';
    }
  }
  EXPECT_TRUE(found) << from;
  // One folder per file: scratchDir empties it, and the tests run in parallel.
  const auto path = test::scratchDir("ifc_georef_" + std::filesystem::path(name).stem().string()) / name;
  test::writeAll(path, out.str());
  return path;
}

/// Largest distance between the vertices of `moved` and those of `original` + `shift`.
double largestDeviation(const BimModel& original, const BimModel& moved, const Eigen::Vector3d& shift) {
  EXPECT_EQ(moved.mesh.vertices.size(), original.mesh.vertices.size());
  EXPECT_EQ(moved.mesh.triangles, original.mesh.triangles);
  double worst = 0;
  for (std::size_t i = 0; i < std::min(moved.mesh.vertices.size(), original.mesh.vertices.size()); ++i)
    worst = std::max(worst, (moved.mesh.vertices[i] - (original.mesh.vertices[i] + shift)).norm());
  return worst;
}

}  // namespace

/// Imports `ifc` and its edited copy; returns the largest deviation from original + shift.
double importedDeviation(const std::string& ifc, const std::filesystem::path& moved_path,
                         const Eigen::Vector3d& shift) {
  const BimModel original = readMesh(test::sharedData(ifc));
  const BimModel moved = readMesh(moved_path);
  EXPECT_EQ(moved.elements.size(), original.elements.size());
  return largestDeviation(original, moved, shift);
}

TEST(IfcGeoref, DuplexSiteInLambert93KeepsTenthOfAMillimetre) {
  // The duplex's IfcSite placement #38273 -> #38272 uses the shared origin #3: give it its own
  // point in Lambert-93.
  const auto path = edited("ifc/duplex.ifc", "#38272=IFCAXIS2PLACEMENT3D(#3,$,$);",
                           "#38272=IFCAXIS2PLACEMENT3D(#900001,$,$);",
                           "#900001=IFCCARTESIANPOINT((651000.123,6860000.456,40.));", "duplex_l93.ifc");
  const double worst = importedDeviation("ifc/duplex.ifc", path, {651000.123, 6860000.456, 40.0});
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", worst);
  RecordProperty("max_deviation_m", text);
  EXPECT_LE(worst, 1e-4);
}

TEST(IfcGeoref, MillimetreWorldSystemOffsetIsScaled) {
  // IfcOpenHouse is in millimetres; its world coordinate system #10 moves to Lambert-93 (mm).
  const auto path = edited("ifc/IfcOpenHouse_IFC4.ifc", "#10=IFCAXIS2PLACEMENT3D(#9,#8,#7);",
                           "#10=IFCAXIS2PLACEMENT3D(#900001,#8,#7);",
                           "#900001=IFCCARTESIANPOINT((651000123.,6860000456.,40000.));", "openhouse_l93.ifc");
  EXPECT_LE(importedDeviation("ifc/IfcOpenHouse_IFC4.ifc", path, {651000.123, 6860000.456, 40.0}), 1e-4);
}

namespace {
/// A site 500 km / 6000 km from the origin, its placement shared by a second top-level placement.
const std::string kSmallSite =
    "ISO-10303-21;\nHEADER;\nFILE_SCHEMA(('IFC2X3'));\nENDSEC;\nDATA;\n"
    "#1=IFCCARTESIANPOINT((500000.,6000000.,10.));\n"
    "#2=IFCAXIS2PLACEMENT3D(#1,$,$);\n"
    "#3=IFCLOCALPLACEMENT($,#2);\n"
    "#4=IFCSITE('g',$,$,$,$,#3,$,$,.ELEMENT.,$,$,$,$,$);\n"
    "#5=IFCLOCALPLACEMENT($,#2);\n"
    "#6=IFCSIUNIT(*,.LENGTHUNIT.,$,.METRE.);\n"
    "#7=IFCUNITASSIGNMENT((#6));\n"
    "#8=IFCCARTESIANPOINT((0.,0.,0.));\n"
    "#9=IFCAXIS2PLACEMENT3D(#8,$,$);\n"
    "#10=IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-5,#9,$);\n"
    "#11=IFCPROJECT('p',$,'x',$,$,$,$,(#10),#7);\n"
    "ENDSEC;\nEND-ISO-10303-21;\n";

/// kSmallSite with `extra` before its ENDSEC.
std::string smallSiteWith(const std::string& extra) {
  return std::string(kSmallSite).insert(kSmallSite.find("ENDSEC;\nEND-ISO"), extra);
}
}  // namespace

TEST(IfcGeoref, PlanLeavesSharedPointsAloneAndKeepsLines) {
  const std::string& text = kSmallSite;
  const auto shift = ifc_georef::plan(text);
  ASSERT_TRUE(shift);
  EXPECT_EQ(shift->metres, Eigen::Vector3d(500000.0, 6000000.0, 10.0));
  const std::string& out = shift->text;
  EXPECT_NE(out.find("#1=IFCCARTESIANPOINT((500000.,6000000.,10.));"), std::string::npos);  // untouched
  EXPECT_NE(out.find("#3=IFCLOCALPLACEMENT($,#13);\n#4="), std::string::npos) << out;  // same line
  EXPECT_NE(out.find("#5=IFCLOCALPLACEMENT($,#15);"), std::string::npos) << out;
  EXPECT_NE(out.find("#12=IFCCARTESIANPOINT((0.,0.,0.));\n#13=IFCAXIS2PLACEMENT3D(#12,$,$);"), std::string::npos) << out;
  // A model near the origin is left alone.
  EXPECT_FALSE(ifc_georef::plan(std::string(text).replace(text.find("500000.,6000000.,10."), 20, "5.,6.,1.")));
}

TEST(IfcGeoref, PlanLeavesADamagedTextAloneAndAppendsAfterTheLastEntity) {
  const auto ignore = [](const step::Entity&) {};
  EXPECT_TRUE(step::forEachEntity(kSmallSite, ignore));
  // A quote left open hides what follows from the scanner, and so do an open comment and an
  // instance the scanner cannot read: the rewrite could reuse hidden ids.
  for (const char* damage : {"#12=IFCWALL('w,$);\n", "/* note\n", "#12=;\n"}) {
    EXPECT_FALSE(step::forEachEntity(smallSiteWith(damage), ignore)) << damage;
    EXPECT_FALSE(ifc_georef::plan(smallSiteWith(damage))) << damage;
  }
  // An ENDSEC inside a comment after the last entity: the new entities go before the comment.
  const auto shift = ifc_georef::plan(smallSiteWith("/* ENDSEC; */\n"));
  ASSERT_TRUE(shift);
  EXPECT_NE(shift->text.find("(#10),#7);\n#12=IFCCARTESIANPOINT("), std::string::npos) << shift->text;
  EXPECT_EQ(test::planProblem(smallSiteWith("/* ENDSEC; */\n")), "");
}

namespace {
constexpr const char* kOpenHouseContext =
    "#11=IFCGEOMETRICREPRESENTATIONCONTEXT('Plan','Model',3,1.E-005,#10,#6);";

/// IfcOpenHouse (millimetres) with an IfcMapConversion of its model context #11 to Lambert-93.
std::filesystem::path withMapConversion(const std::string& conversion_args, const std::string& name) {
  return edited("ifc/IfcOpenHouse_IFC4.ifc", kOpenHouseContext, kOpenHouseContext,
                "#900001=IFCPROJECTEDCRS('EPSG:2154','RGF93 v1 / Lambert-93',$,$,$,$,$);\n"
                "#900002=IFCMAPCONVERSION(#11,#900001," + conversion_args + ");",
                name);
}
}  // namespace

TEST(IfcGeoref, MapConversionPlacesTheModelInTheGrid) {
  // Eastings/Northings/OrthogonalHeight in metres, x axis turned 30 degrees, Scale 0.001
  // (millimetre project units to metres: the imported model is already in metres, so the
  // horizontal factor is 1).
  const auto path =
      withMapConversion("651234.5678,6861234.4321,35.25,0.8660254037844387,0.5,0.001", "openhouse_map.ifc");
  const BimModel original = readMesh(test::sharedData("ifc/IfcOpenHouse_IFC4.ifc"));
  const BimModel mapped = readMesh(path);
  ASSERT_EQ(mapped.mesh.vertices.size(), original.mesh.vertices.size());
  const double a = std::atan2(0.5, 0.8660254037844387);
  double worst = 0;
  for (std::size_t i = 0; i < original.mesh.vertices.size(); ++i) {
    const Eigen::Vector3d& v = original.mesh.vertices[i];
    const Eigen::Vector3d want(651234.5678 + std::cos(a) * v.x() - std::sin(a) * v.y(),
                               6861234.4321 + std::sin(a) * v.x() + std::cos(a) * v.y(), 35.25 + v.z());
    worst = std::max(worst, (mapped.mesh.vertices[i] - want).norm());
  }
  EXPECT_LE(worst, 1e-6);  // double arithmetic on the same imported vertices
  EXPECT_GT(mapped.mesh.bounds().min.x(), 651000.0);
  EXPECT_GT(mapped.mesh.bounds().min.y(), 6861000.0);
}

TEST(IfcGeoref, MapConversionReadsDefaultsAndRefusesAZeroAxis) {
  const std::string head = "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n"
                           "#10=IFCGEOMETRICREPRESENTATIONCONTEXT($,'Model',3,1.E-5,$,$);\n"
                           "#20=IFCPROJECTEDCRS('EPSG:32631',$,$,$,$,$,$);\n";
  const auto m = ifc_georef::readMapConversion(head + "#30=IFCMAPCONVERSION(#10,#20,500000.,5000000.,12.,$,$,$);\nENDSEC;\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->origin, Eigen::Vector3d(500000.0, 5000000.0, 12.0));
  EXPECT_EQ(m->rotation_rad, 0.0);
  EXPECT_EQ(m->scale, 1.0);
  EXPECT_EQ(m->crs, "EPSG:32631");
  EXPECT_EQ(m->line, 7u);
  EXPECT_FALSE(ifc_georef::readMapConversion(head + "ENDSEC;\n"));
  try {
    ifc_georef::readMapConversion(head + "#30=IFCMAPCONVERSION(#10,#20,1.,2.,3.,0.,0.,1.);\nENDSEC;\n");
    FAIL() << "a zero x axis must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("#30 (line 7)"), std::string::npos) << e.what();
  }
  // Through readMesh the same fault names the file.
  const auto bad = withMapConversion("651234.5,6861234.4,35.,0.,0.,1.", "openhouse_bad_map.ifc");
  try {
    readMesh(bad);
    FAIL() << "a zero x axis must be refused";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("openhouse_bad_map.ifc"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("x axis"), std::string::npos) << e.what();
  }
}
