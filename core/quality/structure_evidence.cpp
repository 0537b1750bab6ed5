#include "quality/structure_evidence.hpp"

#include <algorithm>

namespace plumb {

namespace {

/// Sighted and unexplained tested points of one plane.
struct PlaneTally {
  std::size_t sighted = 0, unexplained = 0;
};

bool isUnexplained(Sighting s, bool occluded_unexplained) {
  return s == Sighting::Contradicting || (occluded_unexplained && s == Sighting::Occluded);
}

bool isSighted(Sighting s, bool occluded_unexplained) {
  return s == Sighting::Consistent || isUnexplained(s, occluded_unexplained);
}

/// Index of the large plane each cloud point lies on (-1: none); counts the large planes.
std::vector<int> largePlaneOfPoint(const std::vector<PlanarPolygon>& planes, std::size_t n,
                                   const VisibilityParams& p, std::size_t& large) {
  std::vector<int> of(n, -1);
  large = 0;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    if (planes[k].area < p.structure_min_area || planes[k].inliers.empty()) continue;
    ++large;
    for (auto i : planes[k].inliers)
      if (i < n) of[i] = static_cast<int>(k);
  }
  return of;
}

std::vector<PlaneTally> tallyPlanes(const std::vector<int>& plane_of, std::size_t planes,
                                    const TestedSightings& s) {
  std::vector<PlaneTally> t(planes);
  for (std::size_t k = 0; k < s.index.size(); ++k) {
    const int plane = s.index[k] < plane_of.size() ? plane_of[s.index[k]] : -1;
    if (plane < 0 || !isSighted(s.sighting[k], s.occluded_unexplained)) continue;
    ++t[plane].sighted;
    t[plane].unexplained += isUnexplained(s.sighting[k], s.occluded_unexplained);
  }
  return t;
}

void addPlane(const PlaneTally& t, double area, const VisibilityParams& p, StructureEvidence& e,
              std::size_t& sighted, std::size_t& unexplained) {
  if (t.sighted < static_cast<std::size_t>(p.structure_min_points)) return;
  ++e.judged_planes;
  e.judged_area += area;
  sighted += t.sighted;
  unexplained += t.unexplained;
  const double fraction = static_cast<double>(t.unexplained) / static_cast<double>(t.sighted);
  if (fraction > p.structure_plane_fraction) {
    ++e.unexplained_planes;
    e.unexplained_area += area;
  }
  if (fraction > e.worst_plane_fraction ||
      (fraction == e.worst_plane_fraction && area > e.worst_plane_area)) {
    e.worst_plane_fraction = fraction;
    e.worst_plane_area = area;
  }
}

}  // namespace

StructureEvidence structureEvidence(const std::vector<PlanarPolygon>& planes,
                                    std::size_t cloud_size, const TestedSightings& sightings,
                                    const VisibilityParams& p) {
  StructureEvidence e;
  const auto plane_of = largePlaneOfPoint(planes, cloud_size, p, e.large_planes);
  if (e.large_planes == 0) {
    e.missing_reason = "no planes of at least the minimum area with their points";
    return e;
  }
  e.available = true;
  const auto tally = tallyPlanes(plane_of, planes.size(), sightings);
  std::size_t sighted = 0, unexplained = 0;
  for (std::size_t k = 0; k < planes.size(); ++k)
    addPlane(tally[k], planes[k].area, p, e, sighted, unexplained);
  if (e.judged_area > 0) e.unexplained_area_ratio = e.unexplained_area / e.judged_area;
  if (sighted > 0) e.point_ratio = static_cast<double>(unexplained) / static_cast<double>(sighted);
  return e;
}

}  // namespace plumb
