#include "model/robust_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {

Bounds robustBounds(std::vector<Eigen::Vector3d> samples, double tail, double margin) {
  samples.erase(std::remove_if(samples.begin(), samples.end(), [](const Eigen::Vector3d& p) { return !p.allFinite(); }),
                samples.end());
  Bounds b;
  if (samples.empty()) return b;
  tail = std::clamp(tail, 0.0, 0.25);
  const std::size_t n = samples.size();
  const auto lo = static_cast<std::size_t>(std::floor(tail * double(n - 1)));
  const auto hi = n - 1 - lo;
  std::vector<double> axis(n);
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < n; ++i) axis[i] = samples[i][a];
    std::nth_element(axis.begin(), axis.begin() + long(lo), axis.end());
    b.min[a] = axis[lo];
    std::nth_element(axis.begin(), axis.begin() + long(hi), axis.end());
    b.max[a] = axis[hi];
  }
  const Eigen::Vector3d widen = (margin * b.size()).cwiseMax(0.01);
  b.min -= widen;
  b.max += widen;
  return b;
}

std::vector<Eigen::Vector3d> datasetSamples(const Dataset& data, std::size_t max_samples) {
  const std::size_t total = data.pointCount();
  const std::size_t stride = std::max<std::size_t>(1, total / std::max<std::size_t>(1, max_samples));
  std::vector<Eigen::Vector3d> out;
  out.reserve(total / stride + data.scans.size());
  for (const Scan& scan : data.scans)
    for (std::size_t i = 0; i < scan.cloud.size(); i += stride) out.push_back(scan.pose.apply(scan.cloud.world(i)));
  return out;
}

}  // namespace plumb
