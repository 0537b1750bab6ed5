#include "model/bim_model.hpp"

#include <map>

namespace plumb {

Bounds TriangleMesh::bounds() const {
  Bounds b;
  for (const auto& v : vertices) b.extend(v);
  return b;
}

Eigen::Vector3d TriangleMesh::triangleNormal(std::size_t i) const {
  const auto& t = triangles[i];
  const Eigen::Vector3d n =
      (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

double TriangleMesh::triangleArea(std::size_t i) const {
  const auto& t = triangles[i];
  return 0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
}

double TriangleMesh::area() const {
  double a = 0;
  for (std::size_t i = 0; i < triangles.size(); ++i) a += triangleArea(i);
  return a;
}

void TriangleMesh::transform(const RigidTransform& t) {
  for (auto& v : vertices) v = t.apply(v);
  const Eigen::Matrix3f r = t.rotation().cast<float>();
  for (auto& n : vertex_normals) n = r * n;
}

std::size_t BimModel::elementCountOfType(const std::string& type) const {
  std::size_t n = 0;
  for (const auto& e : elements) n += e.type == type;
  return n;
}

std::vector<std::pair<std::string, std::size_t>> BimModel::elementTypeCounts() const {
  std::map<std::string, std::size_t> counts;
  for (const auto& e : elements) ++counts[e.type];
  return {counts.begin(), counts.end()};
}

std::vector<std::uint32_t> BimModel::trianglesOfType(const std::string& type) const {
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < triangle_element.size(); ++i)
    if (triangle_element[i] < elements.size() && elements[triangle_element[i]].type == type)
      out.push_back(i);
  return out;
}

}  // namespace plumb
