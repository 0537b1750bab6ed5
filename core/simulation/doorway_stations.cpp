#include "simulation/doorway_stations.hpp"

#include <map>
#include <set>

namespace plumb {

std::vector<Eigen::Vector3d> doorwayStations(const GeneratedBuilding& building, int storey, double height) {
  std::set<std::uint32_t> exterior;
  for (const auto& o : building.truth.openings)
    if (o.element_type == "IfcDoor" && o.face == "exterior") exterior.insert(o.element);
  std::map<std::uint32_t, Eigen::Vector3d> centre;
  const double z = storey * building.spec.storey_height + building.spec.slab_thickness + height;
  for (const auto& o : building.truth.openings) {
    if (o.element_type != "IfcDoor" || o.storey != storey || exterior.count(o.element) || centre.count(o.element))
      continue;
    Eigen::Vector3d c = 0.25 * (o.corners[0] + o.corners[1] + o.corners[2] + o.corners[3]);
    c -= 0.5 * building.truth.interior_wall_thickness * o.face_normal;  // into the wall's middle
    c.z() = z;
    centre[o.element] = c;
  }
  std::vector<Eigen::Vector3d> out;
  for (const auto& [element, c] : centre) out.push_back(c);
  return out;
}

}  // namespace plumb
