// IFC -> BimModel through IFC++ (ifcpp_reader.hpp). Carve faces are planar polygons, possibly
// concave after the openings are cut: each is triangulated in its plane by Carve's ear clipper
// and every triangle is turned to face the way the polygon does.
#include "io/mesh/helper/ifcpp_reader.hpp"

#include <ifcpp/IFC4/include/IfcBuildingStorey.h>
#include <ifcpp/IFC4/include/IfcElement.h>
#include <ifcpp/IFC4/include/IfcGloballyUniqueId.h>
#include <ifcpp/IFC4/include/IfcLabel.h>
#include <ifcpp/IFC4/include/IfcProduct.h>
#include <ifcpp/IFC4/include/IfcRelAggregates.h>
#include <ifcpp/IFC4/include/IfcRelContainedInSpatialStructure.h>
#include <ifcpp/IFC4/include/IfcSpace.h>
#include <ifcpp/geometry/Carve/GeometryConverter.h>
#include <ifcpp/model/BuildingModel.h>
#include <ifcpp/reader/ReaderSTEP.h>

#include <carve/triangulator.hpp>

#include <cctype>
#include <fstream>
#include <iterator>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/error.hpp"
#include "common/utf8.hpp"
#include "io/mesh/mesh_io.hpp"

namespace plumb::import_helper {
namespace {

std::string utf8(const std::wstring& w) {
  std::string s;
  for (const wchar_t wc : w) appendUtf8(s, static_cast<std::uint32_t>(wc));
  return s;
}

/// The first error IFC++ reported (its reader and converter report through callbacks).
struct FirstError {
  std::string text;
  static void collect(void* self, shared_ptr<StatusCallback::Message> m) {
    auto* me = static_cast<FirstError*>(self);
    if (m && m->m_message_type == StatusCallback::MESSAGE_TYPE_ERROR && me->text.empty())
      me->text = utf8(m->m_message_text);
    while (!me->text.empty() && std::isspace(static_cast<unsigned char>(me->text.back()))) me->text.pop_back();
  }
  std::string suffix() const { return text.empty() ? "" : " (IFC++ said: " + text + ")"; }
};

/// Body geometry only: not the axis, footprint, bounding box or clearance representations.
bool isBody(const RepresentationData& rep) {
  const std::wstring& id = rep.m_representation_identifier;
  return id.empty() || id == L"Body" || id == L"Facetation" || id == L"Brep" || id == L"Mesh";
}

/// Appends the triangles of one product's meshes to the model, placed by `placement`.
class ProductMesher {
 public:
  ProductMesher(BimModel& model, std::uint32_t element, const carve::math::Matrix& placement)
      : model_(model), element_(element), placement_(placement) {}

  void addMeshSet(const carve::mesh::MeshSet<3>& meshset) {
    for (const carve::mesh::Mesh<3>* mesh : meshset.meshes)
      for (const carve::mesh::Face<3>* face : mesh->faces) addFace(*face);
  }
  std::size_t added() const { return added_; }

 private:
  std::uint32_t vertexIndex(const carve::mesh::Vertex<3>* v) {
    auto [it, fresh] = index_.try_emplace(v, static_cast<std::uint32_t>(model_.mesh.vertices.size()));
    if (fresh) {
      const carve::geom::vector<3> p = placement_ * v->v;
      model_.mesh.vertices.emplace_back(p.x, p.y, p.z);
    }
    return it->second;
  }

  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const carve::geom::vector<3>& normal) {
    const auto& vs = model_.mesh.vertices;
    const Eigen::Vector3d n(normal.x, normal.y, normal.z);
    if ((vs[b] - vs[a]).cross(vs[c] - vs[a]).dot(placement_normal_ * n) < 0) std::swap(b, c);
    model_.mesh.triangles.push_back({a, b, c});
    model_.triangle_element.push_back(element_);
    ++added_;
  }

  void addFace(const carve::mesh::Face<3>& face) {
    const std::size_t n = face.nVertices();
    if (n < 3) return;
    std::vector<std::uint32_t> corners;
    const carve::mesh::Edge<3>* e = face.edge;
    for (std::size_t i = 0; i < n; ++i, e = e->next) corners.push_back(vertexIndex(e->vert));
    if (n == 3) return addTriangle(corners[0], corners[1], corners[2], face.plane.N);
    std::vector<carve::geom::vector<2>> projected;
    face.getProjectedVertices(projected);
    std::vector<carve::triangulate::tri_idx> tris;
    carve::triangulate::triangulate(projected, tris);
    for (const auto& t : tris) addTriangle(corners[t.a], corners[t.b], corners[t.c], face.plane.N);
  }

  BimModel& model_;
  std::uint32_t element_;
  carve::math::Matrix placement_;
  Eigen::Matrix3d placement_normal_ = linearPart(placement_).inverse().transpose();
  std::unordered_map<const carve::mesh::Vertex<3>*, std::uint32_t> index_;
  std::size_t added_ = 0;

