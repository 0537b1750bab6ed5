#include "stair_zones.hpp"

#include <algorithm>
#include <map>

namespace plumb::bimst {

std::vector<Bounds> stairBounds(const BimModel& model) {
  std::map<std::uint32_t, Bounds> boxes;
  for (std::size_t t = 0; t < model.mesh.triangles.size() && t < model.triangle_element.size(); ++t) {
    const std::uint32_t e = model.triangle_element[t];
    if (e >= model.elements.size() || model.elements[e].type.rfind("IfcStair", 0) != 0) continue;
    for (std::uint32_t v : model.mesh.triangles[t]) boxes[e].extend(model.mesh.vertices[v]);
  }
  std::vector<Bounds> out;
  for (const auto& [e, b] : boxes) out.push_back(b);
  return out;
}

bool nearStair(const std::vector<Bounds>& stairs, const Eigen::Vector3d& station, double height,
               double reach, double margin) {
  const double floor = station.z() - height;
  return std::any_of(stairs.begin(), stairs.end(), [&](const Bounds& b) {
    if (floor < b.min.z() - margin || floor > b.max.z() + margin) return false;
    const double dx = std::max({b.min.x() - station.x(), 0.0, station.x() - b.max.x()});
    const double dy = std::max({b.min.y() - station.y(), 0.0, station.y() - b.max.y()});
    return dx * dx + dy * dy <= reach * reach;
  });
}

}  // namespace plumb::bimst
