// The model stream between plumb-import and readMesh: a round trip keeps every field exactly,
// and a damaged stream (cut short, a count or an index out of range) is an error, never UB.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <tuple>

#include "io/mesh/model_stream.hpp"
#include "support/piped_bytes.hpp"

using namespace plumb;

namespace {

BimModel twoTriangles() {
  BimModel m;
  m.format = "ifc";
  m.mesh.vertices = {{651000.123456789, 6860000.456, 40.0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.mesh.vertex_normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 0}};
  m.triangle_element = {0, 1};
  m.elements = {{"IfcWall", "Basic Wall", "2O2Fr$t4X7Zf8NOew3FNtn"}, {"", "pole", ""}};
  return m;
}

}  // namespace

TEST(ModelStream, RoundTripKeepsEveryField) {
  const BimModel m = twoTriangles();
  const auto out = model_stream::decode(test::pipedBytes([&](int fd) { return model_stream::writeModel(fd, m); }));
  const BimModel& r = std::get<BimModel>(out);
  EXPECT_EQ(r.format, "ifc");
  EXPECT_EQ(r.mesh.vertices, m.mesh.vertices);  // doubles bit for bit
  EXPECT_EQ(r.mesh.vertex_normals, m.mesh.vertex_normals);
  EXPECT_TRUE(std::tie(r.mesh.triangles, r.triangle_element) == std::tie(m.mesh.triangles, m.triangle_element));
  ASSERT_EQ(r.elements.size(), m.elements.size());
  for (std::size_t i = 0; i < m.elements.size(); ++i) {
    const auto& [a, b] = std::tie(r.elements[i], m.elements[i]);
    EXPECT_TRUE(std::tie(a.type, a.name, a.guid) == std::tie(b.type, b.name, b.guid)) << i;
  }
}

TEST(ModelStream, FailureKeepsMessageAndLocation) {
  FileLocation where;
  where.line = 11879;
  where.element = "entity #20909 IfcSpace";
  const auto out = model_stream::decode(
      test::pipedBytes([&](int fd) { return model_stream::writeFailure(fd, {"assimp cannot read this IFC", where}); }));
  const auto& f = std::get<model_stream::ImportFailure>(out);
  EXPECT_EQ(f.message, "assimp cannot read this IFC");
  EXPECT_EQ(f.where.line.value_or(0), 11879u);
  EXPECT_EQ(f.where.element, "entity #20909 IfcSpace");
}

TEST(ModelStream, DamagedStreamsAreErrors) {
  BimModel m = twoTriangles();
  const std::string good = test::pipedBytes([&](int fd) { return model_stream::writeModel(fd, m); });
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, std::size_t{13}, good.size() / 2, good.size() - 1})
    EXPECT_THROW(model_stream::decode(good.substr(0, cut)), std::runtime_error) << cut;
  std::string huge_count = good;
  huge_count[8 + 4 + 1 + 4 + 3 + 7] = '\x7f';  // top byte of the vertex count (after magic, version, kind, "ifc")
  EXPECT_THROW(model_stream::decode(huge_count), std::runtime_error);
  m.mesh.triangles[1][2] = 4;  // no vertex 4
  EXPECT_THROW(model_stream::decode(test::pipedBytes([&](int fd) { return model_stream::writeModel(fd, m); })),
               std::runtime_error);
  m = twoTriangles();
  m.triangle_element[1] = 2;  // no element 2
  EXPECT_THROW(model_stream::decode(test::pipedBytes([&](int fd) { return model_stream::writeModel(fd, m); })),
               std::runtime_error);
}
