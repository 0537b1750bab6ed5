// Storey names from the STEP text (io/mesh/ifc_storeys.hpp): STEP string escapes decoded, every
// IfcBuildingStorey found by its GlobalId, and elements renamed by their storey's GlobalId.
#include <gtest/gtest.h>

#include "io/mesh/ifc_storeys.hpp"

using namespace plumb;

TEST(IfcStoreys, StepStringsAreDecoded) {
  EXPECT_EQ(ifc_storeys::decodeString("'Level 1'"), "Level 1");
  EXPECT_EQ(ifc_storeys::decodeString("'Architect''s floor'"), "Architect's floor");
  EXPECT_EQ(ifc_storeys::decodeString("'Erdgescho\\X2\\00DF\\X0\\'"), "Erdgescho\xC3\x9F");  // U+00DF
  EXPECT_EQ(ifc_storeys::decodeString("'\\X\\C4tage'"), "\xC3\x84tage");                     // ISO 8859-1 C4
  EXPECT_EQ(ifc_storeys::decodeString("'Broken \\X2\\00D'"), "Broken \\X2\\00D");           // kept as written
}

TEST(IfcStoreys, NamesByGlobalIdAndElementsRenamed) {
  const std::string text =
      "ISO-10303-21;\nDATA;\n"
      "#39=IFCBUILDINGSTOREY('1xS3BCk291UvhgP2dvNMKI',#33,'Level 1',$,$,#38,$,$,.ELEMENT.,0.);\n"
      "#43=IFCBUILDINGSTOREY('1xS3BCk291UvhgP2dvNMQJ',#33,$,$,$,#42,$,$,.ELEMENT.,3.1);\n"
      "#44=IFCWALL('0000000000000000000001',#33,'W',$,$,$,$,$,$);\nENDSEC;\n";
  const auto names = ifc_storeys::storeyNames(text);
  ASSERT_EQ(names.size(), 2u);
  EXPECT_EQ(names.at("1xS3BCk291UvhgP2dvNMKI"), "Level 1");
  EXPECT_EQ(names.at("1xS3BCk291UvhgP2dvNMQJ"), "1xS3BCk291UvhgP2dvNMQJ");  // unnamed: its id
  BimModel m;
  BimElement a, b;
  a.storey = "Level1";  // as assimp's node name gives it
  a.storey_guid = "1xS3BCk291UvhgP2dvNMKI";
  b.storey = "kept";
  b.storey_guid = "not-in-the-file";
  m.elements = {a, b};
  ifc_storeys::nameStoreys(m, names);
  EXPECT_EQ(m.elements[0].storey, "Level 1");
  EXPECT_EQ(m.elements[1].storey, "kept");
}
