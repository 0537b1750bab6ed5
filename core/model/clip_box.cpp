#include "model/clip_box.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace plumb {

ClipBox slab(int axis, double at, double thickness) {
  if (axis < 0 || axis > 2) throw std::invalid_argument("slab: axis must be 0, 1 or 2");
  ClipBox box;
  box.min[axis] = at - thickness / 2;
  box.max[axis] = at + thickness / 2;
  return box;
}

namespace {
std::vector<bool> insideMask(const Scan& scan, const ClipBox& box, const RigidTransform& to_world) {
  const RigidTransform m = to_world * scan.pose;
  std::vector<bool> keep(scan.cloud.size());
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = box.contains(m.apply(scan.cloud.world(i)));
  return keep;
}
}  // namespace

std::size_t countInside(const Dataset& data, const ClipBox& box, const RigidTransform& to_world) {
  std::size_t n = 0;
  for (const Scan& scan : data.scans) {
    const std::vector<bool> inside = insideMask(scan, box, to_world);
    n += static_cast<std::size_t>(std::count(inside.begin(), inside.end(), true));
  }
  return n;
}

Dataset clipDataset(const Dataset& data, const ClipBox& box, const RigidTransform& to_world) {
  Dataset out = data;
  for (Scan& scan : out.scans) scan.cloud.filter(insideMask(scan, box, to_world));
  return out;
}

}  // namespace plumb
