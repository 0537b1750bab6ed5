#include "io/mesh/model_stream.hpp"

#include <cstdint>
#include <stdexcept>

namespace plumb::model_stream {
namespace {

using helper_stream::Reader;
using helper_stream::Writer;

constexpr helper_stream::RecordType kType{"PLUMBMDL", 3};

void checkIndices(const BimModel& m) {
  for (const auto& t : m.mesh.triangles)
    for (auto v : t)
      if (v >= m.mesh.vertices.size()) throw std::runtime_error("a triangle names a missing vertex");
  if (m.triangle_element.size() != m.mesh.triangles.size())
    throw std::runtime_error("triangle elements do not match the triangles");
  for (auto e : m.triangle_element)
    if (e >= m.elements.size()) throw std::runtime_error("a triangle names a missing element");
  const auto n = m.mesh.vertices.size();
  if ((!m.mesh.vertex_normals.empty() && m.mesh.vertex_normals.size() != n) ||
      (!m.mesh.vertex_colors.empty() && m.mesh.vertex_colors.size() != n))
    throw std::runtime_error("normals or colours do not match the vertices");
}

BimModel readModel(Reader& r) {
  BimModel m;
  m.format = r.str();
  r.table(m.mesh.vertices);
  r.table(m.mesh.triangles);
  r.table(m.triangle_element);
  m.elements.resize(r.count(r.pod<std::uint64_t>(), 20));
  for (auto& e : m.elements) {
    e.type = r.str();
    e.name = r.str();
    e.guid = r.str();
    e.storey = r.str();
    e.storey_guid = r.str();
  }
  r.table(m.mesh.vertex_normals);
  r.table(m.mesh.vertex_colors);
  checkIndices(m);
  return m;
}

}  // namespace

static_assert(sizeof(Eigen::Vector3d) == 24 && sizeof(Eigen::Vector3f) == 12 && sizeof(Rgb8) == 3,
              "the stream copies these as packed arrays");

bool writeModel(int fd, const BimModel& model) {
  Writer w(fd);
  w.begin(kType, helper_stream::kResult);
  w.str(model.format);
  w.table(model.mesh.vertices);
  w.table(model.mesh.triangles);
  w.table(model.triangle_element);
  w.pod(static_cast<std::uint64_t>(model.elements.size()));
  for (const auto& e : model.elements) {
    w.str(e.type);
    w.str(e.name);
    w.str(e.guid);
    w.str(e.storey);
    w.str(e.storey_guid);
  }
  w.table(model.mesh.vertex_normals);
  w.table(model.mesh.vertex_colors);
  return w.finish();
}

bool writeFailure(int fd, const ImportFailure& failure) { return helper_stream::writeFailure(fd, kType, failure); }

std::variant<BimModel, ImportFailure> decode(std::string_view bytes) {
  return helper_stream::decode(bytes, kType, readModel);
}

}  // namespace plumb::model_stream
