#include "ui/lod/detail_points.hpp"

#include <span>

#include "ui/layers/color_ramp.hpp"

namespace plumb::ui {

bool DetailColouring::operator==(const DetailColouring& o) const {
  const PointColoring &a = coloring, &b = o.coloring;
  return a.style.mode == b.style.mode && a.style.scalar_field == b.style.scalar_field &&
         a.scan_index == b.scan_index && a.dataset_index == b.dataset_index && a.elevation_row == b.elevation_row &&
         a.z_min == b.z_min && a.z_max == b.z_max && a.value_min == b.value_min && a.value_max == b.value_max &&
         station_colour == o.station_colour && distances == o.distances;
}

namespace {

Rgba opaque(const Rgb& c) { return {c[0], c[1], c[2], 255}; }

/// Colours of one node's points, appended to `out`.
void colourNode(const LodNodePoints& node, const DetailColouring& c, std::vector<Rgba>& out) {
  if (c.coloring.style.mode == PointColorMode::Scan) {
    for (const std::uint16_t s : node.station) {
      const std::size_t index = s < c.station_colour.size() ? c.station_colour[s] : c.coloring.scan_index + s;
      out.push_back(opaque(categoryColor(index)));
    }
    return;
  }
  PointColoring coloring = c.coloring;  // distances without a target: elevation here
  if (coloring.style.mode == PointColorMode::Distance) coloring.style.mode = PointColorMode::Elevation;
  const PointCloud cloud = node.toPointCloud();
  std::vector<Rgb> rgb(cloud.size());
  fillPointColors(cloud, coloring, rgb);
  for (const Rgb& x : rgb) out.push_back(opaque(x));
}

bool measuresDistances(const DetailColouring& c) {
  return c.coloring.style.mode == PointColorMode::Distance && c.distances && c.distances->target;
}

/// Distance colours of every point read (`points`, dataset frame) to the check's target.
void colourByDistance(const PointCloud& points, const DetailColouring& c, std::vector<Rgba>& out,
                      Progress* progress) {
  const DistanceTarget target = distanceTarget(*c.distances->target);
  const RigidTransform world;  // the target is in world already
  const DistanceResult r =
      target.cloud ? cloudToCloudDistances(points, c.to_world, *target.cloud, world, c.distances->params, progress)
                   : cloudToMeshDistances(points, c.to_world, *target.mesh, world, c.distances->params, progress);
  std::vector<Rgb> rgb(points.size());
  fillDistanceColors(r.distances, c.distances->scale, rgb);
  out.clear();
  for (const Rgb& x : rgb) out.push_back(opaque(x));
}

}  // namespace

DetailPoints loadDetailPoints(const LodCache& cache, const std::vector<std::uint32_t>& nodes,
                              const DetailColouring& colouring, Progress* progress) {
  DetailPoints out;
  out.nodes = nodes;
  out.colouring = colouring;
  const LodHierarchy& h = cache.hierarchy();
  if (!h.nodes.empty()) out.anchor = h.nodes.front().bounds.center();
  const bool distances = measuresDistances(colouring);
  PointCloud read;  // Distance mode: every point read, dataset frame
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    checkCanceled(progress);
    const LodNodePoints node = cache.readNode(nodes[k]);
    const Eigen::Vector3f shift = (node.origin - out.anchor).cast<float>();
    for (const Eigen::Vector3f& p : node.positions) out.positions.push_back(p + shift);
    if (distances) read.append(node.toPointCloud());
    else colourNode(node, colouring, out.colours);
    reportProgress(progress, double(k + 1) / double(nodes.size()), "detail");
  }
  if (distances) colourByDistance(read, colouring, out.colours, progress);
  return out;
}

}  // namespace plumb::ui
