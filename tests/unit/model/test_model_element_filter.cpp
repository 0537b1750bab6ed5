// Registration on chosen elements (issue 14): the filter keeps exactly the triangles of the
// chosen IFC types or elements, counts what it kept per type, and refuses names the model lacks.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "model/model_element_filter.hpp"

using namespace plumb;

namespace {

/// A unit square (two triangles) at height z owned by a new element.
void addSquare(BimModel& m, const BimElement& e, double z) {
  const auto base = static_cast<std::uint32_t>(m.mesh.vertices.size());
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
    m.mesh.vertices.emplace_back(x, y, z);
  m.elements.push_back(e);
  const auto el = static_cast<std::uint32_t>(m.elements.size() - 1);
  m.mesh.triangles.push_back({base, base + 1, base + 2});
  m.mesh.triangles.push_back({base, base + 2, base + 3});
  m.triangle_element.insert(m.triangle_element.end(), 2, el);
}

/// Two walls, a slab and a column, each a square at its own height (the height names it).
BimModel typedModel() {
  BimModel m;
  m.source = "typed.ifc";
  addSquare(m, {"IfcWall", "W1", "0000000000000000000001"}, 1.0);
  addSquare(m, {"IfcWall", "W2", "0000000000000000000002"}, 2.0);
  addSquare(m, {"IfcSlab", "Floor", "0000000000000000000003"}, 3.0);
  addSquare(m, {"IfcColumn", "C1", "0000000000000000000004"}, 4.0);
  return m;
}

std::vector<double> heights(const BimModel& m) {
  std::vector<double> z;
  for (const auto& t : m.mesh.triangles) z.push_back(m.mesh.vertices[t[0]].z());
  return z;
}

}  // namespace

TEST(ModelElementFilter, KeepsTheChosenTypesAndCountsThem) {
  const FilteredModel f = filterModelElements(typedModel(), {{"ifcslab", "IfcColumn"}, {}});
  EXPECT_EQ(heights(f.model), (std::vector<double>{3, 3, 4, 4}));
  EXPECT_EQ(f.model.mesh.vertices.size(), 8u);  // unused vertices dropped
  ASSERT_EQ(f.model.triangle_element.size(), 4u);
  EXPECT_EQ(f.model.elements[f.model.triangle_element[0]].type, "IfcSlab");
  ASSERT_EQ(f.selection.used.size(), 2u);
  EXPECT_EQ(f.selection.used[0].type, "IfcColumn");
  EXPECT_EQ(f.selection.used[0].elements, 1u);
  EXPECT_EQ(f.selection.used[1].triangles, 2u);
  EXPECT_EQ(f.selection.elements_in_model, 4u);
  EXPECT_EQ(f.selection.triangles_in_model, 8u);
  EXPECT_EQ(selectionSummary(f.selection), "types ifcslab, IfcColumn: 2 of 4 elements, 4 of 8 triangles");
}

TEST(ModelElementFilter, KeepsElementsByGlobalIdOrName) {
  const FilteredModel f = filterModelElements(typedModel(), {{}, {"W2", "0000000000000000000004"}});
  EXPECT_EQ(heights(f.model), (std::vector<double>{2, 2, 4, 4}));
  // A type and an element together: either one keeps an element.
  const FilteredModel both = filterModelElements(typedModel(), {{"IfcSlab"}, {"W1"}});
  EXPECT_EQ(heights(both.model), (std::vector<double>{1, 1, 3, 3}));
}

TEST(ModelElementFilter, EmptyFilterKeepsTheWholeModel) {
  const FilteredModel f = filterModelElements(typedModel(), {});
  EXPECT_EQ(f.model.mesh.triangles.size(), 8u);
  EXPECT_EQ(f.selection.filter.describe(), "all elements");
  EXPECT_EQ(f.selection.used.size(), 3u);
}