  static Eigen::Matrix3d linearPart(const carve::math::Matrix& m) {
    Eigen::Matrix3d l;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) l(r, c) = m.m[c][r];  // x' = _11 x + _21 y + _31 z + _41
    return l;
  }
};

/// The whole file. (IFC++'s own loadModelFromFile first switches the process to the locale
/// "en-US" or "en_US.UTF-8" and gives up when neither is installed, as on a stock Debian.)
std::string fileText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw FileError(path, "cannot read the file");
  return text;
}

/// What contains `object` one level up: the spatial element an element is contained in
/// (IfcRelContainedInSpatialStructure), else the whole it is part of (IfcRelAggregates: a space
/// in its storey, a stair flight in its stair).
shared_ptr<IfcObjectDefinition> containerOf(const IfcObjectDefinition& object) {
  if (const auto* element = dynamic_cast<const IfcElement*>(&object))
    for (const auto& weak : element->m_ContainedInStructure_inverse)
      if (const auto rel = weak.lock(); rel && rel->m_RelatingStructure) return rel->m_RelatingStructure;
  for (const auto& weak : object.m_Decomposes_inverse)
    if (const auto rel = weak.lock(); rel && rel->m_RelatingObject) return rel->m_RelatingObject;
  return nullptr;
}

/// The IfcBuildingStorey above `product`: its name (its GlobalId when unnamed) and GlobalId;
/// none within a few levels (a file's spatial tree is site / building / storey / space): "".
void setStoreyOf(const IfcProduct& product, BimElement& e) {
  const IfcObjectDefinition* at = &product;
  shared_ptr<IfcObjectDefinition> up;
  for (int depth = 0; depth < 8 && at; ++depth) {
    if (const auto* storey = dynamic_cast<const IfcBuildingStorey*>(at)) {
      if (storey->m_GlobalId) e.storey_guid = utf8(storey->m_GlobalId->m_value);
      e.storey = storey->m_Name && !storey->m_Name->m_value.empty() ? utf8(storey->m_Name->m_value) : e.storey_guid;
      return;
    }
    up = containerOf(*at);
    at = up.get();
  }
}

BimElement elementOf(const IfcProduct& product) {
  BimElement e;
  setStoreyOf(product, e);
  e.type = ifcBaseType(product.className());
  if (product.m_Name) e.name = utf8(product.m_Name->m_value);
  if (product.m_GlobalId) e.guid = utf8(product.m_GlobalId->m_value);
  return e;
}

/// Adds one product's body triangles as a new element; false (nothing added) when it has none.
bool addProduct(BimModel& model, ProductShapeData& shape) {
  const auto product = dynamic_pointer_cast<IfcProduct>(shape.m_ifc_object_definition.lock());
  if (!product || dynamic_pointer_cast<IfcSpace>(product)) return false;
  const auto element = static_cast<std::uint32_t>(model.elements.size());
  ProductMesher mesher(model, element, shape.getTransform());
  for (const auto& rep : shape.m_vec_representations) {
    if (!rep || !isBody(*rep)) continue;
    for (const auto& item : rep->m_vec_item_data) {
      if (!item) continue;
      for (const auto& ms : item->m_meshsets) if (ms) mesher.addMeshSet(*ms);
      for (const auto& ms : item->m_meshsets_open) if (ms) mesher.addMeshSet(*ms);
    }
  }
  if (mesher.added() == 0) return false;
  model.elements.push_back(elementOf(*product));
  return true;
}

/// importWithIfcpp without the translation of Carve's exceptions.
BimModel readWithIfcpp(const std::filesystem::path& path, IfcppCounts* counts) {
  FirstError first;
  auto ifc = std::make_shared<BuildingModel>();
  ReaderSTEP reader;
  reader.setMessageCallBack(&first, &FirstError::collect);
  std::string text = fileText(path);
  reader.loadModelFromString(text, ifc);
  const std::size_t entities = ifc->getMapIfcEntities().size();
  if (entities == 0) throw FileError(path, "IFC++ read no IFC entities from this file" + first.suffix());

  GeometryConverter converter(ifc);
  converter.setMessageCallBack(&first, &FirstError::collect);
  converter.convertGeometry();
  BimModel model;
  model.format = "ifc";
  std::size_t with_geometry = 0;
  for (auto& [id, shape] : converter.getShapeInputData())
    if (shape && addProduct(model, *shape)) ++with_geometry;
  if (counts) *counts = {entities, with_geometry};
  if (model.mesh.triangles.empty())
    throw FileError(path, "IFC++ read " + std::to_string(entities) +
                              " entities but found no surface geometry in them" + first.suffix());
  return model;
}

}  // namespace

BimModel importWithIfcpp(const std::filesystem::path& path, IfcppCounts* counts) {
  try {
    return readWithIfcpp(path, counts);
  } catch (const carve::exception& e) {  // not a std::exception
    throw FileError(path, "IFC++'s geometry kernel (Carve) failed: " + e.str());
  }
}

}  // namespace plumb::import_helper
