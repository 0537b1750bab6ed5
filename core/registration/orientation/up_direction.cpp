#include "registration/orientation/up_direction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plumb {

namespace {

double angleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(std::abs(a.dot(b)), 0.0, 1.0)) * 180.0 / M_PI;
}

/// The clusters carrying at least min_axis_share of the weight, heaviest first, each at least
/// min_axis_separation_deg from the ones kept before it, at most max_axes.
std::vector<UpCandidate> principalAxes(const DirectionClusteringResult& c,
                                       const OrientationParams& p) {
  double total = 0.0;
  for (const auto& k : c.clusters) total += k.weight;
  std::vector<UpCandidate> axes;
  for (const auto& k : c.clusters) {
    if (int(axes.size()) >= p.max_axes || total <= 0) break;
    if (k.weight < p.min_axis_share * total) continue;
    const bool close = std::any_of(axes.begin(), axes.end(), [&](const UpCandidate& a) {
      return angleDeg(a.up, k.direction) < p.min_axis_separation_deg;
    });
    if (close) continue;
    UpCandidate a;
    a.up = k.direction.normalized();
    if (a.up.z() < 0) a.up = -a.up;
    a.share = k.weight / total;
    a.tilt_deg = angleDeg(a.up, Eigen::Vector3d::UnitZ());
    axes.push_back(a);
  }
  return axes;
}

/// Two walls at right angles, seen without their floor as a principal direction (a room under a
/// pitched roof: the roof's normal, 45 degrees from Z, outweighs the floor): the direction
/// perpendicular to both is an up candidate too, added after the principal axes when no axis
/// lies within min_axis_separation_deg of it. Pairs within kPerpendicularDeg of a right angle.
void addPerpendicularOfWalls(std::vector<UpCandidate>& axes, const OrientationParams& p) {
  constexpr double kPerpendicularDeg = 5.0;
  const std::size_t n = axes.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (std::abs(90.0 - angleDeg(axes[i].up, axes[j].up)) > kPerpendicularDeg) continue;
      UpCandidate c;
      c.up = axes[i].up.cross(axes[j].up).normalized();
      if (c.up.z() < 0) c.up = -c.up;
      const bool close = std::any_of(axes.begin(), axes.end(), [&](const UpCandidate& a) {
        return angleDeg(a.up, c.up) < p.min_axis_separation_deg;
      });
      if (close) continue;
      c.tilt_deg = angleDeg(c.up, Eigen::Vector3d::UnitZ());
      axes.push_back(c);  // share 0: no normal lies on it
    }
}

std::string describe(const UpEstimate& e, const char* from) {
  std::ostringstream o;
  o.precision(3);
  o << "orientation: " << e.axes << " principal direction(s) of the " << from;
  for (std::size_t i = 0; i < e.candidates.size(); i += 2)
    o << (i ? ", " : ": ") << "(" << e.candidates[i].up.x() << ", " << e.candidates[i].up.y()
      << ", " << e.candidates[i].up.z() << ") " << e.candidates[i].tilt_deg << " deg from Z, "
      << 100.0 * e.candidates[i].share << "%" << (e.candidates[i].share > 0 ? "" : " (perpendicular to two walls)");
  o << (e.looks_levelled ? "; looks levelled" : "; not levelled");
  return o.str();
}

}  // namespace

UpEstimate estimateUpDirections(const std::vector<PlanarPolygon>& planes,
                                const std::vector<Segment3D>& segments,
                                const OrientationParams& p,
                                const DirectionClusteringParams& clustering) {
  UpEstimate e;
  auto clusters = clusterPlaneNormals(planes, clustering);
  const char* from = "plane normals";
  if (clusters.clusters.size() < 2 && !segments.empty()) {
    clusters = clusterSegmentDirections(segments, clustering);
    from = "segment directions";
  }
  std::vector<UpCandidate> axes = principalAxes(clusters, p);
  addPerpendicularOfWalls(axes, p);
  // Most plausible first: the axis nearest Z (a levelled dataset keeps its own up first).
  std::stable_sort(axes.begin(), axes.end(), [](const UpCandidate& a, const UpCandidate& b) {
    return a.tilt_deg < b.tilt_deg;
  });
  e.axes = axes.size();
  e.looks_levelled = !axes.empty() && axes.front().tilt_deg <= p.level_tolerance_deg;
  for (const auto& a : axes) {
    e.candidates.push_back(a);
    UpCandidate down = a;
    down.up = -a.up;
    down.tilt_deg = 180.0 - a.tilt_deg;
    e.candidates.push_back(down);
  }
  e.message = describe(e, from);
  return e;
}

}  // namespace plumb
