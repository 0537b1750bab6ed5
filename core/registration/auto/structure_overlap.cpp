#include "registration/auto/structure_overlap.hpp"

namespace plumb {

PointCloud structurePoints(const PointCloud& source, const std::vector<PlanarPolygon>& planes,
                           double min_area, std::size_t min_points) {
  std::vector<std::size_t> indices;
  for (const PlanarPolygon& plane : planes) {
    if (plane.area < min_area) continue;
    for (const auto i : plane.inliers)
      if (i < source.size()) indices.push_back(i);
  }
  if (indices.size() < min_points) return {};
  return source.subset(indices);
}

void measureStructureOverlap(const PointCloud& structure, const std::optional<Eigen::Vector3d>& viewpoint,
                             const RefineTarget& target,
                             const RefineParams& params, std::vector<RefinedHypothesis>& h, std::size_t first) {
  if (structure.empty()) return;
  RefineParams measure = params;
  measure.iterations = 0;  // the fit where the refinement left it
  measure.slide_test = false;
  for (std::size_t i = first; i < h.size(); ++i)
    h[i].refined.structure_overlap =
        refineRegistration(structure, target, h[i].refined.transform, measure, nullptr, viewpoint).overlap;
}

}  // namespace plumb