TEST(ModelElementFilter, UnknownTypeNamesTheFileAndThePresentTypes) {
  try {
    filterModelElements(typedModel(), {{"IfcWall", "IfcBeam"}, {}});
    FAIL() << "no error for a type the model lacks";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "typed.ifc: no element of type 'IfcBeam' (the model has IfcColumn, IfcSlab, IfcWall)");
  }
  EXPECT_THROW(filterModelElements(typedModel(), {{}, {"nowhere"}}), InputError);
}

TEST(ModelElementFilter, NothingKeptOrUntypedModelIsAnError) {
  BimModel m = typedModel();
  m.elements.push_back({"IfcDoor", "D1", ""});  // an element without triangles
  try {
    filterModelElements(m, {{"IfcDoor"}, {}});
    FAIL() << "no error for a filter that keeps no triangle";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("typed.ifc: the element filter (types IfcDoor) keeps no triangle"),
              std::string::npos) << e.what();
  }
  BimModel untyped = typedModel();
  untyped.elements.clear();
  untyped.triangle_element.clear();
  EXPECT_THROW(filterModelElements(untyped, {{"IfcWall"}, {}}), InputError);
}

namespace {
/// typedModel with storeys: W1 and the slab on "Ground floor", W2 and the column on "Level 1".
BimModel storeyModel() {
  BimModel m = typedModel();
  const char* storeys[] = {"Ground floor", "Level 1", "Ground floor", "Level 1"};
  for (std::size_t i = 0; i < m.elements.size(); ++i) m.elements[i].storey = storeys[i];
  return m;
}
ModelElementFilter onStoreys(std::vector<std::string> storeys, std::vector<std::string> types = {}) {
  ModelElementFilter f;
  f.types = std::move(types);
  f.storeys = std::move(storeys);
  return f;
}
}  // namespace

TEST(ModelElementFilter, StoreysKeepTheirElementsAndNarrowTypes) {
  // A storey alone: every element on it (any case).
  EXPECT_EQ(heights(filterModelElements(storeyModel(), onStoreys({"level 1"})).model),
            (std::vector<double>{2, 2, 4, 4}));
  // With a type: only that type on that storey.
  const FilteredModel walls = filterModelElements(storeyModel(), onStoreys({"Level 1"}, {"IfcWall"}));
  EXPECT_EQ(heights(walls.model), (std::vector<double>{2, 2}));
  EXPECT_EQ(walls.selection.filter.describe(), "types IfcWall; storeys Level 1");
  // A storey by its GlobalId.
  BimModel with_ids = storeyModel();
  for (auto& e : with_ids.elements) e.storey_guid = e.storey == "Level 1" ? "2O2Fr$t4X7Zf8NOew3FLQQ" : "";
  EXPECT_EQ(heights(filterModelElements(with_ids, onStoreys({"2O2Fr$t4X7Zf8NOew3FLQQ"})).model),
            (std::vector<double>{2, 2, 4, 4}));
  // Two storeys: the union of both.
  EXPECT_EQ(filterModelElements(storeyModel(), onStoreys({"Level 1", "Ground floor"})).model.mesh.triangles.size(), 8u);
}

TEST(ModelElementFilter, UnknownStoreyNamesTheModelsStoreys) {
  try {
    filterModelElements(storeyModel(), onStoreys({"Roof"}));
    FAIL() << "no error for a storey the model lacks";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "typed.ifc: no element on a storey named 'Roof' (the model's storeys: Ground floor, Level 1)");
  }
  try {
    filterModelElements(typedModel(), onStoreys({"Level 1"}));
    FAIL() << "no error for a model without storeys";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the model names no storeys"), std::string::npos) << e.what();
  }
}

TEST(ModelElementFilter, SplitsCommaSeparatedNames) {
  EXPECT_EQ(splitNameList(" IfcWall, IfcSlab,,IfcColumn "),
            (std::vector<std::string>{"IfcWall", "IfcSlab", "IfcColumn"}));
  EXPECT_TRUE(splitNameList(" , ").empty());
}
