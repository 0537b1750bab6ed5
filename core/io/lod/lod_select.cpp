#include "io/lod/lod_select.hpp"

#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace plumb {
namespace {

struct Candidate {
  double priority;  ///< projected radius, pixels (infinite: the eye is inside the box)
  std::uint32_t id;
  bool operator<(const Candidate& o) const { return priority != o.priority ? priority < o.priority : id > o.id; }
};

/// Projected radius of the node's bounding sphere, pixels.
double priorityOf(const LodView& view, const LodNode& node) {
  const double radius = node.bounds.diagonal() / 2;
  const double distance = (node.bounds.center() - view.eye).norm();
  if (view.metres_per_pixel <= 0 && distance <= radius) return std::numeric_limits<double>::infinity();
  return lodPixels(view, radius, distance);
}

}  // namespace

double lodPixels(const LodView& view, double size, double distance) {
  if (view.metres_per_pixel > 0) return size / view.metres_per_pixel;
  const double slope = std::tan(view.fov_y_rad / 2);
  return size / (std::max(distance, 1e-9) * slope) * (view.viewport_height_px / 2);
}

bool lodOutsideFrustum(const LodView& view, const Bounds& box) {
  const Eigen::Matrix4d& m = view.view_projection;
  for (int row = 0; row < 3; ++row) {
    for (const double sign : {1.0, -1.0}) {
      const Eigen::Vector4d plane = m.row(3).transpose() + sign * m.row(row).transpose();
      // The box corner farthest along the plane's normal: outside if even it is behind.
      Eigen::Vector3d corner;
      for (int a = 0; a < 3; ++a) corner[a] = plane[a] >= 0 ? box.max[a] : box.min[a];
      if (plane.head<3>().dot(corner) + plane[3] < 0) return true;
    }
  }
  return false;
}

LodSelection selectLodNodes(const LodHierarchy& h, const LodView& view, const LodSelectParams& params) {
  LodSelection out;
  if (h.nodes.empty()) return out;
  std::priority_queue<Candidate> queue;
  queue.push({priorityOf(view, h.nodes[0]), 0});
  while (!queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    const LodNode& node = h.nodes[c.id];
    if (lodOutsideFrustum(view, node.bounds)) {
      ++out.culled;
      continue;
    }
    if (out.points + node.point_count > params.point_budget) {
      out.budget_reached = true;
      break;
    }
    out.nodes.push_back(c.id);
    out.points += node.point_count;
    const double distance = (node.bounds.center() - view.eye).norm();
    const bool inside = c.priority == std::numeric_limits<double>::infinity();
    if (!inside && lodPixels(view, node.spacing, distance) <= params.min_spacing_px) continue;
    for (const std::uint32_t child : node.children)
      if (child != kNoLodNode) queue.push({priorityOf(view, h.nodes[child]), child});
  }
  return out;
}

}  // namespace plumb
