#include "simulation/station_order.hpp"

#include <limits>

namespace plumb {

std::vector<Eigen::Vector3d> walkOrder(const std::vector<Eigen::Vector3d>& stations) {
  std::vector<Eigen::Vector3d> out;
  if (stations.empty()) return out;
  std::vector<bool> done(stations.size(), false);
  std::size_t at = 0;
  for (std::size_t k = 0; k < stations.size(); ++k) {
    out.push_back(stations[at]);
    done[at] = true;
    std::size_t next = at;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < stations.size(); ++j)
      if (!done[j] && (stations[j] - stations[at]).norm() < best) best = (stations[j] - stations[at]).norm(), next = j;
    at = next;
  }
  return out;
}

}  // namespace plumb
